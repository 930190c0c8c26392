#include "solver/network/frame/frame_margins.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include "solver/interval/rounding.h"
#include "solver/mission/frame_scale.h"
#include "solver/mission/meridian_convergence.h"
#include "solver/network/sensors/step_model.h"

namespace gesmi {

namespace {

// x > 0 rounded up to 11 significant bits, exactly (a carry out of the mantissa moves
// to the exponent); infinity, NaN and x <= 0 unchanged.
double rounded_up_to_11_bits(double x) {
  if (!(x > 0.0) || x == std::numeric_limits<double>::infinity()) return x;
  constexpr std::uint64_t low = (std::uint64_t{1} << (52 - 10)) - 1;  // the dropped bits
  std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
  if (bits & low) bits = (bits | low) + 1;
  return std::bit_cast<double>(bits);
}

}  // namespace

double frame_widening(double turn, double scale, double other, double own) {
  // All terms are non-negative, so the seven roundings to nearest are covered by a
  // relative 8 units in the last place, and underflow by the smallest normal number.
  constexpr double up = 1.0 + 8.0 * std::numeric_limits<double>::epsilon();
  const double widening = (turn * other + 0.5 * turn * turn * own + scale * (other + own)) * up;
  // (a zero margin times an infinite integral is NaN: the widening is then unbounded)
  return std::isnan(widening) ? std::numeric_limits<double>::infinity() : widening + std::numeric_limits<double>::min();
}

double speed_bound(const Mission& m) {
  // The DVL boxes of SensorBoxes::velocity(), in plain doubles: every term is
  // non-negative, so the roundings to nearest of the few operations per sample (15 at
  // most) are covered by a relative 16 units in the last place, taken at the end, and
  // underflow by the smallest normal number.
  const std::vector<double>* readings[3] = {&m.vx, &m.vy, &m.vz};
  const std::vector<double>* widths[3] = {&m.half_widths.vx, &m.half_widths.vy, &m.half_widths.vz};
  double largest = 0.0, longest = 0.0;
  for (std::size_t k = 0; k < m.size(); ++k) {
    double own[3], largest_l1 = 0.0;
    for (int i = 0; i < 3; ++i) {
      const double speed = std::fabs((*readings[i])[k]);
      own[i] = widths[i]->empty() ? m.model.dvl_relative * speed + m.model.dvl_absolute : (*widths[i])[k];
      largest_l1 += speed + own[i];
    }
    // (the plane's scale only shrinks: the depth's margin alone adds speed)
    const double frame = m.depth_scale_margin * largest_l1;
    double squared = 0.0;
    for (int i = 0; i < 3; ++i) {
      const double speed = std::fabs((*readings[i])[k]);
      const double bound = own[i] + frame;
      squared += (speed + bound) * (speed + bound);
    }
    largest = std::max(largest, squared);  // readings are finite (validate_mission)
    if (k + 1 < m.size()) longest = std::max(longest, sub_up(m.time[k + 1], m.time[k]));
  }
  largest = largest * (1.0 + 16.0 * std::numeric_limits<double>::epsilon()) + std::numeric_limits<double>::min();
  // Plus what the velocity may stray from its samples' boxes within the longest step, on
  // each axis (sqrt(3) < 1.7321): max_acceleration dt / 2 where the rates hold, and in the
  // surface regime, where only the jerk bounds it, J dt² / 8 from the interpolation
  // between the samples (step_regimes.h; a step that falls back takes its speed bound).
  const double rates = mul_up(m.model.max_acceleration, mul_up(0.5, longest));
  const double jerk = interpolation_error_peak(longest, m.model.surface_max_jerk);
  return add_up(sqrt_up(largest), mul_up(1.7321, add_up(rates, jerk)));
}

namespace {

// Plain doubles below: every term is non-negative, so the few roundings to nearest of
// each distance (at most 7) are covered by a relative 8 units in the last place, and
// squares that underflow by the smallest normal number under the root.
constexpr double kUp = 1.0 + 8.0 * std::numeric_limits<double>::epsilon();

// The larger of two distances, NaN when either is (std::max would drop a NaN).
double farther(double a, double b) {
  return std::isnan(a) || std::isnan(b) ? std::numeric_limits<double>::quiet_NaN() : std::max(a, b);
}

// The margins at the farthest distance from the origin a sample can take, capped at the
// zone's; where capped, the farthest such distance is kept in `beyond_zone`. Both
// margins grow with the distance, so the distance is first rounded up to 11 significant
// bits (at most 0.1 % farther): consecutive samples mostly share it, and the tangent in
// the heading's bound is taken once per change.
class MarginsAtDistance {
 public:
  explicit MarginsAtDistance(const Mission& mission)
      : convergence_(mission.origin.latitude),
        zone_heading_(mission.heading_frame_margin),
        zone_scale_(mission.frame_scale_margin) {}
  void take(double farthest, float& heading, float& scale, double& beyond_zone) {
    const double distance = rounded_up_to_11_bits(farthest);
    if (!(distance == last_)) {
      const double h = convergence_.within(distance);
      const double s = frame_scale_within(distance);
      // (capped also when unbounded there: inf, NaN)
      heading_ = float_up(h <= zone_heading_ ? h : zone_heading_);
      scale_ = float_up(s <= zone_scale_ ? s : zone_scale_);
      // (an unbounded box, inf or NaN, cannot show the robot stayed in the zone either)
      beyond_ = !(h <= zone_heading_) || !(s <= zone_scale_);
      last_ = distance;
    }
    heading = heading_;
    scale = scale_;
    if (beyond_) beyond_zone = std::isnan(distance) ? std::numeric_limits<double>::infinity() : std::max(beyond_zone, distance);
  }

