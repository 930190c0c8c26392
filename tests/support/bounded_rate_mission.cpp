#include "tests/support/bounded_rate_mission.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "tests/support/rotation_long_double.h"
#include "tests/support/random_draws.h"

namespace gesmi::test {
namespace {

constexpr long double kPiL = 3.141592653589793238462643383279502884L;

enum class Shape { line, tent_up, tent_down };

// Appends the knots of step [t0, t1] from x0 to x1 (x0 is already the last knot):
// a line, or out at `rate` and back (the peak or trough is the only inner knot).
void add_step(Track& track, long double t0, long double t1, long double x0, long double x1, long double rate,
              Shape shape) {
  if (shape != Shape::line && rate > 0.0L) {
    const long double d = shape == Shape::tent_up ? 1.0L : -1.0L;
    const long double peak_time = (d * (x1 - x0) + rate * (t0 + t1)) / (2.0L * rate);
    if (peak_time > t0 && peak_time < t1) {
      track.t.push_back(peak_time);
      track.x.push_back(x0 + d * rate * (peak_time - t0));
    }
  }
  track.t.push_back(t1);
  track.x.push_back(x1);
}

// A reading r with truth = r + side * kStrictlyInside * bound(r): the truth sits at the
// `side` end of the sample box (side 0: a random point inside). bound is
// Lipschitz with a small constant (DVL: 0.004), so a few fixed-point passes solve it.
template <class Bound>
double reading_for(long double truth, int side, long double inside, Bound bound) {
  long double r = truth;
  for (int pass = 0; pass < 6; ++pass) r = truth - side * inside * bound(r);
  return static_cast<double>(r);
}

struct QuantitySpec {
  long double start, lo, hi;       // first value and the range the walk stays in
  long double up_bias = 0.0L;      // probability of a full-rate step up (drift)
};

// Sample values x_k (a walk whose steps stay within rate * dt) and the sides of
// the sample boxes where the truth sits; then the knots, with tents toward the
// side when both ends of a step sit on the same side.
Track make_track(const std::vector<long double>& times, const std::vector<long double>& rates, const QuantitySpec& spec,
                 std::vector<int>& sides, std::mt19937_64& rng) {
  const std::size_t n = times.size();
  std::vector<long double> x(n);
  x[0] = spec.start;
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const long double reach = rates[k] * (times[k + 1] - times[k]);
    const long double p = uniform(rng, 0.0L, 1.0L);
    long double u;
    if (p < spec.up_bias) u = 1.0L;
    else if (p < spec.up_bias + 0.4L) u = 0.0L;  // hold: tents then reach the widened bound exactly
    else if (p < spec.up_bias + 0.55L) u = rng() % 2 ? 1.0L : -1.0L;  // full-rate ramp
    else u = uniform(rng, -1.0L, 1.0L);
    if (x[k] + u * reach > spec.hi) u = -std::fabs(u);
    if (x[k] + u * reach < spec.lo) u = std::fabs(u);
    x[k + 1] = x[k] + u * reach;
  }
  sides.assign(n, 0);
  sides[0] = rng() % 2 ? 1 : -1;
  for (std::size_t k = 1; k < n; ++k) {
    const int previous = sides[k - 1] == 0 ? 1 : sides[k - 1];
    const auto p = rng() % 20;
    sides[k] = p < 13 ? previous : (p < 17 ? -previous : 0);
  }
  Track track;
  track.t.push_back(times[0]);
  track.x.push_back(x[0]);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    Shape shape;
    if (sides[k] != 0 && sides[k] == sides[k + 1] && rng() % 5 != 0)
      shape = sides[k] > 0 ? Shape::tent_up : Shape::tent_down;
    else
      shape = static_cast<Shape>(rng() % 3);
    add_step(track, times[k], times[k + 1], x[k], x[k + 1], rates[k], shape);
  }
  return track;
}

}  // namespace

