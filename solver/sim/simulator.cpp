#include "solver/sim/simulator.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "solver/mission/between_readings.h"
#include "solver/model/euler.h"
#include "solver/sim/extra_motion.h"
#include "solver/sim/random_source.h"
#include "solver/sim/reading_errors.h"
#include "solver/sim/survey_plan.h"
#include "solver/model/angles.h"

namespace gesmi {
namespace {

constexpr double kMaxTurnRate = 0.045;   // rad/s: below the model's 0.05
constexpr double kMaxPitchRate = 0.004;  // rad/s
constexpr double kMaxSpeedRate = 0.1;    // m/s^2: below the model's 0.2
constexpr int kSubSteps = 2;             // midpoint rule per half step
constexpr double kSurfaceDepth = 0.3;    // m: the robot at the surface
constexpr double kClimbTime = 240.0;     // s before surfacing: time to climb from the survey depth
constexpr double kStopTime = 30.0;       // s before surfacing: time to slow down to a halt

double wrap(double angle) { return std::remainder(angle, kTwoPi); }

// Smooth components of the true motion that the guidance does not steer.
double true_roll(double t) { return 0.02 * std::sin(kTwoPi * t / 23.0); }
double true_sway(double t) { return 0.04 * std::sin(kTwoPi * t / 37.0); }
double true_heave(double t) { return 0.02 * std::sin(kTwoPi * t / 53.0); }

struct TruthState {
  Vec3d p{0.0, 0.0, 6.0};
  double heading = 0.0, pitch = 0.0, speed = 1.5;
};

// Survey waypoints, repeated back and forth until the path is long enough.
std::vector<Waypoint> plan_for(double duration, double& path_length) {
  const std::vector<Waypoint> pass = reference_survey();
  std::vector<Waypoint> plan;
  path_length = 0.0;
  Vec2d at(0.0, 0.0);
  bool forward = true;
  const double needed = duration * 1.45;
  do {
    std::vector<Waypoint> leg = pass;
    if (!forward) std::reverse(leg.begin(), leg.end());
    for (const Waypoint& w : leg) {
      path_length += std::hypot(w.north - at[0], w.east - at[1]);
      at = Vec2d(w.north, w.east);
      plan.push_back(w);
      if (path_length > needed && plan.size() > pass.size()) break;
    }
    forward = !forward;
  } while (path_length < needed * 0.8);
  return plan;
}

// Flies the plan: heading-rate- and acceleration-limited guidance, the rates held
// constant over each step (so the truth is piecewise linear within the bounds), and
// the displacement integrated with a midpoint rule on sub-steps.
class Pilot {
 public:
  Pilot(const std::vector<Waypoint>& plan, double mean_speed) : plan_(plan), mean_speed_(mean_speed) {}
  /// From pilot time `climb`, head for the surface; from `stop`, slow down to a halt.
  void surface_at_end(double climb, double stop) {
    climb_ = climb;
    stop_ = stop;
  }
  bool arrived() const { return target_ >= plan_.size(); }

  struct Rates {
    double turn = 0.0, pitch = 0.0, speed = 0.0;
  };
  Rates step(TruthState& s, double t, double dt) {
    // Next waypoint when close, or once past the line through it across the leg (a
    // waypoint inside the turning circle would otherwise be circled for ever).
    if (target_ < plan_.size()) {
      const Waypoint& w = plan_[target_];
      const Vec2d from = target_ > 0 ? Vec2d(plan_[target_ - 1].north, plan_[target_ - 1].east) : Vec2d(0.0, 0.0);
      const Vec2d to(w.north, w.east), here(s.p[0], s.p[1]);
      if ((to - here).norm() < 20.0 || (here - to).dot(to - from) > 0.0) ++target_;
    }
    const Waypoint& w = plan_[std::min(target_, plan_.size() - 1)];
    const double wanted = std::atan2(w.east - s.p[1], w.north - s.p[0]);
    const double turn = arrived() ? kMaxTurnRate : std::clamp(0.6 * wrap(wanted - s.heading), -kMaxTurnRate, kMaxTurnRate);
    const double depth_goal = t >= climb_ ? kSurfaceDepth : w.depth;
    const double pitch_goal = std::clamp(0.02 * (s.p[2] - depth_goal), -0.04, 0.04);
    const double pitch_rate = std::clamp((pitch_goal - s.pitch) / dt, -kMaxPitchRate, kMaxPitchRate);
    const double speed_goal = t >= stop_ ? 0.0 : mean_speed_ * (1.0 + 0.15 * std::sin(kTwoPi * (t + dt) / 900.0));
    const double speed_rate = std::clamp((speed_goal - s.speed) / dt, -kMaxSpeedRate, kMaxSpeedRate);
    for (int sub = 0; sub < kSubSteps; ++sub) {
      const double f = (sub + 0.5) / kSubSteps;  // midpoint of the sub-step
      const double tm = t + f * dt;
      const Attitude<double> a = make_attitude(true_roll(tm), s.pitch + pitch_rate * f * dt, s.heading + turn * f * dt);
      const Vec3d v(s.speed + speed_rate * f * dt, true_sway(tm), true_heave(tm));
      s.p += (dt / kSubSteps) * body_to_world(a, v);
    }
    s.heading += turn * dt;
    s.pitch += pitch_rate * dt;
    s.speed += speed_rate * dt;
    return {turn, pitch_rate, speed_rate};
  }

