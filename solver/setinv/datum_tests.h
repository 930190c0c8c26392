#pragma once
// Data as interval Booleans. A problem with n data points is seen, on a box P, as one
// interval Boolean per datum: "is datum i consistent with every / some / no p in P".
// For a model f(p) ∈ Y this is member(F_i(P), Y_i); the bearing model of seed 003
// gives "is measurement m explained by a visible landmark". The counts of certain
// yes and no give seed 004's inclusion and separation degrees (Proposition 1).
//
// An evaluator keeps any state per recursion depth it likes (children inherit from
// their father, depth 0 starts fresh) and may stop once more than `false_budget`
// data are certainly false, leaving the rest unknown: the box is then rejected
// whatever they are.

#include <concepts>
#include <cstddef>
#include <span>
#include <vector>

#include "solver/interval/box.h"
#include "solver/setinv/point_math.h"

namespace gesmi {

template <class D>
concept DatumTests = requires(D& d, const Box& box, int depth, std::span<IBool> out, int false_budget) {
  { d.datum_count() } -> std::convertible_to<std::size_t>;
  d.evaluate(box, depth, out, false_budget);
};

/// Certain yes (inclusion degree) and certain no (separation degree) of a result.
struct DatumCounts {
  int yes = 0;
  int no = 0;
};
inline DatumCounts count_data(std::span<const IBool> values) {
  DatumCounts c;
  for (IBool b : values) {
    c.yes += b.is_true();
    c.no += b.is_false() || b.is_empty();
  }
  return c;
}

/// A model templated on the number type: y = f(p), evaluated on points and boxes by
/// the same code (`template <class T> void operator()(std::span<const T>, std::span<T>) const`).
template <class M>
concept PointAndBoxModel = requires(const M& m, std::span<const double> p, std::span<double> y,
                                    std::span<const Interval> pb, std::span<Interval> yb) {
  { m.output_count() } -> std::convertible_to<std::size_t>;
  m(p, y);
  m(pb, yb);
};

/// The data tests of f(p) ∈ Y: datum i is member(F_i(P), Y_i).
template <PointAndBoxModel Model>
class ImageInBox {
 public:
  ImageInBox(Model model, Box image) : model_(std::move(model)), image_(std::move(image)), values_(image_.size()) {}

  std::size_t datum_count() const { return image_.size(); }
  void evaluate(const Box& box, int /*depth*/, std::span<IBool> out, int /*false_budget*/) {
    model_(std::span<const Interval>(box), std::span<Interval>(values_));
    for (std::size_t i = 0; i < values_.size(); ++i) out[i] = member(values_[i], image_[i]);
  }
  /// Point form: which outputs of f(p) fall inside Y.
  void evaluate_point(std::span<const double> p, std::span<bool> out) const {
    std::vector<double> y(image_.size());
    model_(p, std::span<double>(y));
    for (std::size_t i = 0; i < y.size(); ++i) out[i] = image_[i].contains(y[i]);
  }
  const Model& model() const { return model_; }
  const Box& image() const { return image_; }

 private:
  Model model_;
  Box image_;
  std::vector<Interval> values_;  // scratch, sized once
};

}  // namespace gesmi
