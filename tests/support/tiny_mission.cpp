#include "tests/support/tiny_mission.h"

#include <cmath>
#include <numbers>
#include <random>

#include "solver/model/euler.h"

namespace gesmi::test {
namespace {

constexpr double kDt = 0.1;
constexpr int kSamples = 3001;
constexpr double kSpeed = 1.5;
constexpr double kTurnStart = 100.0, kTurnEnd = 170.0;
constexpr double kDepth = 10.0, kFloor = 20.0;

double true_heading(double t) {
  if (t <= kTurnStart) return 0.0;
  if (t >= kTurnEnd) return std::numbers::pi;
  return std::numbers::pi * (t - kTurnStart) / (kTurnEnd - kTurnStart);  // 0.045 rad/s
}
double true_roll(double t) { return 0.01 * std::sin(0.02 * t); }
double true_pitch(double) { return 0.005; }

Vec3d true_body_velocity(double) { return Vec3d(kSpeed, 0.0, 0.0); }

Vec3d world_velocity(double t) {
  const Attitude<double> a = make_attitude(true_roll(t), true_pitch(t), true_heading(t));
  return body_to_world(a, true_body_velocity(t));
}

// An error strictly inside [-bound, bound].
struct ErrorSource {
  std::mt19937_64 rng;
  TinyErrors mode;
  double operator()(double bound, int sign = 1) {
    if (mode == TinyErrors::worst_case) return 0.999 * bound * sign;
    const double u = static_cast<double>(rng() >> 11) * 0x1p-53;  // [0, 1)
    return 0.999 * bound * (2.0 * u - 1.0);
  }
};

}  // namespace

TinyMission make_tiny_mission(std::uint64_t seed, TinyErrors errors) {
  TinyMission out;
  Mission& m = out.mission;
  const SensorModel model;
  m.model = model;
  ErrorSource error{std::mt19937_64(seed), errors};

  // Truth: integrate the world velocity with 20 midpoint sub-steps per sample.
  Vec3d p(0.0, 0.0, kDepth);
  for (int k = 0; k < kSamples; ++k) {
    const double t = k * kDt;
    m.time.push_back(t);
    m.truth_x.push_back(p[0]);
    m.truth_y.push_back(p[1]);
    m.truth_z.push_back(p[2]);
    for (int s = 0; s < 20; ++s) p += (kDt / 20.0) * world_velocity(t + (s + 0.5) * kDt / 20.0);
  }
  // Readings.
  for (int k = 0; k < kSamples; ++k) {
    const double t = m.time[static_cast<std::size_t>(k)];
    m.roll.push_back(true_roll(t) + error(model.roll));
    m.pitch.push_back(true_pitch(t) + error(model.pitch, -1));
    m.heading.push_back(true_heading(t) + error(model.heading));
    const Vec3d v = true_body_velocity(t);
    // Bound a|v~| + b around the reading: keep the error within a|v| + b - margin.
    m.vx.push_back(v[0] + error(model.dvl_relative * v[0] * 0.99 + model.dvl_absolute * 0.99));
    m.vy.push_back(v[1] + error(model.dvl_absolute * 0.99, -1));
    m.vz.push_back(v[2] + error(model.dvl_absolute * 0.99));
    const double z = m.truth_z[static_cast<std::size_t>(k)];
    m.depth.push_back(z + error(model.depth_absolute));
    m.altitude.push_back(kFloor - z + error(model.altitude));
  }
  // One mine between the legs, on the floor.
  const double east = kSpeed / (std::numbers::pi / (kTurnEnd - kTurnStart));  // turn radius
  const Vec3d mine(80.0, east, kFloor);
  m.mine_count = 1;
  m.truth_mines = {mine[0], mine[1], mine[2]};
  // Detections: the sample where the mine is closest to the sonar plane, per leg.
  const auto add_detection = [&](std::size_t k) {
    const double t = m.time[k];
    const Vec3d q(m.truth_x[k], m.truth_y[k], m.truth_z[k]);
    const double range = (q - mine).norm();
    m.mark_time.push_back(t);
    m.mark_mine.push_back(0);
    m.mark_range.push_back(range + error(model.mark_range));
    m.mark_side.push_back(1);
  };
  const auto along = [&](std::size_t k) {
    const double t = m.time[k];
    const Attitude<double> a = make_attitude(true_roll(t), true_pitch(t), true_heading(t));
    const Vec3d e(m.truth_x[k] - mine[0], m.truth_y[k] - mine[1], m.truth_z[k] - mine[2]);
    return world_to_body(a, e)[0];
  };
  const auto in_swath = [&](std::size_t k) {
    const Vec3d q(m.truth_x[k], m.truth_y[k], m.truth_z[k]);
    return (q - mine).norm() < model.sonar_max_range - 5.0;
  };
  for (std::size_t k = 0; k + 1 < m.time.size(); ++k)
    if ((along(k) <= 0.0) != (along(k + 1) <= 0.0) && in_swath(k))
      add_detection(std::fabs(along(k)) < std::fabs(along(k + 1)) ? k : k + 1);
  // GPS at both ends, boxes in the local frame.
  for (const std::size_t k : {std::size_t{0}, m.time.size() - 1}) {
    PositionFix fix;
    fix.time = m.time[k];
    fix.box[0] = Interval::around(m.truth_x[k] + error(model.gps_metres), model.gps_metres);
    fix.box[1] = Interval::around(m.truth_y[k] + error(model.gps_metres), model.gps_metres);
    fix.source_index = out.fixes.size();
    out.fixes.push_back(fix);
    // The same fix in the mission, in the local frame, as io/ would fill it.
    m.gps_time.push_back(fix.time);
    m.gps_north.push_back(fix.box[0].mid());
    m.gps_east.push_back(fix.box[1].mid());
    m.gps_north_halfwidth.push_back(fix.box[0].rad());
    m.gps_east_halfwidth.push_back(fix.box[1].rad());
  }
  return out;
}

}  // namespace gesmi::test
