// The frame's margins applied after the build (frame_margins.h): the sensor domains
// of a frameless build, widened for a turn of at most m and a scale error of at most
// s, hold the exact displacement of a truth whose gyrocompass reads from a north
// turned by any angle within m and whose DVL reads speeds up to a factor 1 / (1 - s)
// of the frame's (or 1 - s: the depth's effect), for every step model. The oracle is
// the truth's closed-form integral in long double (tests/support/smooth_truth.h),
// independent of the rotations in solver/model.

#include <gtest/gtest.h>

#include <numbers>

#include "solver/mission/frame_scale.h"
#include "solver/mission/meridian_convergence.h"
#include "solver/network/frame/frame_margins.h"
#include "solver/network/sensors/sensor_priors.h"
#include "solver/network/sensors/sensor_boxes.h"
#include "tests/support/smooth_truth.h"
#include "tests/support/expect_interval.h"

namespace gesmi {
namespace {

using test::SmoothTruth;

using test::holds;

// A per-sample margin as the solver stores it: a float at or above the value.
float float_above(double x) { return std::nextafter(static_cast<float>(x), INFINITY); }

// How the DVL's horizontal world velocity differs from the frame's: u = A p, A a 2 × 2
// matrix on (north, east). The frame shrinks the radial part of a surface velocity by
// up to 1 - s (u = p + s / (1 - s) (p.r) r, r the radial direction); the depth slows
// the robot against its surface point (u = (1 - s) p).
struct Distortion {
  double nn = 1.0, ne = 0.0, en = 0.0, ee = 1.0;
  static Distortion uniform(double factor) { return {factor, 0.0, 0.0, factor}; }
  static Distortion radial(double scale, double azimuth) {
    const double k = scale / (1.0 - scale), rn = std::cos(azimuth), re = std::sin(azimuth);
    return {1.0 + k * rn * rn, k * rn * re, k * rn * re, 1.0 + k * re * re};
  }
};

// Steps whose increment misses the truth's displacement, when the readings come from
// a north turned by `turn` and the DVL's horizontal velocity is `distortion` of the
// frame's, and the domains are widened for `margins` (per sample).
int misses(const SmoothTruth& truth, const SensorModel& model, double turn, double heading_error,
           const FrameMargins& margins, std::size_t samples, std::uint64_t seed, Distortion distortion = {}) {
  // The gyrocompass reads psi_true = psi_local - turn, plus its error.
  Mission m = test::mission_of(truth, model, samples, seed, heading_error - turn);
  for (std::size_t k = 0; k < m.size(); ++k) {  // (roll and pitch are zero: vx, vy are horizontal)
    const double c = std::cos(m.heading[k]), s = std::sin(m.heading[k]);
    const double north = c * m.vx[k] - s * m.vy[k], east = s * m.vx[k] + c * m.vy[k];
    const double n = distortion.nn * north + distortion.ne * east, e = distortion.en * north + distortion.ee * east;
    m.vx[k] = c * n + s * e;
    m.vy[k] = -s * n + c * e;
  }
  const TubeDomains d = sensor_domains_in(frameless_sensor_priors(m, model, StepRegimes{}), margins);
  int outside = 0;
  for (std::size_t k = 0; k + 1 < m.size(); ++k) {
    const auto exact = truth.displacement(m.time[k], m.time[k + 1]);
    outside += !holds(d.dx[k], exact[0]) + !holds(d.dy[k], exact[1]) + !holds(d.dz[k], exact[2]);
  }
  return outside;
}

// Truths the model's step holds for: bounded jerk for the trapezoid and the rate hull,
// constant speeds for the paper's sample model (its boxes then hold over the step).
std::vector<SmoothTruth> truths_for(StepModel step) {
  std::vector<SmoothTruth> all = test::truths();
  if (step == StepModel::sample)
    for (SmoothTruth& t : all) t.vx.amplitude = t.vy.amplitude = t.vz.amplitude = 0.0L;
  // Near east, where a turn moves the north component by its second-order term.
  SmoothTruth east = all.front();
  east.heading = std::numbers::pi_v<long double> / 2 - 0.001L;
  all.push_back(east);
  return all;
}

TEST(HeadingFrame, TurnedIncrementsHoldTheDisplacementForEveryStepModel) {
  std::uint64_t seed = 31;
  for (const StepModel step : {StepModel::trapezoid, StepModel::rate_hull, StepModel::sample}) {
    const SensorModel model = test::model_with(step, 1.0);
    for (const SmoothTruth& truth : truths_for(step))
      for (const double margin : {1e-3, 0.02, 0.05})
        for (const double turn : {-margin, margin, 0.3 * margin})
          for (const double error : {-0.99 * model.heading, 0.99 * model.heading}) {
            std::vector<float> margins(300, float_above(margin));
            for (std::size_t k = 0; k < margins.size(); k += 7) margins[k] = float_above(1.5 * margin);  // per sample
            EXPECT_EQ(misses(truth, model, turn, error, FrameMargins{{0.0, margins}, {}}, margins.size(), seed++), 0)
                << static_cast<int>(step) << " heading " << static_cast<double>(truth.heading) << " margin " << margin
                << " turn " << turn << " error " << error;
          }
  }
}

TEST(HeadingFrame, TheTestCatchesAMarginSmallerThanTheTurn) {
  // Negative control: the same truths turned by the margin, the domains widened for
  // half of it (or not at all).
  const SensorModel model = test::model_with(StepModel::trapezoid, 1.0);
  for (const double part : {0.0, 0.5}) {
    int outside = 0;
    std::uint64_t seed = 41;
    for (const SmoothTruth& truth : truths_for(StepModel::trapezoid))
      for (const double turn : {-0.02, 0.02})
        outside += misses(truth, model, turn, std::copysign(0.99 * model.heading, -turn),
                          FrameMargins{{part * 0.02, {}}, {}}, 300, seed++);
    EXPECT_GT(outside, 100) << "margin at " << part << " of the turn";
  }
}

TEST(HeadingFrame, ScaledIncrementsHoldTheDisplacementForEveryStepModel) {
  std::uint64_t seed = 61;
  for (const StepModel step : {StepModel::trapezoid, StepModel::rate_hull, StepModel::sample}) {
    const SensorModel model = test::model_with(step, 1.0);
    for (const SmoothTruth& truth : truths_for(step))
      for (const double scale : {1e-4, 1e-3, 0.01}) {
        // Uniform (either way), and a radial shrink across the track: the frame's error
        // then falls on the other axis too.
        const double track = static_cast<double>(truth.heading);
        const Distortion distortions[] = {Distortion::uniform(1.0 / (1.0 - scale)), Distortion::uniform(1.0 - scale),
                                          Distortion::radial(scale, track + std::numbers::pi / 4),
                                          Distortion::radial(scale, track - std::numbers::pi / 4),
                                          Distortion::radial(scale, std::numbers::pi / 4)};
        for (const Distortion& distortion : distortions)
          for (const double turn : {0.0, 0.01}) {
            std::vector<float> margins(300, float_above(scale));
            for (std::size_t k = 0; k < margins.size(); k += 7) margins[k] = float_above(1.5 * scale);  // per sample
            const FrameMargins frame{{turn, {}}, {0.0, margins}};
            EXPECT_EQ(misses(truth, model, turn, 0.99 * model.heading, frame, margins.size(), seed++, distortion), 0)
                << static_cast<int>(step) << " heading " << track << " scale " << scale << " distortion " << distortion.nn
                << " " << distortion.ne << " turn " << turn;
          }
      }
  }
}

TEST(HeadingFrame, TheTestCatchesAScaleMarginSmallerThanTheScale) {
  // Negative control: speeds read 1 / (1 - s) too fast, the domains widened for half
  // of s (or not at all).
  const SensorModel model = test::model_with(StepModel::trapezoid, 1.0);
  for (const double part : {0.0, 0.5}) {
    int outside = 0;
    std::uint64_t seed = 71;
    for (const SmoothTruth& truth : truths_for(StepModel::trapezoid))
      outside += misses(truth, model, 0.0, 0.0, FrameMargins{{}, {part * 0.01, {}}}, 300, seed++,
                        Distortion::uniform(1.0 / (1.0 - 0.01)));
    EXPECT_GT(outside, 100) << "scale margin at " << part << " of the scale";
  }
}

TEST(HeadingFrame, WidensAboutAsMuchAsTurningTheHeadingBoxItself) {
  // Tightness: widening after the build costs little against building with the heading
  // box widened by the margin (the exact first-order effect): at most 2 % wider on
  // every step, for a margin of 20 % of the heading bound.
  const SensorModel model = test::model_with(StepModel::trapezoid, 1.0);
  for (const SmoothTruth& truth : test::truths()) {
    const Mission m = test::mission_of(truth, model, 200, 51);
    const double margin = 0.2 * model.heading;
    const TubeDomains after = sensor_domains_in(frameless_sensor_priors(m, model, StepRegimes{}), FrameMargins{{margin, {}}, {}});
    const SensorBoxes direct(m, model, FrameMargins{{margin, {}}, {}});
    for (std::size_t k = 0; k + 1 < m.size(); ++k) {
      const Vec3I d = direct.step_increment(k);
      EXPECT_LE(after.dx[k].width(), 1.02 * d[0].width() + 1e-12) << k;
      EXPECT_LE(after.dy[k].width(), 1.02 * d[1].width() + 1e-12) << k;
    }
  }
}

// speed_bound() against the farthest corner of every sample's DVL box (the model's bound
// with the depth's scale margin, or the per-sample half-widths), in long double, plus
// 1.7321 (max_acceleration dt / 2 + surface_max_jerk dt² / 8) for the longest step:
// never below, and within 1e-9.
long double farthest_speed(const Mission& m) {
  long double largest = 0.0L, longest = 0.0L;
  const std::vector<double>* readings[3] = {&m.vx, &m.vy, &m.vz};
  const std::vector<double>* widths[3] = {&m.half_widths.vx, &m.half_widths.vy, &m.half_widths.vz};
  for (std::size_t k = 0; k < m.size(); ++k) {
    long double squared = 0.0L;
    long double own[3], largest_l1 = 0.0L;
    for (int i = 0; i < 3; ++i) {
      const long double v = std::fabs(static_cast<long double>((*readings[i])[k]));
      own[i] = widths[i]->empty() ? static_cast<long double>(m.model.dvl_relative) * v + m.model.dvl_absolute : (*widths[i])[k];
      largest_l1 += v + own[i];
    }
    const long double frame = static_cast<long double>(m.depth_scale_margin) * largest_l1;
    for (int i = 0; i < 3; ++i) {
      const long double v = std::fabs(static_cast<long double>((*readings[i])[k]));
      const long double bound = own[i] + frame;
      squared += (v + bound) * (v + bound);
    }
    largest = std::max(largest, std::sqrt(squared));
    if (k + 1 < m.size()) longest = std::max(longest, static_cast<long double>(m.time[k + 1]) - m.time[k]);
  }
  const long double stray = m.model.max_acceleration * longest / 2.0L + m.model.surface_max_jerk * longest * longest / 8.0L;
  return largest + 1.7321L * stray;  // sqrt(3) rounded up, as documented
}

TEST(HeadingFrame, SpeedBoundHoldsTheFarthestCornerOfEveryDvlBox) {
  const SensorModel model = test::model_with(StepModel::trapezoid, 1.0);
  for (const SmoothTruth& truth : test::truths()) {
    Mission m = test::mission_of(truth, model, 400, 7, 0.0);
    m.depth_scale_margin = 3e-5;  // as io/ sets it for a floor 190 m deep
    for (const bool per_sample : {false, true}) {
      if (per_sample)
        for (auto* w : {&m.half_widths.vx, &m.half_widths.vy, &m.half_widths.vz}) w->assign(m.size(), 0.03);
      const long double exact = farthest_speed(m);
      const double bound = speed_bound(m);
      EXPECT_GE(bound, exact);
      EXPECT_LE(bound, exact * (1.0L + 1e-9L));
    }
  }
}

}  // namespace
}  // namespace gesmi

