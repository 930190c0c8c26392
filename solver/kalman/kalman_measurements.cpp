#include "solver/kalman/kalman_measurements.h"

#include <algorithm>
#include <Eigen/LU>
#include <cmath>
#include <stdexcept>

#include "solver/model/euler.h"
#include "solver/model/vector_sin_cos.h"

namespace gesmi {
namespace {

// The rotation of an attitude.
Mat3d rotation(const Attitude<double>& a) {
  Mat3d r;
  for (int c = 0; c < 3; ++c) r.col(c) = body_to_world(a, Vec3d(Vec3d::Unit(c)));
  return r;
}

// The rotation at these angles with the heading corrected by the heading bias.
Mat3d rotation(double roll, double pitch, double heading, double heading_bias) {
  return rotation(make_attitude(roll, pitch, heading - heading_bias));
}

// The rotations of the samples in order, their sines and cosines from libmvec a block at
// a time (vector_sin_cos.h): glibc's scalar sincos was 3-4 % of the smoother at 10^6 steps.
// Within 4 ulps of libm's (glibc's tested bound), far below the smoother's own rounding;
// angles beyond kVectorLibmLargest take libm's.
class SampleRotations {
 public:
  SampleRotations(const Mission& m, double heading_bias) : m_(m), heading_bias_(heading_bias) {}
  /// Sample k's rotation; k goes up by one from call to call.
  Mat3d at(std::size_t k) {
    if (k < first_ || k >= first_ + filled_) fill(k);
    const std::size_t j = k - first_;
    SinCos<double> sc[3];
    for (int a = 0; a < 3; ++a)
      sc[a] = std::fabs(angle_[a][j]) < kVectorLibmLargest ? SinCos<double>{sine_[a][j], cosine_[a][j]}
                                                           : sin_cos(angle_[a][j]);
    return rotation(Attitude<double>{sc[0], sc[1], sc[2]});
  }

 private:
  static constexpr std::size_t kBlock = 256;
  void fill(std::size_t first) {
    first_ = first;
    const std::size_t n = std::min(kBlock, m_.size() - first);
    filled_ = n;
    for (std::size_t j = 0; j < n; ++j) {
      angle_[0][j] = m_.roll[first + j];
      angle_[1][j] = m_.pitch[first + j];
      angle_[2][j] = m_.heading[first + j] - heading_bias_;
    }
    for (int a = 0; a < 3; ++a) sin_cos_many(angle_[a].data(), n, sine_[a].data(), cosine_[a].data());
  }

