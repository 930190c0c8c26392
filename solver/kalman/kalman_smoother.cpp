#include "solver/kalman/kalman_smoother.h"

#include <Eigen/LU>
#include <cmath>
#include <limits>

#include "solver/kalman/arrowhead_chain.h"
#include "solver/model/euler.h"

namespace gesmi {
namespace {


// Variance of a uniform law on [-bound, bound], scaled.
double variance(double bound, double factor) { return factor * bound * bound / 3.0; }

Mat3d rotation(const Mission& m, std::size_t k) {
  const Attitude<double> a = make_attitude(m.roll[k], m.pitch[k], m.heading[k]);
  Mat3d r;
  for (int c = 0; c < 3; ++c) r.col(c) = body_to_world(a, Vec3d(Vec3d::Unit(c)));
  return r;
}

struct Linearisation {
  std::vector<Vec3d> position;  // per step
  std::vector<Vec3d> mine;      // per mine index
  std::vector<char> mine_known;
};

// Builds and solves the linearised system; `lin` gives the linearisation points of
// the range measurements (the first pass initialises the mines along the way).
void build_and_solve(const Mission& m, const SensorModel& model, std::span<const PositionFix> fixes,
                     const KalmanOptions& o, Linearisation& lin, ArrowheadChain& chain) {
  const std::size_t n = m.size(), q = 3 * static_cast<std::size_t>(m.mine_count);
  chain.reset();
  const double f = o.noise_factor;
  // Odometry: p(k+1) - p(k) = dt (R_k v_k + R_{k+1} v_{k+1}) / 2, DVL noise per axis.
  // Each sample's rotation is computed once: the next step's r0 is this step's r1.
  Mat3d r1 = n > 0 ? rotation(m, 0) : Mat3d::Identity();
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const double dt = m.time[k + 1] - m.time[k];
    const Mat3d r0 = r1;
    r1 = rotation(m, k + 1);
    const Vec3d v0(m.vx[k], m.vy[k], m.vz[k]), v1(m.vx[k + 1], m.vy[k + 1], m.vz[k + 1]);
    const Vec3d delta = 0.5 * dt * (r0 * v0 + r1 * v1);
    Vec3d var_body;
    for (int c = 0; c < 3; ++c) {
      const double v = c == 0 ? m.vx[k] : (c == 1 ? m.vy[k] : m.vz[k]);
      var_body[c] = variance(model.dvl_relative * std::fabs(v) + model.dvl_absolute, f);
    }
    const Mat3d cov = dt * dt * r0 * var_body.asDiagonal() * r0.transpose() + 1e-12 * Mat3d::Identity();
    chain.add_step(k, cov.inverse(), delta);
  }
  // Depth at every step; a weak horizontal prior on the first position (GPS may be absent).
  // The bound grows with the depth: evaluated at the reading it would weigh readings
  // that erred deep less than those that erred shallow (a 0.3 m bias on the reference
  // mission), so it is evaluated at the current estimate instead.
  for (std::size_t k = 0; k < n; ++k) {
    const double var = variance(model.depth_absolute + model.depth_relative * std::fabs(lin.position[k][2]), f);
    Mat3d info = Mat3d::Zero();
    info(2, 2) = 1.0 / var;
    chain.add_position(k, info, Vec3d(0.0, 0.0, m.depth[k]));
  }
  chain.add_position(0, Mat3d::Identity() * 1e-10, Vec3d::Zero());
  for (const PositionFix& fix : fixes) {
    const auto it = std::lower_bound(m.time.begin(), m.time.end(), fix.time);
    const auto k = static_cast<std::size_t>(std::min<std::ptrdiff_t>(it - m.time.begin(), static_cast<std::ptrdiff_t>(n) - 1));
    Mat3d info = Mat3d::Zero();
    info(0, 0) = 1.0 / variance(fix.box[0].rad(), f);
    info(1, 1) = 1.0 / variance(fix.box[1].rad(), f);
    chain.add_position(k, info, Vec3d(fix.box[0].mid(), fix.box[1].mid(), 0.0));
  }
  // Detections.
  const double var_range = variance(model.mark_range, f);
  const double var_along = variance(model.along_track_tolerance, f);
  for (std::size_t j = 0; j < m.mark_count(); ++j) {
    const int i = m.mark_mine[j];
    if (i < 0) continue;  // the smoother needs the association
    const auto it = std::lower_bound(m.time.begin(), m.time.end(), m.mark_time[j]);
    const auto k = static_cast<std::size_t>(std::min<std::ptrdiff_t>(it - m.time.begin(), static_cast<std::ptrdiff_t>(n) - 1));
    const Mat3d r = rotation(m, k);
    const auto mi = static_cast<std::size_t>(i);
    if (!lin.mine_known[mi]) {
      // First detection: the mine in the sonar plane, on the declared side, below the
      // robot by the altitude, at the measured range.
      const double h = m.altitude[k];
      const double across = std::sqrt(std::max(m.mark_range[j] * m.mark_range[j] - h * h, 0.0));
      const Vec3d mine_body(0.0, m.mark_side[j] > 0 ? across : -across, h);
      lin.mine[mi] = lin.position[k] + r * mine_body;
      lin.mine_known[mi] = 1;
    }
    const auto col = static_cast<Eigen::Index>(3 * mi);
    Eigen::RowVectorXd hm = Eigen::RowVectorXd::Zero(static_cast<Eigen::Index>(q));
    // Range: |p - m| = r, linearised: u . p - u . m = r (u the unit vector at the point).
    const Vec3d e = lin.position[k] - lin.mine[mi];
    const double rho = std::max(e.norm(), 1e-6);
    const Vec3d u = e / rho;
    hm.segment<3>(col) = -u.transpose();
    chain.add_mixed(k, u.transpose(), hm, m.mark_range[j], 1.0 / var_range);
    // Sonar plane: i_r . (p - m) = 0.
    const Vec3d ir = r.col(0);
    hm.segment<3>(col) = -ir.transpose();
    chain.add_mixed(k, ir.transpose(), hm, 0.0, 1.0 / var_along);
    // Mine depth: m_z - p_z = altitude + s.
    hm.setZero();
    hm(col + 2) = 1.0;
    const double var_depth = f * (model.altitude * model.altitude + model.mine_depth_band * model.mine_depth_band) / 3.0;
    chain.add_mixed(k, Eigen::RowVector3d(0.0, 0.0, -1.0), hm, m.altitude[k], 1.0 / var_depth);
  }
  chain.solve();
}

}  // namespace

