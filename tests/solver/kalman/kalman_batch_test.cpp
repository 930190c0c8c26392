// The Kalman smoother against an independent batch solve of the same model: the whole
// nonlinear least-squares problem over every position and every detected mine, written
// here from the model's description (kalman_smoother.h, docs/comparison.md "The
// smoother") as a whitened residual vector and its Jacobian, solved by Gauss-Newton
// with a dense normal matrix and a dense Cholesky factorisation. The smoother's
// information-form chain and this solve share nothing but the mission, so once both
// have converged their means and covariances must agree.
//
// The mission is a 390 s window of a simulated survey at 1 Hz (about 1200 unknowns),
// with two GPS fixes and four marks of two mines, each seen on two legs.

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "solver/kalman/kalman_smoother.h"
#include "solver/sim/simulator.h"

namespace gesmi {
namespace {

using Index = Eigen::Index;
using Row3 = Eigen::RowVector3d;

// The samples of `m` in [t0, t1] with their marks and truth, and no GPS.
Mission window(const Mission& m, double t0, double t1) {
  Mission w;
  w.model = m.model;
  w.mine_count = m.mine_count;
  w.truth_mines = m.truth_mines;
  for (std::size_t k = 0; k < m.size(); ++k) {
    if (m.time[k] < t0 || m.time[k] > t1) continue;
    w.time.push_back(m.time[k]);
    w.roll.push_back(m.roll[k]);
    w.pitch.push_back(m.pitch[k]);
    w.heading.push_back(m.heading[k]);
    w.vx.push_back(m.vx[k]);
    w.vy.push_back(m.vy[k]);
    w.vz.push_back(m.vz[k]);
    w.altitude.push_back(m.altitude[k]);
    w.depth.push_back(m.depth[k]);
    w.truth_x.push_back(m.truth_x[k]);
    w.truth_y.push_back(m.truth_y[k]);
    w.truth_z.push_back(m.truth_z[k]);
  }
  for (std::size_t j = 0; j < m.mark_count(); ++j) {
    if (m.mark_time[j] < w.time.front() || m.mark_time[j] > w.time.back()) continue;
    w.mark_time.push_back(m.mark_time[j]);
    w.mark_mine.push_back(m.mark_mine[j]);
    w.mark_range.push_back(m.mark_range[j]);
    w.mark_side.push_back(m.mark_side[j]);
    w.truth_marks_outlier.push_back(m.truth_marks_outlier[j]);
    w.truth_marks_mine.push_back(m.truth_marks_mine[j]);
  }
  return w;
}

// The sample a time belongs to: the first at or after it (the last one past the end).
std::size_t sample_at(const Mission& m, double t) {
  const auto it = std::lower_bound(m.time.begin(), m.time.end(), t);
  return std::min(static_cast<std::size_t>(it - m.time.begin()), m.size() - 1);
}

// A GPS fix at time t (between samples is allowed): the true position of its sample
// plus errors given as fractions of the model's metric bound.
void add_fix(Mission& m, double t, double north_fraction, double east_fraction) {
  const std::size_t k = sample_at(m, t);
  const double b = m.model.gps_metres;
  m.gps_time.push_back(t);
  m.gps_north.push_back(m.truth_x[k] + north_fraction * b);
  m.gps_east.push_back(m.truth_y[k] + east_fraction * b);
  m.gps_north_halfwidth.push_back(b);
  m.gps_east_halfwidth.push_back(b);
  m.truth_gps_outlier.push_back(0);
}

// R = Rz(heading) Ry(pitch) Rx(roll): body (x forward, y starboard, z down) to NED.
Mat3d body_to_ned(const Mission& m, std::size_t k) {
  return (Eigen::AngleAxisd(m.heading[k], Vec3d::UnitZ()) * Eigen::AngleAxisd(m.pitch[k], Vec3d::UnitY()) *
          Eigen::AngleAxisd(m.roll[k], Vec3d::UnitX()))
      .toRotationMatrix();
}

// Whitened residuals r = (h(x) - z) / sigma and their Jacobian dr/dx, row by row.
class Rows {
 public:
  void add(double residual, double sigma, std::initializer_list<std::pair<Index, Row3>> blocks) {
    const auto row = static_cast<Index>(r_.size());
    r_.push_back(residual / sigma);
    for (const auto& [column, d] : blocks)
      for (int c = 0; c < 3; ++c)
        if (d[c] != 0.0) jacobian_.emplace_back(row, column + c, d[c] / sigma);
  }
  Eigen::VectorXd residuals() const { return Eigen::Map<const Eigen::VectorXd>(r_.data(), static_cast<Index>(r_.size())); }
  Eigen::SparseMatrix<double> jacobian(Index unknowns) const {
    Eigen::SparseMatrix<double> j(static_cast<Index>(r_.size()), unknowns);
    j.setFromTriplets(jacobian_.begin(), jacobian_.end());
    return j;
  }

