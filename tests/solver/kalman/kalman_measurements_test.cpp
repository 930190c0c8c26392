// The smoother's odometry factors take their rotations' sines and cosines from libmvec
// (kalman_measurements.cpp, SampleRotations): each step's displacement and information
// must be those of the model computed independently, here with libm's sin and cos in
// long double, to within rounding.

#include "solver/kalman/kalman_measurements.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "solver/sim/simulator.h"

namespace gesmi {
namespace {

struct OdometryRecorder final : MeasurementSink {
  std::vector<Mat3d> information;
  std::vector<Vec3d> delta;
  void odometry(std::size_t k, const Mat3d& w, const Vec3d& d, const BiasJacobian&) override {
    EXPECT_EQ(k, delta.size());
    information.push_back(w);
    delta.push_back(d);
  }
  void scalar(std::size_t, const Eigen::RowVector3d&, int, const Eigen::RowVector3d&, const BiasRow&, double, double,
              const ConstraintRef*) override {}
};

using Mat3l = Eigen::Matrix<long double, 3, 3>;
using Vec3l = Eigen::Matrix<long double, 3, 1>;

// R = Rz(heading - bias) Ry(pitch) Rx(roll) (euler.h), in long double.
Mat3l rotation(long double roll, long double pitch, long double heading) {
  Mat3l x, y, z;
  x << 1, 0, 0, 0, std::cos(roll), -std::sin(roll), 0, std::sin(roll), std::cos(roll);
  y << std::cos(pitch), 0, std::sin(pitch), 0, 1, 0, -std::sin(pitch), 0, std::cos(pitch);
  z << std::cos(heading), -std::sin(heading), 0, std::sin(heading), std::cos(heading), 0, 0, 0, 1;
  return z * y * x;
}

TEST(KalmanMeasurements, OdometryIsTheModelsWithLibmRotations) {
  SimulationOptions o;
  o.seed = 4;
  o.duration = 300.0;  // 3,000 samples: blocks of 256 and a last partial one
  Mission m = simulate_mission(o);
  // Headings far from the first turn too: the vector functions' range reduction.
  for (std::size_t k = 0; k < m.size(); k += 7) m.heading[k] += 2000.0 * M_PI;
  for (const double bias : {0.0, 0.01}) {
    SCOPED_TRACE(::testing::Message() << "heading bias " << bias);
    KalmanLinearisation lin;
    lin.position.assign(m.size(), Vec3d::Zero());
    lin.bias[bias_heading] = bias;
    OdometryRecorder recorder;
    linearise_measurements(m, m.model, {}, {1.0, bias != 0.0, FactorSet::odometry, {}}, lin, recorder);
    ASSERT_EQ(recorder.delta.size(), m.size() - 1);
    const auto at = [&](std::size_t k) {
      return rotation(m.roll[k], m.pitch[k], static_cast<long double>(m.heading[k]) - bias);
    };
    for (std::size_t k = 0; k + 1 < m.size(); ++k) {
      const long double dt = m.time[k + 1] - m.time[k];
      const Mat3l r0 = at(k), r1 = at(k + 1);
      // (the DVL biases at the linearisation point are zero: the readings themselves)
      const Vec3l v0(m.vx[k], m.vy[k], m.vz[k]), v1(m.vx[k + 1], m.vy[k + 1], m.vz[k + 1]);
      const Vec3l expected = 0.5L * dt * (r0 * v0 + r1 * v1);
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(static_cast<double>(expected[c]), recorder.delta[k][c], 1e-13 + 1e-12 * std::fabs(expected[c]))
            << "step " << k << " axis " << c;
      Vec3l var_body;
      for (int c = 0; c < 3; ++c)
        var_body[c] = uniform_variance(m.model.dvl_relative * std::fabs(static_cast<double>(v0[c])) + m.model.dvl_absolute, 1.0);
      const Mat3l cov = dt * dt * r0 * var_body.asDiagonal() * r0.transpose() + 1e-12L * Mat3l::Identity();
      const Mat3l product = cov * recorder.information[k].cast<long double>();
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          ASSERT_NEAR(static_cast<double>(product(i, j)), i == j ? 1.0 : 0.0, 1e-9) << "step " << k;
    }
  }
}

}  // namespace
}  // namespace gesmi