std::string KalmanOptions::validate() const {
  if (!(noise_factor > 0.0) || !std::isfinite(noise_factor)) return "the noise factor must be a positive number";
  if (max_iterations < 1 || max_iterations > 100) return "the iteration cap must be between 1 and 100";
  if (!(tolerance >= 0.0) || !std::isfinite(tolerance)) return "the tolerance must be a finite number >= 0";
  return {};
}

KalmanResult kalman_smooth(const Mission& m, const SensorModel& model, std::span<const PositionFix> fixes,
                           const KalmanOptions& o) {
  const std::size_t n = m.size(), k_mines = static_cast<std::size_t>(m.mine_count);
  // First linearisation: dead reckoning from the first fix (or the origin).
  Linearisation lin;
  lin.position.assign(n, Vec3d::Zero());
  Vec3d p = fixes.empty() ? Vec3d(0.0, 0.0, m.depth[0]) : Vec3d(fixes[0].box[0].mid(), fixes[0].box[1].mid(), m.depth[0]);
  // (this dead reckoning is the first linearisation point; its depths set the depth
  // variances of the first pass, independently of each reading's error)
  lin.position[0] = p;
  Mat3d r1 = n > 0 ? rotation(m, 0) : Mat3d::Identity();  // each sample's rotation once
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const double dt = m.time[k + 1] - m.time[k];
    const Mat3d r0 = r1;
    r1 = rotation(m, k + 1);
    p += 0.5 * dt * (r0 * Vec3d(m.vx[k], m.vy[k], m.vz[k]) + r1 * Vec3d(m.vx[k + 1], m.vy[k + 1], m.vz[k + 1]));
    lin.position[k + 1] = p;
  }
  lin.mine.assign(k_mines, Vec3d::Zero());
  lin.mine_known.assign(k_mines, 0);

  KalmanResult result;
  result.steps = n;
  result.mines = k_mines;
  if (o.max_iterations < 1) return result;  // nothing solved (validate() refuses such options)
  ArrowheadChain chain(n, 3 * k_mines);  // one set of buffers for every linearisation
  for (int it = 0; it < o.max_iterations; ++it) {
    build_and_solve(m, model, fixes, o, lin, chain);
    ++result.iterations;
    // The step: how far the new estimate moved any coordinate from the linearisation
    // point (for a mine first placed in this pass, from where it was placed).
    double step = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      step = std::max(step, (chain.mean(k) - lin.position[k]).cwiseAbs().maxCoeff());
      lin.position[k] = chain.mean(k);
    }
    for (std::size_t i = 0; i < k_mines; ++i) {
      if (!lin.mine_known[i]) continue;
      const Vec3d mine = chain.static_mean().segment<3>(static_cast<Eigen::Index>(3 * i));
      step = std::max(step, (mine - lin.mine[i]).cwiseAbs().maxCoeff());
      lin.mine[i] = mine;
    }
    result.last_step = step;
    result.converged = step <= o.tolerance;
    if (result.converged) break;
  }
  chain.release_workspace();  // before the result's arrays: the peak stays that of a solve
  result.mean.resize(3 * n);
  result.covariance.resize(9 * n);
  for (std::size_t k = 0; k < n; ++k) {
    for (int r = 0; r < 3; ++r) {
      result.mean[3 * k + static_cast<std::size_t>(r)] = chain.mean(k)[r];
      for (int c = 0; c < 3; ++c) result.covariance[9 * k + static_cast<std::size_t>(3 * r + c)] = chain.covariance(k)(r, c);
    }
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  result.mine_mean.assign(3 * k_mines, nan);
  result.mine_covariance.assign(9 * k_mines, nan);
  for (std::size_t i = 0; i < k_mines; ++i) {
    if (!lin.mine_known[i]) continue;
    const auto b = static_cast<Eigen::Index>(3 * i);
    for (int r = 0; r < 3; ++r) {
      result.mine_mean[3 * i + static_cast<std::size_t>(r)] = chain.static_mean()[b + r];
      for (int c = 0; c < 3; ++c)
        result.mine_covariance[9 * i + static_cast<std::size_t>(3 * r + c)] = chain.static_covariance()(b + r, b + c);
    }
  }
  return result;
}

