#include "solver/setinv/paving.h"

namespace gesmi {

double box_volume(std::span<const Interval> box) {
  double v = 1.0;
  for (const Interval& x : box) {
    if (x.is_empty()) return 0.0;
    v *= x.hi() - x.lo();
  }
  return v;
}

double Paving::volume() const {
  double v = 0.0;
  for (std::size_t i = 0; i < size(); ++i) v += box_volume(box(i));
  return v;
}

Box Paving::hull() const {
  Box h(dim_, Interval::empty());
  for (std::size_t i = 0; i < size(); ++i) {
    const auto b = box(i);
    for (std::size_t k = 0; k < dim_; ++k) h[k] = gesmi::hull(h[k], b[k]);
  }
  return h;
}

}  // namespace gesmi