  const Mission& m_;
  double heading_bias_;
  std::size_t first_ = 0, filled_ = 0;  // the block's samples: [first_, first_ + filled_)
  std::array<std::array<double, kBlock>, 3> angle_{}, sine_{}, cosine_{};
};

// d/dpsi Rz(psi) = S Rz(psi): the heading's derivative of a world vector w is S w.
Vec3d heading_derivative(const Vec3d& w) { return Vec3d(-w[1], w[0], 0.0); }

}  // namespace

const std::array<BiasDescription, kBiasCount>& bias_descriptions() {
  static const std::array<BiasDescription, kBiasCount> list = {{{"heading", "rad"},
                                                                {"dvl_scale_x", "1"},
                                                                {"dvl_scale_y", "1"},
                                                                {"dvl_scale_z", "1"},
                                                                {"dvl_offset_x", "m/s"},
                                                                {"dvl_offset_y", "m/s"},
                                                                {"dvl_offset_z", "m/s"},
                                                                {"depth_scale", "1"},
                                                                {"depth_offset", "m"}}};
  return list;
}

BiasVec bias_prior_sigma(const SensorModel& model, double f) {
  BiasVec sigma;
  sigma[bias_heading] = std::sqrt(uniform_variance(model.heading, f));
  for (int c = 0; c < 3; ++c) {
    sigma[bias_dvl_scale_x + c] = std::sqrt(uniform_variance(model.dvl_relative, f));
    sigma[bias_dvl_offset_x + c] = std::sqrt(uniform_variance(model.dvl_absolute, f));
  }
  sigma[bias_depth_scale] = std::sqrt(uniform_variance(model.depth_relative, f));
  sigma[bias_depth_offset] = std::sqrt(uniform_variance(model.depth_absolute, f));
  return sigma;
}

std::vector<MarkSample> mark_samples(const Mission& m) {
  if (m.size() == 0) return {};  // no sample to take (step_at() needs one)
  std::vector<MarkSample> samples;
  samples.reserve(m.mark_count());
  for (std::size_t j = 0; j < m.mark_count(); ++j) {
    const std::size_t k = step_at(m, m.mark_time[j]);
    samples.push_back({m.roll[k], m.pitch[k], m.heading[k], m.altitude[k]});
  }
  return samples;
}

std::size_t step_at(const Mission& m, double time) {
  const auto it = std::lower_bound(m.time.begin(), m.time.end(), time);
  return static_cast<std::size_t>(std::min<std::ptrdiff_t>(it - m.time.begin(), static_cast<std::ptrdiff_t>(m.size()) - 1));
}

void linearise_measurements(const Mission& m, const SensorModel& model, std::span<const PositionFix> fixes,
                            const MeasurementOptions& o, KalmanLinearisation& lin, MeasurementSink& sink) {
  const std::size_t n = m.size();
  const double f = o.noise_factor;
  const double heading_bias = o.biases ? lin.bias[bias_heading] : 0.0;
  // The velocity reading corrected by the DVL biases at the linearisation point.
  const auto velocity = [&](std::size_t k) {
    Vec3d v(m.vx[k], m.vy[k], m.vz[k]);
    if (o.biases)
      for (int c = 0; c < 3; ++c) v[c] -= lin.bias[bias_dvl_scale_x + c] * v[c] + lin.bias[bias_dvl_offset_x + c];
    return v;
  };
  // Odometry: p(k+1) - p(k) = dt (R_k v_k + R_{k+1} v_{k+1}) / 2, DVL noise per axis.
  // Each sample's rotation is computed once: the next step's r0 is this step's r1.
  const bool odometry = o.factors != FactorSet::without_odometry;
  SampleRotations rotations(m, heading_bias);
  Mat3d r1 = n > 0 && odometry ? rotations.at(0) : Mat3d::Identity();
  BiasJacobian jacobian = BiasJacobian::Zero();
  for (std::size_t k = 0; k + 1 < n && odometry; ++k) {
    const double dt = m.time[k + 1] - m.time[k];
    const Mat3d r0 = r1;
    r1 = rotations.at(k + 1);
    const Vec3d delta = 0.5 * dt * (r0 * velocity(k) + r1 * velocity(k + 1));
    Vec3d var_body;
    for (int c = 0; c < 3; ++c) {
      const double v = c == 0 ? m.vx[k] : (c == 1 ? m.vy[k] : m.vz[k]);
      var_body[c] = uniform_variance(model.dvl_relative * std::fabs(v) + model.dvl_absolute, f);
    }
    const Mat3d cov = dt * dt * r0 * var_body.asDiagonal() * r0.transpose() + 1e-12 * Mat3d::Identity();
    if (o.biases) {
      // true heading = reading - bias, true speed = reading - s reading - offset.
      jacobian.col(bias_heading) = -heading_derivative(delta);
      const Vec3d v0(m.vx[k], m.vy[k], m.vz[k]), v1(m.vx[k + 1], m.vy[k + 1], m.vz[k + 1]);
      for (int c = 0; c < 3; ++c) {
        jacobian.col(bias_dvl_scale_x + c) = -0.5 * dt * (r0.col(c) * v0[c] + r1.col(c) * v1[c]);
        jacobian.col(bias_dvl_offset_x + c) = -0.5 * dt * (r0.col(c) + r1.col(c));
      }
    }
    sink.odometry(k, cov.inverse(), delta, jacobian);
  }
  if (o.factors == FactorSet::odometry) return;
  const Eigen::RowVector3d ex(1.0, 0.0, 0.0), ey(0.0, 1.0, 0.0), ez(0.0, 0.0, 1.0), none = Eigen::RowVector3d::Zero();
  // Depth at every step. The bound grows with the depth: evaluated at the reading it
  // would weigh readings that erred deep less than those that erred shallow (a 0.3 m
  // bias on the reference mission), so it is evaluated at the current estimate instead.
  // With biases the reading is d (1 + s) + o, linearised at (d_lin, s_lin):
  // reading + d_lin s_lin = (1 + s_lin) d + d_lin s + o.
  const double depth_scale = o.biases ? lin.bias[bias_depth_scale] : 0.0;
  BiasRow depth_row = BiasRow::Zero();
  if (o.biases) depth_row[bias_depth_offset] = 1.0;
  for (std::size_t k = 0; k < n; ++k) {
    const double d = lin.position[k][2];
    const double var = depth_variance(model, d, f);
    if (o.biases) depth_row[bias_depth_scale] = d;
    sink.scalar(k, (1.0 + depth_scale) * ez, -1, none, depth_row, m.depth[k] + d * depth_scale, 1.0 / var, nullptr);
  }
  for (const PositionFix& fix : fixes) {
    const std::size_t k = step_at(m, fix.time);
    const ConstraintRef source = ConstraintRef::gps_fix(fix.source_index);
    sink.scalar(k, ex, -1, none, BiasRow::Zero(), fix.box[0].mid(), 1.0 / uniform_variance(fix.box[0].rad(), f), &source);
    sink.scalar(k, ey, -1, none, BiasRow::Zero(), fix.box[1].mid(), 1.0 / uniform_variance(fix.box[1].rad(), f), &source);
  }
  // Detections.
  const double var_range = uniform_variance(model.mark_range, f);
  const double var_along = uniform_variance(model.along_track_tolerance, f);
  const double var_mine_depth = f * (model.altitude * model.altitude + model.mine_depth_band * model.mine_depth_band) / 3.0;
  const std::vector<MarkSample> read_here = o.marks.empty() ? mark_samples(m) : std::vector<MarkSample>();
  const std::span<const MarkSample> marks = o.marks.empty() ? std::span<const MarkSample>(read_here) : o.marks;
  if (marks.size() != m.mark_count())
    throw std::invalid_argument("linearise_measurements: one kept sample per mark is needed (mark_samples())");
  for (std::size_t j = 0; j < m.mark_count(); ++j) {
    const int i = m.mark_mine[j];
    if (i < 0) continue;  // the smoother needs the association
    const std::size_t k = step_at(m, m.mark_time[j]);
    const MarkSample& sample = marks[j];
    const Mat3d r = rotation(sample.roll, sample.pitch, sample.heading, heading_bias);
    const auto mi = static_cast<std::size_t>(i);
    if (!lin.mine_known[mi]) {
      const double h = sample.altitude;
      const double across = std::sqrt(std::max(m.mark_range[j] * m.mark_range[j] - h * h, 0.0));
      const Vec3d mine_body(0.0, m.mark_side[j] > 0 ? across : -across, h);
      lin.mine[mi] = lin.position[k] + r * mine_body;
      lin.mine_known[mi] = 1;
    }
    const ConstraintRef source = ConstraintRef::mark(j);
    // Range: |p - m| = r, linearised: u . p - u . m = r (u the unit vector at the point).
    const Vec3d e = lin.position[k] - lin.mine[mi];
    const Vec3d u = e / std::max(e.norm(), 1e-6);
    sink.scalar(k, u.transpose(), i, -u.transpose(), BiasRow::Zero(), m.mark_range[j], 1.0 / var_range, &source);
    // Sonar plane: i_r . (p - m) = 0, i_r turning with the heading bias.
    const Vec3d ir = r.col(0);
    BiasRow plane_bias = BiasRow::Zero();
    if (o.biases) plane_bias[bias_heading] = -heading_derivative(ir).dot(e);
    sink.scalar(k, ir.transpose(), i, -ir.transpose(), plane_bias, plane_bias[bias_heading] * heading_bias,
                1.0 / var_along, &source);
    // Mine depth: m_z - p_z = altitude + s.
    sink.scalar(k, -ez, i, ez, BiasRow::Zero(), sample.altitude, 1.0 / var_mine_depth, &source);
  }
}

}  // namespace gesmi
