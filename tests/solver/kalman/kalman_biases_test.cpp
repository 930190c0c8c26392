// The bias-aware Kalman smoother: its measurement model's derivatives against finite
// differences of the model itself, and the recovery of known constant biases added to
// the readings of a mission whose other errors are tiny.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "solver/kalman/kalman_measurements.h"
#include "solver/kalman/kalman_smoother.h"
#include "solver/sim/simulator.h"

namespace gesmi {
namespace {

// Every factor the model generates, in order.
struct Recorder final : MeasurementSink {
  std::vector<Vec3d> delta;
  std::vector<BiasJacobian> jacobian;
  std::vector<double> prediction;  // hp . p + hm . m + hb . b - z at the linearisation point
  std::vector<BiasRow> hb;
  const KalmanLinearisation* lin = nullptr;
  void odometry(std::size_t, const Mat3d&, const Vec3d& d, const BiasJacobian& j) override {
    delta.push_back(d);
    jacobian.push_back(j);
  }
  void scalar(std::size_t k, const Eigen::RowVector3d& hp, int mine, const Eigen::RowVector3d& hm, const BiasRow& row,
              double z, double, const ConstraintRef*) override {
    double value = hp.dot(lin->position[k]) + row.dot(lin->bias) - z;
    if (mine >= 0) value += hm.dot(lin->mine[static_cast<std::size_t>(mine)]);
    prediction.push_back(value);
    hb.push_back(row);
  }
};

Recorder record(const Mission& m, KalmanLinearisation lin) {
  Recorder r;
  r.lin = &lin;
  linearise_measurements(m, m.model, gps_fixes(m), {1.0, true}, lin, r);
  return r;
}

// A short simulated mission with its mines placed once (so that every call generates
// the same factors).
struct Fixture {
  Mission mission;
  KalmanLinearisation lin;
};

Fixture fixture() {
  SimulationOptions o;
  o.seed = 3;
  o.duration = 900.0;
  Fixture f{simulate_mission(o), {}};
  const std::size_t n = f.mission.size(), k = static_cast<std::size_t>(f.mission.mine_count);
  f.lin.position.assign(n, Vec3d::Zero());
  for (std::size_t i = 0; i < n; ++i)
    f.lin.position[i] = Vec3d(f.mission.truth_x[i], f.mission.truth_y[i], f.mission.truth_z[i]);
  f.lin.mine.assign(k, Vec3d::Zero());
  f.lin.mine_known.assign(k, 0);
  Recorder placing;
  placing.lin = &f.lin;
  linearise_measurements(f.mission, f.mission.model, gps_fixes(f.mission), {1.0, true}, f.lin, placing);
  f.lin.bias << 0.003, 0.002, -0.001, 0.001, 0.002, -0.002, 0.001, 0.05, 0.5;
  return f;
}

// The derivatives of the odometry and of every scalar measurement with respect to each
// bias equal central differences of the model's own values at nearby points.
TEST(KalmanBiases, DerivativesMatchFiniteDifferencesOfTheModel) {
  const Fixture f = fixture();
  const Recorder at = record(f.mission, f.lin);
  ASSERT_GT(at.delta.size(), 1000u);
  const BiasVec steps = (BiasVec() << 1e-5, 1e-5, 1e-5, 1e-5, 1e-5, 1e-5, 1e-5, 1e-4, 1e-3).finished();
  for (int b = 0; b < kBiasCount; ++b) {
    KalmanLinearisation plus = f.lin, minus = f.lin;
    plus.bias[b] += steps[b];
    minus.bias[b] -= steps[b];
    const Recorder up = record(f.mission, plus), down = record(f.mission, minus);
    double worst_odometry = 0.0, worst_scalar = 0.0;
    for (std::size_t k = 0; k < at.delta.size(); ++k) {
      const Vec3d numeric = (up.delta[k] - down.delta[k]) / (2.0 * steps[b]);
      worst_odometry = std::max(worst_odometry, (numeric - at.jacobian[k].col(b)).cwiseAbs().maxCoeff() /
                                                    std::max(1e-3, at.jacobian[k].col(b).cwiseAbs().maxCoeff()));
    }
    for (std::size_t i = 0; i < at.prediction.size(); ++i) {
      const double numeric = (up.prediction[i] - down.prediction[i]) / (2.0 * steps[b]);
      worst_scalar = std::max(worst_scalar, std::fabs(numeric - at.hb[i][b]) / std::max(1.0, std::fabs(at.hb[i][b])));
    }
    EXPECT_LT(worst_odometry, 1e-5) << bias_descriptions()[static_cast<std::size_t>(b)].name;
    EXPECT_LT(worst_scalar, 1e-6) << bias_descriptions()[static_cast<std::size_t>(b)].name;
  }
}

// Readings of a mission simulated with tiny errors, with known constant biases added
// (reading = truth + bias, as the model defines them), smoothed with the declared
// bounds: the bias-aware smoother finds every bias within 3 sigma and contains the
// truth, where the plain smoother does not.
TEST(KalmanBiases, RecoversConstantBiasesAddedToTheReadings) {
  SensorModel tiny;
  tiny.roll = tiny.pitch = 1e-7;
  tiny.heading = 1e-6;
  tiny.dvl_relative = tiny.dvl_absolute = 1e-6;
  tiny.depth_absolute = 0.01;
  tiny.depth_relative = 0.0;
  tiny.altitude = 0.001;
  tiny.mark_range = 0.01;
  tiny.gps_metres = 0.5;
  SimulationOptions o;
  o.seed = 2;
  o.duration = 2400.0;
  Mission m = simulate_mission(o, tiny);
  m.model = SensorModel{};  // smoothed with the declared bounds
  BiasVec injected;
  injected << 0.004, 0.003, 0.0, 0.0, -0.003, 0.002, 0.0, 0.1, 1.0;
  for (std::size_t k = 0; k < m.size(); ++k) {
    m.heading[k] += injected[bias_heading];
    std::vector<double>* v[3] = {&m.vx, &m.vy, &m.vz};
    for (int c = 0; c < 3; ++c)
      (*v[c])[k] = (*v[c])[k] * (1.0 + injected[bias_dvl_scale_x + c]) + injected[bias_dvl_offset_x + c];
    m.depth[k] = m.depth[k] * (1.0 + injected[bias_depth_scale]) + injected[bias_depth_offset];
  }
  const std::vector<PositionFix> fixes = gps_fixes(m);
  KalmanOptions with;
  with.biases = true;
  const KalmanResult plain = kalman_smooth(m, m.model, fixes), aware = kalman_smooth(m, m.model, fixes, with);
  ASSERT_TRUE(aware.converged);
  for (int b = 0; b < kBiasCount; ++b) {
    std::printf("[ report ] %-12s injected %+.4g, estimated %+.4g (sigma %.3g, prior %.3g)\n",
                std::string(bias_descriptions()[static_cast<std::size_t>(b)].name).c_str(), injected[b],
                aware.bias_estimate[b], aware.bias_sigma[b], aware.bias_prior_sigma[b]);
    EXPECT_LE(std::fabs(aware.bias_estimate[b] - injected[b]), 3.0 * aware.bias_sigma[b])
        << bias_descriptions()[static_cast<std::size_t>(b)].name;
  }
  // The biases the data determine are found far more precisely than their priors (the
  // DVL's along-track scale and offset only together, at a nearly constant speed).
  for (const int b : {int{bias_heading}, int{bias_depth_scale}})
    EXPECT_LT(aware.bias_sigma[b], 0.5 * aware.bias_prior_sigma[b]) << bias_descriptions()[static_cast<std::size_t>(b)].name;
  // Nothing but the barometer sees the absolute depth: its offset keeps its prior.
  EXPECT_GT(aware.bias_sigma[bias_depth_offset], 0.99 * aware.bias_prior_sigma[bias_depth_offset]);
  const Containment c = three_sigma_containment(aware, m);
  std::printf("[ report ] truth within 3 sigma horizontally: bias-aware %.1f %% of steps, plain %.1f %%; chi2/dof plain %.3g, "
              "bias-aware %.3g\n",
              100.0 * c.horizontal, 100.0 * three_sigma_containment(plain, m).horizontal,
              plain.consistency.chi2_per_dof, aware.consistency.chi2_per_dof);
  EXPECT_GE(c.horizontal, 0.99);
  EXPECT_GE(c.vertical, 0.99);
  EXPECT_LT(three_sigma_containment(plain, m).horizontal, 0.5);
  EXPECT_FALSE(plain.biases);
}

}  // namespace
}  // namespace gesmi