long double Track::at(long double time) const {
  if (time <= t.front()) return x.front();
  if (time >= t.back()) return x.back();
  const auto i = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), time) - t.begin());  // t[i-1] <= time < t[i]
  const long double w = (time - t[i - 1]) / (t[i] - t[i - 1]);
  return x[i - 1] + w * (x[i] - x[i - 1]);
}

void TrueMotion::world_velocity(long double time, long double out[3]) const {
  const RotationLd r(roll.at(time), pitch.at(time), heading.at(time));
  const long double v[3] = {vx.at(time), vy.at(time), vz.at(time)};
  r.to_world(v, out);
}

void TrueMotion::displacement(long double t0, long double t1, long double out[3]) const {
  static constexpr long double node[2] = {0.3399810435848562648026658L, 0.8611363115940525752239465L};
  static constexpr long double weight[2] = {0.6521451548625461426269361L, 0.3478548451374538573730639L};
  std::vector<long double> cuts = {t0};
  for (auto it = std::upper_bound(knots.begin(), knots.end(), t0); it != knots.end() && *it < t1; ++it)
    cuts.push_back(*it);
  cuts.push_back(t1);
  out[0] = out[1] = out[2] = 0.0L;
  for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
    const long double a = cuts[c], b = cuts[c + 1];
    const int pieces = std::max(1, static_cast<int>(std::ceil((b - a) / 0.01L)));
    const long double h = (b - a) / pieces;
    for (int p = 0; p < pieces; ++p) {
      const long double centre = a + (p + 0.5L) * h, half = 0.5L * h;
      for (int i = 0; i < 2; ++i)
        for (const long double sign : {-1.0L, 1.0L}) {
          long double w[3];
          world_velocity(centre + sign * node[i] * half, w);
          for (int j = 0; j < 3; ++j) out[j] += weight[i] * half * w[j];
        }
    }
  }
}