 private:
  std::vector<double> r_;
  std::vector<Eigen::Triplet<double>> jacobian_;
};

// The batch problem: unknowns x = (p_0 .. p_{n-1}, the detected mines), 3 each.
class Batch {
 public:
  // `variance_scale` multiplies every variance but the priors' (1: the model itself).
  Batch(const Mission& m, std::span<const PositionFix> fixes, double variance_scale = 1.0)
      : m_(m), fixes_(fixes), f_(variance_scale), slot_(static_cast<std::size_t>(m.mine_count), -1) {
    for (std::size_t j = 0; j < m.mark_count(); ++j) {
      const int i = m.mark_mine[j];
      if (i >= 0 && slot_[static_cast<std::size_t>(i)] < 0) slot_[static_cast<std::size_t>(i)] = detected_++;
    }
  }
  std::size_t n() const { return m_.size(); }
  Index unknowns() const { return static_cast<Index>(3 * n()) + 3 * detected_; }
  Index p(std::size_t k) const { return static_cast<Index>(3 * k); }
  // Column of mine i, or -1 when no mark names it.
  Index mine(int i) const {
    const int s = slot_[static_cast<std::size_t>(i)];
    return s < 0 ? -1 : static_cast<Index>(3 * n()) + 3 * s;
  }

  // A bound b read as a uniform law on [-b, b]: standard deviation b / sqrt(3), scaled.
  double sigma(double bound) const { return std::sqrt(f_ / 3.0) * bound; }

  // Trapezoid odometry between samples k and k + 1.
  Vec3d delta(std::size_t k) const {
    const double dt = m_.time[k + 1] - m_.time[k];
    return 0.5 * dt *
           (body_to_ned(m_, k) * Vec3d(m_.vx[k], m_.vy[k], m_.vz[k]) +
            body_to_ned(m_, k + 1) * Vec3d(m_.vx[k + 1], m_.vy[k + 1], m_.vz[k + 1]));
  }

  // Start: dead reckoning through the first fix (at its own sample, unlike the
  // smoother, which puts p_0 there), each mine placed at its first mark by the sonar
  // geometry: in the sonar plane, on the marked side, the altitude below the robot.
  Eigen::VectorXd start() const {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(unknowns());
    const std::size_t a = fixes_.empty() ? 0 : sample_at(m_, fixes_[0].time);
    x.segment<3>(p(a)) = Vec3d(fixes_.empty() ? 0.0 : fixes_[0].box[0].mid(), fixes_.empty() ? 0.0 : fixes_[0].box[1].mid(), m_.depth[a]);
    for (std::size_t k = a; k + 1 < n(); ++k) x.segment<3>(p(k + 1)) = x.segment<3>(p(k)) + delta(k);
    for (std::size_t k = a; k > 0; --k) x.segment<3>(p(k - 1)) = x.segment<3>(p(k)) - delta(k - 1);
    std::vector<char> placed(slot_.size(), 0);
    for (std::size_t j = 0; j < m_.mark_count(); ++j) {
      const int i = m_.mark_mine[j];
      if (i < 0 || placed[static_cast<std::size_t>(i)]) continue;
      placed[static_cast<std::size_t>(i)] = 1;
      const std::size_t k = sample_at(m_, m_.mark_time[j]);
      const double h = m_.altitude[k], r = m_.mark_range[j];
      const double across = std::sqrt(std::max(r * r - h * h, 0.0)) * (m_.mark_side[j] > 0 ? 1.0 : -1.0);
      x.segment<3>(mine(i)) = x.segment<3>(p(k)) + body_to_ned(m_, k) * Vec3d(0.0, across, h);
    }
    return x;
  }

