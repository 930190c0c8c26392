#pragma once
// A contractor for bearing data, kept valid when up to q of them are outliers. If
// bearing m is explained by landmark l, the sensor sees l in a direction
// phi = theta + zero + beta_m + [-delta, delta], so the sensor lies on the ray
// s = l - rho (cos phi, sin phi), rho >= 0. Forward-backward on that ray bounds the
// robot position for each landmark; the hull over the landmarks bounds it for the
// measurement, and x, y are narrowed to the q-relaxed intersection over the
// measurements. Visibility is ignored (a superset). Seed 003's test is unchanged;
// this only removes boxes before it runs.

#include <utility>
#include <vector>

#include "solver/interval/box.h"
#include "solver/setinv/localization/localization_map.h"

namespace gesmi {

class CtcBearingRelaxed {
 public:
  CtcBearingRelaxed(std::vector<LandmarkPoint> landmarks, std::vector<BearingSensor> sensors,
                    std::vector<BearingMeasurement> measurements, int outliers = 0);

  CtcBearingRelaxed with_outliers(int q) const;
  void contract(Box& box) const;

 private:
  std::vector<LandmarkPoint> landmarks_;
  std::vector<BearingSensor> sensors_;
  std::vector<BearingMeasurement> measurements_;
  int outliers_;
  mutable std::vector<Interval> x_, y_;  // scratch, sized once
  mutable std::vector<std::pair<double, int>> events_;
};

/// Applies two contractors in turn (stops when the box is empty).
template <class A, class B>
struct CtcPair {
  A first;
  B second;
  void contract(Box& box) const {
    first.contract(box);
    if (!is_empty(box)) second.contract(box);
  }
  CtcPair with_outliers(int q) const { return {first.with_outliers(q), second.with_outliers(q)}; }
};

}  // namespace gesmi