BoundedRateMission make_bounded_rate_mission(std::uint64_t seed, const BoundedRateOptions& options) {
  std::mt19937_64 rng(seed);
  BoundedRateMission out;
  Mission& m = out.mission;
  const SensorModel& model = options.model;
  m.model = model;
  const std::size_t n = options.samples;

  // Irregular steps: mostly 0.1 s, some short, some long (where a tent goes far).
  std::vector<long double> times(n);
  double t = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    m.time.push_back(t);
    times[k] = t;
    static constexpr double kSteps[] = {0.1, 0.1, 0.1, 0.1, 0.1, 0.05, 0.013, 0.5, 2.0, 0.1};
    const double dt = kSteps[rng() % 10];
    t += rng() % 4 == 0 ? dt * static_cast<double>(uniform(rng, 0.5L, 1.5L)) : dt;
  }
  const std::vector<long double> attitude_rate(n, model.max_attitude_rate * kStrictlyInside);
  const std::vector<long double> acceleration(n, model.max_acceleration * kStrictlyInside);

  TrueMotion& truth = out.truth;
  std::vector<int> side_roll, side_pitch, side_heading, side_vx, side_vy, side_vz, side_altitude;
  truth.roll = make_track(times, attitude_rate, {0.0L, -0.2L, 0.2L}, side_roll, rng);
  truth.pitch = make_track(times, attitude_rate, {0.0L, -0.2L, 0.2L}, side_pitch, rng);
  const long double h0 = options.initial_heading;
  const bool crossing = std::fabs(std::fabs(h0) - kPiL) < 0.1L;  // near the cut: drift across it
  truth.heading = make_track(times, attitude_rate,
                             crossing ? QuantitySpec{h0, h0 - 0.05L, h0 + 0.8L, 0.3L} : QuantitySpec{h0, h0 - 0.03L, h0 + 0.03L},
                             side_heading, rng);
  truth.vx = make_track(times, acceleration, {1.5L, 0.5L, 2.5L}, side_vx, rng);
  const long double lateral = options.lateral_speed;
  truth.vy = make_track(times, acceleration, {0.0L, -lateral, lateral}, side_vy, rng);
  truth.vz = make_track(times, acceleration, {0.0L, -lateral, lateral}, side_vz, rng);
  // Altitude: its rate is bounded by |v| (1 + slope) (docs/model.md), here by the
  // smallest |vx| over the step (|v| >= |vx|), taken over the knots of vx.
  const long double slope = static_cast<long double>(model.mine_depth_band) / model.sonar_max_range;
  std::vector<long double> altitude_rate(n, 0.0L);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    long double slowest = std::min(std::fabs(truth.vx.at(times[k])), std::fabs(truth.vx.at(times[k + 1])));
    for (std::size_t i = 0; i < truth.vx.t.size(); ++i)
      if (truth.vx.t[i] > times[k] && truth.vx.t[i] < times[k + 1]) slowest = std::min(slowest, std::fabs(truth.vx.x[i]));
    altitude_rate[k] = slowest * (1.0L + slope) * kStrictlyInside;
  }
  truth.altitude = make_track(times, altitude_rate, {10.0L, 5.0L, 15.0L}, side_altitude, rng);

  for (const Track* track : {&truth.roll, &truth.pitch, &truth.heading, &truth.vx, &truth.vy, &truth.vz, &truth.altitude})
    truth.knots.insert(truth.knots.end(), track->t.begin(), track->t.end());
  std::sort(truth.knots.begin(), truth.knots.end());
  truth.knots.erase(std::unique(truth.knots.begin(), truth.knots.end()), truth.knots.end());

  // Readings: the truth at an end of its sample box (or inside it for side 0).
  const auto constant = [](double b) { return [b](long double) { return static_cast<long double>(b); }; };
  const auto dvl = [&](long double r) { return model.dvl_relative * std::fabs(r) + model.dvl_absolute; };
  const auto inside = [&](int side) { return side == 0 ? uniform(rng, -1.0L, 1.0L) * kStrictlyInside : kStrictlyInside; };
  const auto read = [&](const Track& track, const std::vector<int>& sides, std::size_t k, auto bound) {
    const int side = sides[k] == 0 ? 1 : sides[k];
    return reading_for(track.at(times[k]), side, inside(sides[k]), bound);
  };
  for (std::size_t k = 0; k < n; ++k) {
    m.roll.push_back(read(truth.roll, side_roll, k, constant(model.roll)));
    m.pitch.push_back(read(truth.pitch, side_pitch, k, constant(model.pitch)));
    // The gyrocompass wraps its heading into [-pi, pi).
    const double h = read(truth.heading, side_heading, k, constant(model.heading));
    m.heading.push_back(std::remainder(h, 2.0 * std::numbers::pi));
    m.vx.push_back(read(truth.vx, side_vx, k, dvl));
    m.vy.push_back(read(truth.vy, side_vy, k, dvl));
    m.vz.push_back(read(truth.vz, side_vz, k, dvl));
    m.altitude.push_back(read(truth.altitude, side_altitude, k, constant(model.altitude)));
    m.depth.push_back(10.0);
  }

  // True positions at the samples.
  out.px.assign(n, 0.0L);
  out.py.assign(n, 0.0L);
  out.pz.assign(n, 0.0L);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    long double d[3];
    truth.displacement(times[k], times[k + 1], d);
    out.px[k + 1] = out.px[k] + d[0];
    out.py[k + 1] = out.py[k] + d[1];
    out.pz[k + 1] = out.pz[k] + d[2];
  }
  for (std::size_t k = 0; k < n; ++k) {
    m.truth_x.push_back(static_cast<double>(out.px[k]));
    m.truth_y.push_back(static_cast<double>(out.py[k]));
    m.truth_z.push_back(static_cast<double>(out.pz[k]));
  }
  return out;
}

}  // namespace gesmi::test