 private:
  const std::vector<Waypoint>& plan_;
  double mean_speed_;
  std::size_t target_ = 0;
  double climb_ = std::numeric_limits<double>::infinity(), stop_ = std::numeric_limits<double>::infinity();
};

TruthState start_state(const std::vector<Waypoint>& plan, double speed) {
  TruthState s;
  s.speed = speed;
  s.heading = std::atan2(plan[0].east, plan[0].north);
  return s;
}

// The mean speed that makes the robot reach the last waypoint just before the end:
// one trial flight, then scaled by the time it took.
double calibrated_speed(const std::vector<Waypoint>& plan, double path_length, double duration, double dt) {
  const double guess = std::clamp(path_length / duration, 1.2, 2.2);
  Pilot pilot(plan, guess);
  TruthState s = start_state(plan, guess);
  double t = 0.0;
  while (!pilot.arrived() && t < 3.0 * duration) {
    pilot.step(s, t, dt);
    t += dt;
  }
  return std::clamp(guess * t / std::max(duration - 60.0, 0.5 * duration), 1.2, 2.2);
}

}  // namespace

const char* simulated_errors_name(SimulatedErrors errors) {
  switch (errors) {
    case SimulatedErrors::uniform: return "uniform";
    case SimulatedErrors::worst_case: return "worst-case";
    case SimulatedErrors::at_samples: return "at-samples";
    case SimulatedErrors::drifting: return "drifting";
    case SimulatedErrors::corners: return "corners";
    case SimulatedErrors::bias_noise: return "bias-noise";
  }
  return "uniform";
}

std::string simulated_errors_names() {
  std::string names;
  for (const SimulatedErrors e : kAllSimulatedErrors) {
    names += names.empty() ? "" : e == kAllSimulatedErrors.back() ? " or " : ", ";
    names += simulated_errors_name(e);
  }
  return names;
}

bool parse_simulated_errors(std::string_view name, SimulatedErrors& errors) {
  for (const SimulatedErrors e : kAllSimulatedErrors)
    if (name == simulated_errors_name(e)) {
      errors = e;
      return true;
    }
  return false;
}

const char* bias_drift_name(BiasDrift drift) {
  switch (drift) {
    case BiasDrift::none: return "none";
    case BiasDrift::ramp: return "ramp";
    case BiasDrift::flip: return "flip";
  }
  return "none";
}

bool parse_bias_drift(std::string_view name, BiasDrift& drift) {
  for (const BiasDrift d : {BiasDrift::none, BiasDrift::ramp, BiasDrift::flip})
    if (name == bias_drift_name(d)) {
      drift = d;
      return true;
    }
  return false;
}

std::string SimulationOptions::validate() const {
  if (!(duration > 0.0) || !std::isfinite(duration)) return "duration must be a positive number of seconds";
  if (!(rate > 0.0) || !std::isfinite(rate) || rate > 1000.0) return "rate must be in (0, 1000] Hz";
  if (duration * rate > 2e8) return "duration x rate exceeds 2e8 samples";
  if (mines < 0 || mines > kMaxMines) return "mines must be between 0 and " + std::to_string(kMaxMines);
  if (!(missed >= 0.0 && missed <= 1.0)) return "missed must be a probability in [0, 1]";
  if (!(unassociated >= 0.0 && unassociated <= 1.0)) return "unassociated must be a probability in [0, 1]";
  if (outliers < 0) return "outliers must be >= 0";
  if (!(surface >= 0.0) || (surface > 0.0 && !(2.0 * surface < duration - 60.0)))
    return "surface must be >= 0 s and leave at least 60 s submerged between the two surface phases";
  if (!(wave_height >= 0.0 && wave_height <= 20.0)) return "wave-height must be in [0, 20] m";
  if (!(wave_period >= 0.2 && wave_period <= 60.0)) return "wave-period must be in [0.2, 60] s";
  if (bursts < 0 || bursts > 1000) return "bursts must be between 0 and 1000";
  if (!(burst_jerk >= 0.0 && burst_jerk <= 1000.0)) return "burst-jerk must be in [0, 1000] m/s³";
  if (!(bias_share >= 0.0 && bias_share <= 1.0)) return "bias-share must be in [0, 1]";
  return {};
}

namespace {

// The true values the sensors read at one instant: the flown state plus the extra motion.
struct TrueSample {
  Vec3d p;
  double roll, pitch, heading;
  Vec3d v;  // body frame
  double altitude;
};

// At mission time t, `flown` s into the flight (the pilot's clock: the smooth motions the
// guidance does not steer follow it). `waiting`: the robot waits at the surface, with
// none of its own motion.
TrueSample true_sample(const TruthState& s, double t, double flown, const ExtraMotion* extra, bool waiting) {
  TrueSample x{s.p, true_roll(flown), s.pitch, s.heading,
               waiting ? Vec3d(0.0, 0.0, 0.0) : Vec3d(s.speed, true_sway(flown), true_heave(flown)), 0.0};
  if (extra) {
    Vec3d displacement, velocity;
    extra->at(t, displacement, velocity);
    x.p += displacement;
    x.v += world_to_body(make_attitude(x.roll, x.pitch, x.heading), velocity);
  }
  x.altitude = sea_floor_depth(x.p[0], x.p[1]) - x.p[2];
  return x;
}

// The readings of sample k from the truth at k - 1, k and k + 1 (`before`, `at`,
// `after`; the ends repeat `at`) and the rates of the step that follows.
void read_sample(Mission& m, std::size_t k, const TrueSample& before, const TrueSample& at, const TrueSample& after,
                 const Pilot::Rates& rates, double dt, const SensorModel& model, ReadingErrors& error) {
  using E = ReadingErrors;
  const double t = m.time[k];
  const auto curve = [](double a, double b, double c) { return a - 2.0 * b + c; };
  m.roll[k] = at.roll + error(E::roll, model.roll, t, after.roll - at.roll, curve(before.roll, at.roll, after.roll));
  m.pitch[k] = at.pitch + error(E::pitch, model.pitch, t, rates.pitch, curve(before.pitch, at.pitch, after.pitch));
  m.heading[k] = wrap(at.heading + error(E::heading, model.heading, t, rates.turn,
                                         curve(before.heading, at.heading, after.heading)));
  const E::Sensor dvl_sensors[3] = {E::vx, E::vy, E::vz};
  std::vector<double>* dvl[3] = {&m.vx, &m.vy, &m.vz};
  for (int i = 0; i < 3; ++i) {
    const double v = at.v[i];
    const double change = i == 0 ? rates.speed : (i == 1 ? true_sway(t + dt) : true_heave(t + dt)) - v;
    (*dvl[i])[k] = v + error.scaled(dvl_sensors[i], v, model.dvl_relative, model.dvl_absolute, t, change,
                                    curve(before.v[i], v, after.v[i]));
  }
  const double z = at.p[2];
  m.depth[k] = z + error.scaled(E::depth, z, model.depth_relative, model.depth_absolute, t, after.p[2] - z,
                                curve(before.p[2], z, after.p[2]));
  m.altitude[k] = at.altitude + error(E::altitude, model.altitude, t, after.altitude - at.altitude,
                                      curve(before.altitude, at.altitude, after.altitude));
}

// The DVL without bottom lock at the samples `unlocked`: no reading, bridged by the
// surface speed as an import bridges a log's rows without one (io/imports/nav_grid.h);
// its altitude enclosed between the locked readings.
void drop_bottom_lock(Mission& m, const std::vector<unsigned char>& unlocked, const SensorModel& model) {
  const std::size_t n = m.size();
  ChannelReadings altitude;
  for (std::size_t k = 0; k < n; ++k)
    if (!unlocked[k]) {
      altitude.time.push_back(m.time[k]);
      altitude.value.push_back(m.altitude[k]);
      altitude.half_width.push_back(model.altitude);
    }
  if (altitude.time.empty() || altitude.time.size() == n) return;
  std::vector<double>* readings[3] = {&m.vx, &m.vy, &m.vz};
  std::vector<double>* widths[3] = {&m.half_widths.vx, &m.half_widths.vy, &m.half_widths.vz};
  ChannelFill dvl_fill{"surface_max_speed", 0, 0, 0, altitude.time.front(), altitude.time.back()};
  for (std::size_t k = 0; k < n; ++k) {
    if (unlocked[k]) ++(m.time[k] < altitude.time.front() ? dvl_fill.before : m.time[k] > altitude.time.back() ? dvl_fill.after : dvl_fill.between);
    for (int i = 0; i < 3; ++i) {
      if (unlocked[k]) (*readings[i])[k] = 0.0;
      widths[i]->push_back(unlocked[k] ? model.surface_max_speed : dvl_bound(model, (*readings[i])[k]));
    }
  }
  for (const std::size_t c : {3u, 4u, 5u}) m.half_widths.fill[c] = dvl_fill;
  ChannelAtGrid at = enclose_between_readings(altitude, m.time, model.max_altitude_rate, false);
  m.altitude = std::move(at.value);
  m.half_widths.altitude = std::move(at.half_width);
  m.half_widths.fill[6] = {"max_altitude_rate", dvl_fill.before, dvl_fill.between, dvl_fill.after, altitude.time.front(),
                           altitude.time.back()};
}


// Where a mine crosses the starboard sonar plane below the robot within range: the
// crossings at samples k - 1 and k (the closer of the two).
struct SonarCrossings {
  struct Crossing {
    double time;
    int mine;
    double range;
  };
  std::vector<Vec3d> mines;
  std::vector<Vec3d> previous_offset;  // per mine: the robot-frame offset at the previous sample
  std::vector<char> previous_valid;
  std::vector<Crossing> found;