 private:
  MeridianConvergence convergence_;
  double zone_heading_, zone_scale_;
  double last_ = std::numeric_limits<double>::quiet_NaN();
  float heading_ = 0.0f, scale_ = 0.0f;
  bool beyond_ = false;
};

// The farthest the robot can be from the origin during step k (from sample k to k + 1),
// from the farthest it can be at either end: within the farther of its ends plus half
// the step's travel (the robot is never farther than that from one of them).
double step_reach(const Mission& mission, double speed, std::size_t k, double here, double next) {
  const double half_travel = speed * (0.5 * (mission.time[k + 1] - mission.time[k]));
  return (farther(here, next) + half_travel) * kUp;
}

// The margins of the samples `wanted(k)` accepts, into v (one value per sample), from
// `reach` (the farthest the robot can be from the origin at each sample's time): each
// sample takes them once, at the farther of its two steps' reach (NaN, from an empty
// box, gives the zone's). `reach(k)` is called once per sample, in order.
template <class Reach, class Wanted>
void margins_within(const Mission& mission, std::size_t n, Reach reach, double speed, Wanted wanted,
                    FrameMarginValues& v) {
  MarginsAtDistance margins(mission);
  const auto take = [&](std::size_t k, double farthest) {
    if (wanted(k)) margins.take(farthest, v.heading[k], v.scale[k], v.beyond_zone);
  };
  if (n == 0) return;
  double here = reach(0);
  if (n == 1) take(0, here * kUp);
  double before = 0.0;  // the step ending at sample k
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const double next = reach(k + 1);
    const double after = step_reach(mission, speed, k, here, next);
    take(k, farther(before, after));
    before = after;
    here = next;
  }
  if (n > 1) take(n - 1, before);
}

// Every sample's margins.
template <class Reach>
FrameMarginValues margins_within(const Mission& mission, std::size_t n, Reach reach, double speed) {
  FrameMarginValues v;
  v.heading.assign(n, 0.0f);
  v.scale.assign(n, 0.0f);
  margins_within(mission, n, reach, speed, [](std::size_t) { return true; }, v);
  return v;
}

// The farthest distance from the origin the fixes allow at each sample, in sample
// order (infinite without fixes): min over fixes i of r_i + speed |t - t_i|, r_i the
// farthest point of fix i's box. The best fix before a time stays the best as time
// goes on (all grow at the same rate), and likewise after it, so the best fix on each
// side changes only at fix times: kept per fix, in time order (no array per sample).
class ReachFromFixes {
 public:
  ReachFromFixes(const Mission& m, double speed) : m_(m), speed_(speed), order_(m.gps_time.size()) {
    const std::size_t g = order_.size();
    for (std::size_t i = 0; i < g; ++i) order_[i] = i;
    std::sort(order_.begin(), order_.end(), [&](std::size_t a, std::size_t b) { return m.gps_time[a] < m.gps_time[b]; });
    fix_reach_.resize(g);
    for (std::size_t i = 0; i < g; ++i) {
      const double north = std::fabs(m.gps_north[i]) + m.gps_north_halfwidth[i];
      const double east = std::fabs(m.gps_east[i]) + m.gps_east_halfwidth[i];
      fix_reach_[i] = std::sqrt(north * north + east * east + std::numeric_limits<double>::min()) * kUp;
    }
    // best_before_[j]: the best of the first j + 1 fixes in time order; best_after_[j]:
    // the best of fixes j onwards (compared at the later, resp. earlier, fix time).
    best_before_.resize(g);
    best_after_.resize(g);
    for (std::size_t j = 0; j < g; ++j) {
      const std::size_t i = order_[j];
      best_before_[j] = j > 0 && !(from(i, m.gps_time[i]) < from(best_before_[j - 1], m.gps_time[i])) ? best_before_[j - 1] : i;
    }
    for (std::size_t j = g; j-- > 0;) {
      const std::size_t i = order_[j];
      best_after_[j] = j + 1 < g && !(from(i, m.gps_time[i]) < from(best_after_[j + 1], m.gps_time[i])) ? best_after_[j + 1] : i;
    }
  }
  /// The bound at sample k; k increases from call to call.
  double operator()(std::size_t k) {
    const double t = m_.time[k];
    const std::size_t g = order_.size();
    while (at_or_before_ < g && m_.gps_time[order_[at_or_before_]] <= t) ++at_or_before_;
    while (first_after_ < g && m_.gps_time[order_[first_after_]] < t) ++first_after_;
    double reach = std::numeric_limits<double>::infinity();
    if (at_or_before_ > 0) reach = from(best_before_[at_or_before_ - 1], t);
    if (first_after_ < g) reach = std::min(reach, from(best_after_[first_after_], t));
    return reach;
  }

