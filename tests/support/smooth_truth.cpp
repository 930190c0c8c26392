#include "tests/support/smooth_truth.h"

#include <numbers>

namespace gesmi::test {

Mission mission_of(const SmoothTruth& truth, const SensorModel& model, std::size_t samples, std::uint64_t seed,
                   double heading_error) {
  Mission m;
  m.model = model;
  std::uint64_t state = seed;
  const auto next_unit = [&] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) / 9007199254740992.0;
  };
  double t = 0.0;
  for (std::size_t k = 0; k < samples; ++k) {
    m.time.push_back(t);
    const auto lean = [&](const Wave& w, double bound) {
      const long double curvature = w.second_derivative(t);
      return static_cast<double>(w.at(t)) + 0.99 * bound * (curvature >= 0.0L ? 1.0 : -1.0);
    };
    const auto dvl_bound = [&](const Wave& w) {
      return (model.dvl_relative * std::fabs(static_cast<double>(w.at(t))) + model.dvl_absolute) / (1.0 + model.dvl_relative);
    };
    m.roll.push_back(0.0);
    m.pitch.push_back(0.0);
    m.heading.push_back(static_cast<double>(truth.heading) + heading_error);
    m.vx.push_back(lean(truth.vx, dvl_bound(truth.vx)));
    m.vy.push_back(lean(truth.vy, dvl_bound(truth.vy)));
    m.vz.push_back(lean(truth.vz, dvl_bound(truth.vz)));
    m.altitude.push_back(10.0);
    m.depth.push_back(5.0);
    t += 0.05 + 0.25 * next_unit();
  }
  return m;
}

std::vector<SmoothTruth> truths() {
  std::vector<SmoothTruth> all;
  for (const long double heading : {0.0L, 0.7L, std::numbers::pi_v<long double> - 0.01L, -2.0L})
    all.push_back({heading, {1.5L, 0.15L, 2.0L, 0.3L}, {0.0L, 0.075L, 2.0L, 1.1L}, {0.0L, 0.0225L, 6.3245553L, 0.0L}});
  return all;
}

SensorModel model_with(StepModel step, double jerk) {
  SensorModel model;
  model.step_model = step;
  model.max_jerk = jerk;
  model.max_acceleration = 5.0;
  model.max_attitude_rate = 1.0;
  return model;
}

}  // namespace gesmi::test