namespace gesmi {
namespace {

// frame_margins_from_fixes() against the farthest distance the fixes allow over each
// step, found exactly in long double: at time t the robot is within min over fixes i of
// (farthest point of fix i's box + speed |t - t_i|) of the origin.
TEST(FrameMarginsFromFixes, HoldTheFarthestPointTheFixesAllowOnEveryStep) {
  std::uint64_t state = 17;
  const auto unit = [&] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) / 9007199254740992.0;
  };
  const double speed = 2.7;
  for (int trial = 0; trial < 20; ++trial) {
    Mission m;
    m.origin = {trial % 2 ? 70.0 : 48.2, 0.0};
    m.heading_frame_margin = meridian_convergence_within(m.origin.latitude, 100000.0);
    m.frame_scale_margin = frame_scale_within(100000.0);
    double t = 0.0;
    for (int k = 0; k < 200; ++k) {
      m.time.push_back(t);
      t += trial == 3 ? 400.0 * unit() : 0.1 + 30.0 * unit();  // (one mission with long steps)
    }
    for (int i = 0; i < trial % 5; ++i) {  // 0 to 4 fixes, anywhere in time, some before or after
      m.gps_time.push_back(-100.0 + (t + 200.0) * unit());
      m.gps_north.push_back(-90000.0 + 180000.0 * unit());
      m.gps_east.push_back(-20000.0 + 40000.0 * unit());
      m.gps_north_halfwidth.push_back(3.0 * unit());
      m.gps_east_halfwidth.push_back(3.0 * unit());
    }
    const FrameMarginValues v = frame_margins_from_fixes(m, speed);
    ASSERT_EQ(v.heading.size(), m.size());
    std::vector<double> loosest(m.size(), 0.0);  // per sample: the bound a step's length farther out
    for (std::size_t k = 0; k + 1 < m.size(); ++k) {
      // f(t) = min over fixes of (r_i + speed |t - t_i|) is piecewise linear: its maximum
      // over the step is at an end or where a fix's rising side meets another's falling
      // side, t = (r_j - r_i + speed (t_i + t_j)) / (2 speed).
      const std::size_t g = m.gps_time.size();
      std::vector<long double> r(g);
      for (std::size_t i = 0; i < g; ++i) {
        const long double north = std::fabs(static_cast<long double>(m.gps_north[i])) + m.gps_north_halfwidth[i];
        const long double east = std::fabs(static_cast<long double>(m.gps_east[i])) + m.gps_east_halfwidth[i];
        r[i] = std::sqrt(north * north + east * east);
      }
      const auto nearest = [&](long double at) {
        long double best = INFINITY;
        for (std::size_t i = 0; i < g; ++i) best = std::min(best, r[i] + speed * std::fabs(at - m.gps_time[i]));
        return best;
      };
      const long double a = m.time[k], b = m.time[k + 1];
      long double farthest = std::max(nearest(a), nearest(b));
      for (std::size_t i = 0; i < g; ++i)
        for (std::size_t j = 0; j < g; ++j) {
          const long double at = (r[j] - r[i] + speed * (static_cast<long double>(m.gps_time[i]) + m.gps_time[j])) / (2 * speed);
          if (a < at && at < b) farthest = std::max(farthest, nearest(at));
        }
      const double d = static_cast<double>(farthest);
      const double heading = std::min(m.heading_frame_margin, meridian_convergence_within(m.origin.latitude, d));
      const double scale = std::min(m.frame_scale_margin, frame_scale_within(d));
      for (const std::size_t s : {k, k + 1}) {
        EXPECT_GE(v.heading[s], heading) << trial << " step " << k;
        EXPECT_GE(v.scale[s], scale) << trial << " step " << k;
      }
      const double looser = d + speed * (m.time[k + 1] - m.time[k]);
      for (const std::size_t s : {k, k + 1})
        loosest[s] = std::max(loosest[s], std::min(m.heading_frame_margin, meridian_convergence_within(m.origin.latitude, looser)));
    }
    // Tightness: no more than the bound a step's travel farther out.
    for (std::size_t k = 0; k < m.size(); ++k) EXPECT_LE(v.heading[k], loosest[k] * (1 + 2e-3)) << trial << " sample " << k;
  }
}

}  // namespace
}  // namespace gesmi