  // Every residual of the batch problem at x. The depth bound grows with the depth and,
  // as in the smoother, is evaluated at the estimate: here at x, the current
  // linearisation point, so it is refreshed at every Gauss-Newton iteration and held
  // fixed within one (its dependence on x is not differentiated, and the fixed point
  // reached is the smoother's).
  Rows rows(const Eigen::VectorXd& x) const {
    Rows rows;
    const SensorModel& s = m_.model;
    const Row3 ex(1.0, 0.0, 0.0), ey(0.0, 1.0, 0.0), ez(0.0, 0.0, 1.0);
    // Odometry p_{k+1} - p_k = delta_k: each DVL component's bound at its reading of
    // sample k, in the body frame, turned by R_k and scaled by the step; whitened by the
    // inverse Cholesky factor of that covariance (plus the smoother's 1e-12 m^2 floor).
    for (std::size_t k = 0; k + 1 < n(); ++k) {
      const double dt = m_.time[k + 1] - m_.time[k];
      Vec3d var_body;
      const double v[3] = {m_.vx[k], m_.vy[k], m_.vz[k]};
      for (int c = 0; c < 3; ++c) var_body[c] = std::pow(sigma(s.dvl_relative * std::fabs(v[c]) + s.dvl_absolute), 2);
      const Mat3d rk = body_to_ned(m_, k);
      const Mat3d cov = dt * dt * rk * var_body.asDiagonal() * rk.transpose() + 1e-12 * Mat3d::Identity();
      const Mat3d l = cov.llt().matrixL();
      const Mat3d w = l.inverse();  // |w e|^2 = e^T cov^-1 e
      const Vec3d e = w * (x.segment<3>(p(k + 1)) - x.segment<3>(p(k)) - delta(k));
      for (int a = 0; a < 3; ++a) rows.add(e[a], 1.0, {{p(k), -w.row(a)}, {p(k + 1), w.row(a)}});
    }
    // Depth at every sample.
    for (std::size_t k = 0; k < n(); ++k) {
      const double z = x[p(k) + 2];
      rows.add(z - m_.depth[k], sigma(s.depth_absolute + s.depth_relative * std::fabs(z)), {{p(k), ez}});
    }
    // Weak priors toward the origin: information 1e-10 on p_0 (so that a mission
    // without GPS is still determined), 1e-12 on each mine.
    for (int a = 0; a < 3; ++a) rows.add(x[p(0) + a], 1.0 / std::sqrt(1e-10), {{p(0), Row3::Unit(a)}});
    for (int i = 0; i < m_.mine_count; ++i)
      if (mine(i) >= 0)
        for (int a = 0; a < 3; ++a) rows.add(x[mine(i) + a], 1.0 / std::sqrt(1e-12), {{mine(i), Row3::Unit(a)}});
    // GPS: north and east at the fix's sample, the box's half-widths as bounds.
    for (const PositionFix& fix : fixes_) {
      const std::size_t k = sample_at(m_, fix.time);
      rows.add(x[p(k)] - fix.box[0].mid(), sigma(fix.box[0].rad()), {{p(k), ex}});
      rows.add(x[p(k) + 1] - fix.box[1].mid(), sigma(fix.box[1].rad()), {{p(k), ey}});
    }
    // Marks: the slant range |p - m|, the sonar plane i_r . (p - m) = 0 (i_r the body's
    // forward axis) and the mine's depth m_z - p_z = altitude, whose error combines the
    // altitude's bound and the sea floor band.
    for (std::size_t j = 0; j < m_.mark_count(); ++j) {
      const int i = m_.mark_mine[j];
      if (i < 0) continue;
      const std::size_t k = sample_at(m_, m_.mark_time[j]);
      const Vec3d e = x.segment<3>(p(k)) - x.segment<3>(mine(i));
      const Row3 u = e.normalized().transpose();
      rows.add(e.norm() - m_.mark_range[j], sigma(s.mark_range), {{p(k), u}, {mine(i), -u}});
      const Row3 ir = body_to_ned(m_, k).col(0).transpose();
      rows.add(ir.dot(e), sigma(s.along_track_tolerance), {{p(k), ir}, {mine(i), -ir}});
      const double sd = std::sqrt(f_ * (s.altitude * s.altitude + s.mine_depth_band * s.mine_depth_band) / 3.0);
      rows.add(x[mine(i) + 2] - x[p(k) + 2] - m_.altitude[k], sd, {{p(k), -ez}, {mine(i), ez}});
    }
    return rows;
  }

