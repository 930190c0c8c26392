#include "tests/support/sonar_configuration.h"

#include <cmath>
#include <numbers>

#include "tests/support/rotation_long_double.h"
#include "tests/support/random_draws.h"

namespace gesmi::test {
namespace {


void body_vector(const SonarConfiguration& c, long double eb[3], long double e[3]) {
  const RotationLd r(c.roll, c.pitch, c.heading);
  for (int i = 0; i < 3; ++i) e[i] = static_cast<long double>(c.p[i]) - c.m[i];  // exact: doubles of similar size
  r.to_body(e, eb);
}

}  // namespace

long double adversarial(std::mt19937_64& rng, long double lo, long double hi) {
  const long double mid = 0.5L * (lo + hi), half = 0.5L * (hi - lo) * kStrictlyInside;
  switch (rng() % 3) {
    case 0: return mid - half;
    case 1: return mid + half;
    default: return uniform(rng, mid - half, mid + half);
  }
}

bool satisfies_mark_geometry(const SonarConfiguration& c, const SensorModel& model) {
  long double eb[3], e[3];
  body_vector(c, eb, e);
  const long double s = -e[2] - c.altitude;  // e.z = -(a + s)
  const long double norm = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
  return std::fabs(eb[0]) <= model.along_track_tolerance && c.side * eb[1] <= 0.0L && eb[2] <= 0.0L &&
         std::fabs(s) <= model.mine_depth_band && std::fabs(norm - c.range) <= 1e-12L * (1.0L + norm) &&
         std::fabs(c.measured_range - c.range) <= model.mark_range;
}

SonarConfiguration random_sonar_configuration(std::mt19937_64& rng, const SensorModel& model, double max_range,
                                              const double* robot) {
  for (;;) {
    SonarConfiguration c;
    const auto pick = [&](double lo, double hi) { return rng() % 4 == 0 ? 0.0 : static_cast<double>(uniform(rng, lo, hi)); };
    c.roll = pick(-0.3, 0.3);
    c.pitch = pick(-0.3, 0.3);
    c.heading = rng() % 8 == 0 ? (rng() % 2 ? std::numbers::pi : -std::numbers::pi) : pick(-3.2, 3.2);
    c.side = rng() % 2 ? 1 : -1;
    const long double tol = model.along_track_tolerance;
    long double range;
    switch (rng() % 5) {
      case 0: range = max_range * kStrictlyInside; break;
      case 1: range = uniform(rng, 1e-3L, 2.0L); break;
      default: range = uniform(rng, 1.0L, max_range);
    }
    // e_b = (along, across, down): along within the tolerance, the rest of the
    // length in the lower half of the sonar plane on the declared side, from
    // grazing (down near 0) to straight below (across near 0).
    const long double along = std::min(range, tol) * adversarial(rng, -1.0L, 1.0L);
    const long double rest = std::sqrt(std::max(0.0L, range * range - along * along));
    const long double beta = adversarial(rng, 1e-6L, std::numbers::pi_v<long double> / 2 - 1e-6L);
    const long double eb[3] = {along, -c.side * rest * std::cos(beta), -rest * std::sin(beta)};
    long double e[3];
    RotationLd(c.roll, c.pitch, c.heading).to_world(eb, e);
    for (int i = 0; i < 3; ++i) {
      c.p[i] = robot ? robot[i] : static_cast<double>(i == 2 ? uniform(rng, 0.0L, 100.0L) : uniform(rng, -2000.0L, 2000.0L));
      c.m[i] = static_cast<double>(c.p[i] - e[i]);
    }
    long double actual_b[3], actual[3];
    body_vector(c, actual_b, actual);
    c.range = std::sqrt(actual[0] * actual[0] + actual[1] * actual[1] + actual[2] * actual[2]);
    const long double s = adversarial(rng, -model.mine_depth_band, model.mine_depth_band);
    c.altitude = -actual[2] - s;
    c.measured_range = static_cast<double>(c.range + adversarial(rng, -model.mark_range, model.mark_range));
    if (c.range <= max_range && satisfies_mark_geometry(c, model)) return c;  // rounding kept it feasible
  }
}

}  // namespace gesmi::test