  explicit SonarCrossings(std::vector<Vec3d> mine_positions)
      : mines(std::move(mine_positions)), previous_offset(mines.size()), previous_valid(mines.size(), 0) {}

  void at(const Mission& m, std::size_t k, const TrueSample& x, const SensorModel& model) {
    const Attitude<double> att = make_attitude(x.roll, x.pitch, x.heading);
    for (std::size_t i = 0; i < mines.size(); ++i) {
      const Vec3d e = x.p - mines[i];
      if (std::hypot(e[0], e[1]) > model.sonar_max_range + 20.0) {
        previous_valid[i] = 0;
        continue;
      }
      const Vec3d eb = world_to_body(att, e);
      if (previous_valid[i] && (eb[0] <= 0.0) != (previous_offset[i][0] <= 0.0)) {
        const bool now_closer = std::fabs(eb[0]) <= std::fabs(previous_offset[i][0]);
        const Vec3d close = now_closer ? eb : previous_offset[i];
        const std::size_t kc = now_closer ? k : k - 1;
        const double range = close.norm();
        if (close[1] < 0.0 && close[2] < 0.0 && range < model.sonar_max_range - 2.0 &&
            std::fabs(close[0]) < 0.9 * model.along_track_tolerance)
          found.push_back({m.time[kc], static_cast<int>(i), range});
      }
      previous_offset[i] = eb;
      previous_valid[i] = 1;
    }
  }
};

// GPS fixes in the local frame: at the first and the last sample, and every second at
// the surface.
void add_fixes(Mission& m, const SimulationOptions& o, const ExtraMotion& extra, const SensorModel& model,
               ReadingErrors& error) {
  const std::size_t n = m.size();
  const std::size_t every = std::max<std::size_t>(1, static_cast<std::size_t>(std::llround(o.rate)));
  for (std::size_t k = 0; k < n; ++k) {
    const bool surface_fix = extra.at_surface(m.time[k]) && k % every == 0;
    if (k != 0 && k != n - 1 && !surface_fix) continue;
    m.gps_time.push_back(m.time[k]);
    m.gps_north.push_back(m.truth_x[k] + error(ReadingErrors::gps_north, model.gps_metres, m.time[k]));
    m.gps_east.push_back(m.truth_y[k] + error(ReadingErrors::gps_east, model.gps_metres, m.time[k]));
    // Boxes of the metric bound, usable in memory; io/ recomputes them from the
    // longitudes and latitudes when the mission is written and read back.
    m.gps_north_halfwidth.push_back(model.gps_metres);
    m.gps_east_halfwidth.push_back(model.gps_metres);
    m.truth_gps_outlier.push_back(0);
  }
}

}  // namespace

Mission simulate_mission(const SimulationOptions& o, const SensorModel& model) {
  RandomSource rng(o.seed);
  ReadingErrors error(rng, o);
  Mission m;
  m.model = model;
  m.mine_count = o.mines;
  const std::size_t n = static_cast<std::size_t>(std::floor(o.duration * o.rate + 1e-9)) + 1;
  const double dt = 1.0 / o.rate;
  // The survey flies between the surface phases (the whole mission without them).
  const double flight = o.duration - 2.0 * o.surface;
  double path_length = 0.0;
  const std::vector<Waypoint> plan = plan_for(flight, path_length);
  const double mean_speed = calibrated_speed(plan, path_length, flight, dt);
  SonarCrossings sonar(reference_mines(o.mines, sea_floor_depth));
  for (const Vec3d& mine : sonar.mines) m.truth_mines.insert(m.truth_mines.end(), {mine[0], mine[1], mine[2]});

  for (std::vector<double>* v : {&m.time, &m.roll, &m.pitch, &m.heading, &m.vx, &m.vy, &m.vz, &m.altitude, &m.depth,
                                 &m.truth_x, &m.truth_y, &m.truth_z})
    v->resize(n);

  const ExtraMotion extra(o);
  const bool has_extra = o.surface > 0.0 || o.bursts > 0;
  TruthState s = start_state(plan, mean_speed);
  Pilot pilot(plan, mean_speed);
  if (o.surface > 0.0) {
    s.p[2] = kSurfaceDepth;
    s.speed = 0.0;
    pilot.surface_at_end(flight - kClimbTime, flight - kStopTime);
  }
  std::vector<unsigned char> unlocked(n, 0);
  // The truth at k - 1, k and k + 1: the flown state (stepped from k to k + 1 before
  // sample k's readings, whose errors may depend on the step) plus the extra motion.
  const auto waiting = [&](double t) { return o.surface > 0.0 && (t <= o.surface || t >= o.duration - o.surface); };
  TrueSample at = true_sample(s, 0.0, -o.surface, has_extra ? &extra : nullptr, waiting(0.0)), before = at;
  for (std::size_t k = 0; k < n; ++k) {
    const double t = static_cast<double>(k) * dt;
    m.time[k] = t;
    m.truth_x[k] = at.p[0];
    m.truth_y[k] = at.p[1];
    m.truth_z[k] = at.p[2];
    // The step that follows (its rates orient the at-samples errors); the robot waits
    // at the surface before the survey.
    const bool flying = k + 1 < n && !waiting(t);
    const Pilot::Rates rates = flying ? pilot.step(s, t - o.surface, dt) : Pilot::Rates{};
    const TrueSample after =
        k + 1 < n ? true_sample(s, t + dt, t + dt - o.surface, has_extra ? &extra : nullptr, waiting(t + dt)) : at;
    read_sample(m, k, before, at, after, rates, dt, model, error);
    unlocked[k] = extra.at_surface(t) && !o.surface_dvl;
    sonar.at(m, k, at, model);
    before = at;
    at = after;
  }

  // Marks: missed ones go to the truth, outliers are corrupted, some lose their number.
  const std::vector<SonarCrossings::Crossing>& crossings = sonar.found;
  std::vector<std::size_t> kept;
  for (const SonarCrossings::Crossing& c : crossings) {
    if (rng.chance(o.missed)) {
      m.truth_missed_marks.insert(m.truth_missed_marks.end(), {c.time, static_cast<double>(c.mine), c.range});
      continue;
    }
    m.mark_time.push_back(c.time);
    m.mark_mine.push_back(rng.chance(o.unassociated) ? -1 : c.mine);
    m.mark_range.push_back(c.range + error(ReadingErrors::mark, model.mark_range, c.time));
    m.mark_side.push_back(1);
    m.truth_marks_outlier.push_back(0);
    m.truth_marks_mine.push_back(c.mine);
  }
  for (int q = 0; q < o.outliers && q < static_cast<int>(m.mark_count()); ++q) {
    std::size_t j;
    do j = static_cast<std::size_t>(rng.uniform() * static_cast<double>(m.mark_count()));
    while (m.truth_marks_outlier[j]);
    m.truth_marks_outlier[j] = 1;
    const double shift = rng.uniform(20.0, 35.0);  // far beyond the ±1 m bound
    m.mark_range[j] = m.mark_range[j] + shift <= model.sonar_max_range ? m.mark_range[j] + shift : m.mark_range[j] - shift;
    m.mark_range[j] = std::max(m.mark_range[j], 0.0);
  }

  add_fixes(m, o, extra, model, error);
  if (o.surface > 0.0 && !o.surface_dvl) drop_bottom_lock(m, unlocked, model);
  return m;
}

}  // namespace gesmi