  // J^T J at x, dense (the information matrix of the linearised problem).
  Eigen::MatrixXd normal_matrix(const Rows& r) const {
    const Eigen::SparseMatrix<double> j = r.jacobian(unknowns());
    return Eigen::MatrixXd(Eigen::SparseMatrix<double>(j.transpose() * j));
  }

 private:
  const Mission& m_;
  std::span<const PositionFix> fixes_;
  double f_;
  std::vector<int> slot_;
  int detected_ = 0;
};

struct BatchSolution {
  Eigen::VectorXd x;
  Eigen::MatrixXd covariance;
  int iterations = 0;
  double last_step = 0.0;
};

// Gauss-Newton on the whole problem until no coordinate moves 1e-7 m (at most 50).
BatchSolution gauss_newton(const Batch& b) {
  BatchSolution s;
  s.x = b.start();
  s.last_step = std::numeric_limits<double>::infinity();
  while (s.iterations < 50 && s.last_step >= 1e-7) {
    const Rows r = b.rows(s.x);
    const Eigen::LLT<Eigen::MatrixXd> llt(b.normal_matrix(r));
    EXPECT_EQ(llt.info(), Eigen::Success);
    const Eigen::VectorXd step = -llt.solve(r.jacobian(b.unknowns()).transpose() * r.residuals());
    s.x += step;
    s.last_step = step.cwiseAbs().maxCoeff();
    ++s.iterations;
  }
  // The covariance: the inverse of the information at the solution.
  const Eigen::LLT<Eigen::MatrixXd> llt(b.normal_matrix(b.rows(s.x)));
  s.covariance = llt.solve(Eigen::MatrixXd::Identity(b.unknowns(), b.unknowns()));
  return s;
}

// Largest differences of the smoother from the batch solve: means (m), covariance
// diagonals (relative) and off-diagonals (relative to sqrt(c_aa c_bb), a correlation).
struct Differences {
  double mean = 0.0, variance = 0.0, correlation = 0.0;
  double chi2 = 0.0;  // relative difference of the fit's chi-square
  double dof = 0.0;   // difference of its degrees of freedom
  void covariance(const double* smoother, const Eigen::MatrixXd& batch, Index at) {
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c) {
        const double expected = batch(at + a, at + c), got = smoother[3 * a + c];
        if (a == c)
          variance = std::max(variance, std::fabs(got - expected) / expected);
        else
          correlation = std::max(correlation, std::fabs(got - expected) / std::sqrt(batch(at + a, at + a) * batch(at + c, at + c)));
      }
  }
};

Differences compare(SimulatedErrors errors) {
  SimulationOptions o;
  o.seed = 1;
  o.errors = errors;
  o.rate = 1.0;
  o.mines = 10;
  // Marks of mines 7 and 4 at 3936, 3972, 4206 and 4310 s.
  Mission m = window(simulate_mission(o), 3925.0, 4315.0);
  const bool worst = errors == SimulatedErrors::worst_case;
  add_fix(m, 3975.4, worst ? 0.99 : 0.6, worst ? -0.99 : -0.3);  // between samples: the next one
  add_fix(m, 4290.0, worst ? -0.99 : 0.2, worst ? 0.99 : 0.7);
  const std::vector<PositionFix> fixes = gps_fixes(m);

  const KalmanOptions ko;  // the defaults: 1 mm tolerance, variances as the bounds say
  const Batch batch(m, fixes, ko.noise_factor);
  // Several marks of two mines (compared below), a dense problem of modest size.
  EXPECT_GE(m.mark_count(), 4u);
  EXPECT_EQ(batch.unknowns(), static_cast<Index>(3 * m.size() + 6));
  EXPECT_LE(batch.unknowns(), 2000);

  const KalmanResult smoothed = kalman_smooth(m, m.model, fixes, ko);
  EXPECT_TRUE(smoothed.converged) << "last step " << smoothed.last_step;
  const BatchSolution solved = gauss_newton(batch);
  EXPECT_LT(solved.last_step, 1e-7) << "Gauss-Newton did not converge in " << solved.iterations;

  Differences d;
  for (std::size_t k = 0; k < m.size(); ++k) {
    for (int a = 0; a < 3; ++a)
      d.mean = std::max(d.mean, std::fabs(smoothed.mean[3 * k + static_cast<std::size_t>(a)] - solved.x[batch.p(k) + a]));
    d.covariance(&smoothed.covariance[9 * k], solved.covariance, batch.p(k));
  }
  int compared_mines = 0;
  for (int i = 0; i < m.mine_count; ++i) {
    const auto u = static_cast<std::size_t>(i);
    if (batch.mine(i) < 0) {
      EXPECT_TRUE(std::isnan(smoothed.mine_mean[3 * u])) << "mine " << i << " was never detected";
      continue;
    }
    ++compared_mines;
    for (int a = 0; a < 3; ++a)
      d.mean = std::max(d.mean, std::fabs(smoothed.mine_mean[3 * u + static_cast<std::size_t>(a)] - solved.x[batch.mine(i) + a]));
    d.covariance(&smoothed.mine_covariance[9 * u], solved.covariance, batch.mine(i));
  }
  EXPECT_EQ(compared_mines, 2);
  // The fit's chi-square: the squared whitened residuals at the solution but the weak
  // priors' (3 on p_0 and 3 per mine, after the odometry and depth rows), and its
  // degrees of freedom, rows minus unknowns.
  const Eigen::VectorXd residuals = batch.rows(solved.x).residuals();
  const Index priors_at = static_cast<Index>(4 * m.size() - 3), prior_rows = 3 + 3 * compared_mines;
  const double chi2 = residuals.squaredNorm() - residuals.segment(priors_at, prior_rows).squaredNorm();
  const double dof = static_cast<double>(residuals.size() - prior_rows - batch.unknowns());
  d.chi2 = std::fabs(smoothed.consistency.chi2 - chi2) / chi2;
  d.dof = std::fabs(smoothed.consistency.dof - dof);
  std::printf("[ report ] chi2 %.6g on %.0f dof (batch), %.6g on %.0f (smoother)\n", chi2, dof,
              smoothed.consistency.chi2, smoothed.consistency.dof);
  std::printf("[ report ] %s errors, %zu steps, %zu marks: smoother %d linearisations (last step %.2g m), "
              "Gauss-Newton %d (last step %.2g m); largest differences: mean %.3g m, variance %.3g relative, "
              "correlation %.3g\n",
              simulated_errors_name(errors), m.size(), m.mark_count(), smoothed.iterations, smoothed.last_step,
              solved.iterations, solved.last_step, d.mean, d.variance, d.correlation);
  return d;
}

// Means within 1 mm, variances within 1e-3 relative, covariances between two axes of
// one position or mine within 1e-3 of sqrt(c_aa c_bb); the chi-square within 1e-4
// relative (the smoother's is that of its last linearisation) on the same degrees of
// freedom.
void expect_agreement(const Differences& d) {
  EXPECT_LE(d.mean, 1e-3);
  EXPECT_LE(d.variance, 1e-3);
  EXPECT_LE(d.correlation, 1e-3);
  EXPECT_LE(d.chi2, 1e-4);
  EXPECT_EQ(d.dof, 0.0);
}

TEST(KalmanBatch, MatchesAGaussNewtonBatchSolveWithUniformErrors) { expect_agreement(compare(SimulatedErrors::uniform)); }

TEST(KalmanBatch, MatchesAGaussNewtonBatchSolveWithWorstCaseErrors) {
  expect_agreement(compare(SimulatedErrors::worst_case));
}

}  // namespace
}  // namespace gesmi