 private:
  double from(std::size_t i, double t) const { return (fix_reach_[i] + speed_ * std::fabs(t - m_.gps_time[i])) * kUp; }

  const Mission& m_;
  double speed_;
  std::vector<std::size_t> order_, best_before_, best_after_;
  std::vector<double> fix_reach_;
  std::size_t at_or_before_ = 0;  // fixes (in time order) at or before the last sample's time
  std::size_t first_after_ = 0;   // the first fix at or after it
};

}  // namespace

FrameMarginValues frame_margins_over(const Mission& mission, const TubeDomains& tube) {
  if (!has_frame_margins(mission)) return {};
  return frame_margins_over(mission, tube, speed_bound(mission));
}

namespace {

// The farthest distance from the origin within sample k's box of the tube.
double tube_reach(const TubeDomains& tube, std::size_t k) {
  const double north = tube.px[k].mag(), east = tube.py[k].mag();
  return std::sqrt(north * north + east * east + std::numeric_limits<double>::min()) * kUp;
}

}  // namespace

FrameMarginValues frame_margins_over(const Mission& mission, const TubeDomains& tube, double speed) {
  if (!has_frame_margins(mission)) return {};
  return margins_within(mission, tube.size(), [&](std::size_t k) { return tube_reach(tube, k); }, speed);
}

FrameMarginValues zone_margin_values(const Mission& mission, std::size_t samples) {
  if (!has_frame_margins(mission)) return {};
  FrameMarginValues v;
  // What a sample capped at the zone takes (MarginsAtDistance): no sample takes more.
  v.heading.assign(samples, float_up(mission.heading_frame_margin));
  v.scale.assign(samples, float_up(mission.frame_scale_margin));
  return v;
}

void narrow_margins_over(FrameMarginValues& margins, const Mission& mission, const TubeDomains& tube, double speed,
                         std::span<const unsigned char> wanted) {
  const std::size_t n = tube.size();
  if (!has_frame_margins(mission) || n == 0) return;
  if (margins.heading.size() != n || margins.scale.size() != n || wanted.size() != n)
    throw std::invalid_argument("narrow_margins_over: one margin and one flag per sample of the tube");
  margins_within(mission, n, [&](std::size_t k) { return tube_reach(tube, k); }, speed,
                 [&](std::size_t k) { return wanted[k] != 0; }, margins);
}

FrameMarginValues frame_margins_from_fixes(const Mission& mission, double speed) {
  if (!has_frame_margins(mission)) return {};
  return margins_within(mission, mission.size(), ReachFromFixes(mission, speed), speed);
}

}  // namespace gesmi