Containment three_sigma_containment(const KalmanResult& r, const Mission& m) {
  Containment c;
  if (!m.has_truth()) return {std::nan(""), std::nan("")};
  std::size_t inside = 0;
  const double* truth[3] = {m.truth_x.data(), m.truth_y.data(), m.truth_z.data()};
  for (std::size_t k = 0; k < r.steps; ++k) {
    bool in = true;
    for (std::size_t a = 0; a < 3; ++a)
      in = in && std::fabs(truth[a][k] - r.mean[3 * k + a]) <= 3.0 * std::sqrt(r.covariance[9 * k + 4 * a]);
    inside += in;
  }
  c.trajectory = static_cast<double>(inside) / static_cast<double>(r.steps);
  std::size_t mines_inside = 0, mines_seen = 0;
  for (std::size_t i = 0; i < r.mines && 3 * i + 2 < m.truth_mines.size(); ++i) {
    if (std::isnan(r.mine_mean[3 * i])) continue;
    ++mines_seen;
    bool in = true;
    for (std::size_t a = 0; a < 3; ++a)
      in = in && std::fabs(m.truth_mines[3 * i + a] - r.mine_mean[3 * i + a]) <= 3.0 * std::sqrt(r.mine_covariance[9 * i + 4 * a]);
    mines_inside += in;
  }
  c.mines = mines_seen ? static_cast<double>(mines_inside) / static_cast<double>(mines_seen) : std::nan("");
  return c;
}

}  // namespace gesmi
