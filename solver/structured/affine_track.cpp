#include "solver/structured/affine_track.h"

#include "solver/model/euler.h"
#include "solver/network/sensors/step_model.h"

namespace gesmi {
namespace {

using Pair = std::array<Interval, 2>;

Pair operator+(const Pair& a, const Pair& b) { return {a[0] + b[0], a[1] + b[1]}; }
Pair operator*(const Interval& x, const Pair& a) { return {x * a[0], x * a[1]}; }
Pair horizontal(const Vec3I& v) { return {v[0], v[1]}; }
Pair turned(const Pair& y) { return {y[1], -y[0]}; }  // J (n, e) = (e, -n)

// The world-frame images of a sample's body axes, Q e_a, under the noise's attitude box.
std::array<Pair, 3> body_axes(const SensorBoxes::SampleBoxes& s) {
  const Attitude<Interval> attitude = make_attitude(s.roll, s.pitch, s.heading);
  std::array<Pair, 3> axes;
  for (std::size_t a = 0; a < 3; ++a) {
    Vec3I unit(Interval(0.0), Interval(0.0), Interval(0.0));
    unit[static_cast<Eigen::Index>(a)] = Interval(1.0);
    axes[a] = horizontal(body_to_world(attitude, unit));
  }
  return axes;
}

}  // namespace

SmallAngleRests small_angle_rests(double bound) {
  const Interval b(0.0, bound);
  const Interval square = b * b, cube = square * b;
  return {Interval(-(square / Interval(2.0)).hi(), 0.0),
          Interval(-(cube / Interval(6.0)).hi(), (cube / Interval(6.0)).hi())};
}

void StepSums::clear() {
  c_ = outside_ = Pair{Interval(0.0), Interval(0.0)};
  k_.fill(c_);
  l_.fill(c_);
}

void StepSums::add_step(std::size_t k) {
  if (whole_.regimes().special(k)) {
    outside_ = outside_ + horizontal(whole_.step_increment(k));
    return;
  }
  const Interval dt = Interval(mission_.time[k + 1]) - Interval(mission_.time[k]);
  const Interval half = dt / Interval(2.0);
  const Interval rest = trapezoid_remainder(dt, whole_.regimes().jerk(whole_.model(), k));
  outside_ = outside_ + Pair{rest, rest};
  for (const std::size_t j : {k, k + 1}) {
    const SensorBoxes::SampleBoxes s = noise_.sample(j);
    c_ = c_ + half * horizontal(s.world_velocity);
    const std::array<Pair, 3> axes = body_axes(s);
    const std::array<const std::vector<double>*, 3> dvl = {&mission_.vx, &mission_.vy, &mission_.vz};
    for (std::size_t a = 0; a < 3; ++a) {
      k_[a] = k_[a] + (half * Interval((*dvl[a])[j])) * axes[a];
      l_[a] = l_[a] + half * axes[a];
    }
  }
}

AffineDisplacement StepSums::form(const std::array<double, kBiasTerms>& bias_bound) const {
  AffineDisplacement d;
  const Interval heading_bias(-bias_bound[kHeadingBias], bias_bound[kHeadingBias]);
  const SmallAngleRests rotation = small_angle_rests(bias_bound[kHeadingBias]);
  Pair unrotated = c_;  // Y over every bias within its bounds
  Pair rest = {c_[0] - Interval(c_[0].mid()), c_[1] - Interval(c_[1].mid())};
  for (std::size_t a = 0; a < 3; ++a) {
    const Interval scale(-bias_bound[kScaleBias + a], bias_bound[kScaleBias + a]);
    const Interval offset(-bias_bound[kOffsetBias + a], bias_bound[kOffsetBias + a]);
    for (std::size_t i = 0; i < 2; ++i) {
      unrotated[i] = unrotated[i] - k_[a][i] * scale - l_[a][i] * offset;
      d.coefficient[i][kScaleBias + a] = -k_[a][i].mid();
      d.coefficient[i][kOffsetBias + a] = -l_[a][i].mid();
      rest[i] =
          rest[i] - (k_[a][i] - Interval(k_[a][i].mid())) * scale - (l_[a][i] - Interval(l_[a][i].mid())) * offset;
    }
  }
  const Pair centre = {Interval(c_[0].mid()), Interval(c_[1].mid())};
  const Pair turned_rest = turned({unrotated[0] - centre[0], unrotated[1] - centre[1]});
  const Pair turned_whole = turned(unrotated);
  for (std::size_t i = 0; i < 2; ++i) {
    d.value[i] = c_[i].mid();
    d.coefficient[i][kHeadingBias] = turned(centre)[i].mid();  // beta J c: c_e north, -c_n east
    d.rest[i] = rest[i] + heading_bias * turned_rest[i] + rotation.cos_minus_one * unrotated[i] +
                rotation.sin_minus_angle * turned_whole[i] + outside_[i];
  }
  return d;
}

}  // namespace gesmi
