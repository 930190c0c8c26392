#include "solver/kalman/arrowhead_chain.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace gesmi {
namespace {

using Mat3 = ArrowheadChain::Mat3;

// The forward pass's blocks are symmetric (information, its inverse, W S W, T^T S T): each
// is computed from, or as, its upper triangle and mirrored, a third less arithmetic in the
// pass that dominates the smoother, and symmetric bit for bit.

// The inverse of a symmetric block, read from its upper triangle: six cofactors where a
// general inverse takes nine.
Mat3 symmetric_inverse(const Mat3& a) {
  const double c00 = a(1, 1) * a(2, 2) - a(1, 2) * a(1, 2);
  const double c01 = a(0, 2) * a(1, 2) - a(0, 1) * a(2, 2);
  const double c02 = a(0, 1) * a(1, 2) - a(0, 2) * a(1, 1);
  const double c11 = a(0, 0) * a(2, 2) - a(0, 2) * a(0, 2);
  const double c12 = a(0, 1) * a(0, 2) - a(0, 0) * a(1, 2);
  const double c22 = a(0, 0) * a(1, 1) - a(0, 1) * a(0, 1);
  const double inverse_determinant = 1.0 / (a(0, 0) * c00 + a(0, 1) * c01 + a(0, 2) * c02);
  Mat3 s;
  s << c00, c01, c02, c01, c11, c12, c02, c12, c22;
  return s * inverse_determinant;
}

// x y where the product is known to be symmetric: its upper triangle, mirrored.
Mat3 symmetric_product(const Mat3& x, const Mat3& y) {
  Mat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) r(j, i) = r(i, j) = x.row(i).dot(y.col(j));
  return r;
}

}  // namespace

ArrowheadChain::ArrowheadChain(std::size_t n, std::size_t q, double prior_info)
    : n_(n), q_(q), prior_info_(prior_info), diag_(9 * n, 0.0), eta_(n, Vec3::Zero()),
      step_info_(n > 0 ? n - 1 : 0),
      d_(MatX::Identity(static_cast<Eigen::Index>(q), static_cast<Eigen::Index>(q)) * prior_info),
      eta_m_(VecX::Zero(static_cast<Eigen::Index>(q))) {}

ArrowheadChain::ArrowheadChain(std::size_t n, std::size_t q, std::vector<Symmetric3> step_information, double prior_info)
    : n_(n), q_(q), prior_info_(prior_info), diag_(9 * n, 0.0), eta_(n, Vec3::Zero()),
      step_info_(std::move(step_information)),
      d_(MatX::Identity(static_cast<Eigen::Index>(q), static_cast<Eigen::Index>(q)) * prior_info),
      eta_m_(VecX::Zero(static_cast<Eigen::Index>(q))),
      steps_(Steps::kept) {
  if (step_info_.size() != (n > 0 ? n - 1 : 0))
    throw std::invalid_argument("ArrowheadChain: one step information per step (n - 1)");
}

void ArrowheadChain::reset() {
  step_info_.assign(n_ > 0 ? n_ - 1 : 0, Symmetric3{});  // (released after a last solve)
  steps_ = Steps::building;
  clear_factors();
}

void ArrowheadChain::require_steps(const char* caller) const {
  if (steps_ == Steps::released)
    throw std::logic_error(std::string("ArrowheadChain::") + caller + ": the workspace was released; reset() first");
}

void ArrowheadChain::require_factors(const char* caller) const {
  if (stage_ != Stage::factors)
    throw std::logic_error(std::string("ArrowheadChain::") + caller + ": the factors were solved already; reset() first");
  if (steps_ == Steps::kept)
    throw std::logic_error(std::string("ArrowheadChain::") + caller +
                           ": after reset_keeping_steps(), add_steps_again() first (it writes every block)");
}

void ArrowheadChain::release_workspace() {
  std::vector<Symmetric3>().swap(step_info_);
  steps_ = Steps::released;
  release_segments();
}

void ArrowheadChain::release_segments() {
  std::vector<std::size_t>().swap(events_);
  std::vector<Mat3>().swap(coupling_start_);
  std::vector<MatX>().swap(segment_b_);
  std::vector<MatX>().swap(b_sigma_);
  std::vector<Vec3>().swap(bm_);
  std::vector<Mat3>().swap(b_sigma_b_);
}

void ArrowheadChain::reset_keeping_steps() {
  require_steps("reset_keeping_steps");
  steps_ = Steps::kept;
  // The blocks are not zeroed: add_steps_again() writes every one of them, next.
  if (diag_.size() != 9 * n_) diag_.assign(9 * n_, 0.0);  // (after take_covariances())
  clear_static_factors();
}

void ArrowheadChain::clear_factors() {
  diag_.assign(9 * n_, 0.0);  // (also after take_covariances())
  for (Vec3& x : eta_) x.setZero();
  clear_static_factors();
}

void ArrowheadChain::clear_static_factors() {
  mixed_.clear();
  const auto q = static_cast<Eigen::Index>(q_);
  d_ = MatX::Identity(q, q) * prior_info_;
  eta_m_.setZero();
  stage_ = Stage::factors;
}

void ArrowheadChain::add_position(std::size_t k, const Mat3& information, const Vec3& mean) {
  require_factors("add_position");
  diag(k) += information;
  eta_[k] += information * mean;
}

void ArrowheadChain::add_step(std::size_t k, const Mat3& w, const Vec3& delta) {
  if (steps_ != Steps::building)
    throw std::logic_error("ArrowheadChain::add_step: the steps are kept or released; reset() first");
  require_factors("add_step");
  // Read as kept (its upper triangle, mirrored), so that add_steps_again() adds the same.
  const Symmetric3 added = Symmetric3::upper_of(w);
  step_info_[k] = step_info_[k] + added;
  add_step_terms(k, added.full(), delta);
}

void ArrowheadChain::add_step_terms(std::size_t k, const Mat3& w, const Vec3& delta) {
  // Residual p_{k+1} - p_k - delta: blocks (k,k) and (k+1,k+1) get W, (k,k+1) gets -W.
  diag(k) += w;
  diag(k + 1) += w;
  eta_[k] -= w * delta;
  eta_[k + 1] += w * delta;
}

void ArrowheadChain::add_steps_again(std::span<const Vec3> delta, std::span<const double> reference) {
  if (steps_ != Steps::kept || stage_ != Stage::factors)
    throw std::logic_error("ArrowheadChain::add_steps_again: once after reset_keeping_steps()");
  if (delta.size() != step_info_.size()) throw std::invalid_argument("ArrowheadChain::add_steps_again: one delta per step");
  if (reference.size() != 3 * n_)
    throw std::invalid_argument("ArrowheadChain::add_steps_again: one reference (three numbers) per position");
  steps_ = Steps::added_again;
  const auto point = [&](std::size_t k) { return Eigen::Map<const Vec3>(reference.data() + 3 * k); };
  // Each block written once, as add_step_terms() would have accumulated it on zeroed
  // blocks (the same sums in the same order, so the same bits): no pass that zeroes the
  // blocks first, and no second read and write of each. (At 10^7 steps the blocks are
  // 960 MB, zeroed and then read and written twice at every pass before.)
  Mat3 w_before = Mat3::Zero();  // W_{k-1}
  Vec3 pushed = Vec3::Zero();    // W_{k-1} times the step from p_{k-1} to p_k
  for (std::size_t k = 0; k < n_; ++k) {
    Mat3 block = Mat3::Zero();
    Vec3 term = Vec3::Zero();
    if (k > 0) {
      block += w_before;
      term += pushed;
    }
    if (k + 1 < n_) {
      const Mat3 w = step_info_[k].full();
      const Vec3 wd = w * relative_step(delta[k], point(k), point(k + 1));
      block += w;
      term -= wd;
      w_before = w;
      pushed = wd;
    }
    diag(k) = block;
    eta_[k] = term;
  }
}

void ArrowheadChain::add_position_row(std::size_t k, const Row3& hp, double z, double w) {
  require_factors("add_position_row");
  diag(k) += w * hp.transpose() * hp;
  eta_[k] += w * z * hp.transpose();
}

void ArrowheadChain::add_static(std::size_t j, double z, double w) {
  require_factors("add_static");
  const auto i = static_cast<Eigen::Index>(j);
  d_(i, i) += w;
  eta_m_[i] += w * z;
}

void ArrowheadChain::keep_cross_covariance_at(std::vector<std::size_t> steps) {
  cross_at_.clear();
  for (const std::size_t k : steps) cross_at_[k];  // filled by solve()
}

void ArrowheadChain::keep_cross_covariance_columns(std::size_t first, std::size_t count) {
  if (first + count > q_) throw std::invalid_argument("ArrowheadChain: cross covariance columns beyond the static unknowns");
  column_first_ = first;
  column_count_ = count;
  cross_columns_.assign(3 * count * n_, 0.0);
}

void ArrowheadChain::add_mixed(std::size_t k, const Row3& hp, const Eigen::RowVectorXd& hm, double z, double w) {
  require_factors("add_mixed");
  diag(k) += w * hp.transpose() * hp;
  eta_[k] += w * z * hp.transpose();
  MatX& b = mixed_[k];  // created empty at the first mixed factor of step k
  if (b.size() == 0) b = MatX::Zero(3, static_cast<Eigen::Index>(q_));
  b += w * hp.transpose() * hm;
  d_ += w * hm.transpose() * hm;
  eta_m_ += w * z * hm.transpose();
}

// Between two steps that carry mixed factors ("events"), the coupling of p_k to the
// static unknowns evolves as B_k = T_k B_e with T_k a 3x3 matrix and B_e the full
// 3 x q coupling at the last event e. Accumulating T_k^T S_k T_k and T_k^T c_k over a
// segment lets the q x q updates happen once per event instead of once per step, and
// the backward recursions run on 3x3 blocks, so a step costs a few 3x3 products.
void ArrowheadChain::solve() {
  solve_means();
  solve_covariances();
}

// flatten (here, for the forward pass, and on the backward passes): GCC left Eigen's 3x3
// products and copies as calls (a third of the smoother's time in perf); inlined, the
// same operations in the same order (bitwise the same results) take 30 % less.
[[gnu::flatten]] void ArrowheadChain::solve_means() {
  require_steps("solve_means");
  if (steps_ == Steps::kept)
    throw std::logic_error("ArrowheadChain::solve_means: after reset_keeping_steps(), add_steps_again() first");
  if (stage_ != Stage::factors)
    throw std::logic_error("ArrowheadChain::solve_means: the factors were solved already; reset() and add them again");
  stage_ = Stage::means;
  const auto q = static_cast<Eigen::Index>(q_);
  // The steps with a mixed factor, each the start of a segment.
  events_.clear();
  for (const auto& [k, b] : mixed_) events_.push_back(k);
  coupling_start_.assign((n_ + kCouplingBlock - 1) / kCouplingBlock, Mat3::Zero());  // T_k at each block's start
  segment_b_.clear();  // B_e of each segment (3 x q)
  MatX d = d_;
  VecX eta_m = eta_m_;
  Mat3 a = n_ == 0 ? Mat3::Zero() : Mat3(diag(0));
  Vec3 eta = eta_.empty() ? Vec3::Zero() : eta_[0];
  Mat3 t = Mat3::Identity();
  Mat3 acc = Mat3::Zero();
  Vec3 acc_eta = Vec3::Zero();
  const auto close_segment = [&] {
    if (segment_b_.empty()) return;
    const MatX& b = segment_b_.back();
    d.noalias() -= b.transpose() * acc * b;
    eta_m.noalias() -= b.transpose() * acc_eta;
    acc.setZero();
    acc_eta.setZero();
  };
  const auto open_segment = [&](const MatX& mixed, const MatX* carried) {
    MatX b = mixed;
    if (carried) b += t * *carried;
    close_segment();
    segment_b_.push_back(std::move(b));
    t.setIdentity();
  };
  auto next_mixed = mixed_.begin();  // the first step with a mixed factor not yet reached
  const auto mixed_at = [&](std::size_t k) -> const MatX* {
    if (next_mixed == mixed_.end() || next_mixed->first != k) return nullptr;
    return &(next_mixed++)->second;
  };
  if (n_ > 0)
    if (const MatX* b0 = mixed_at(0)) open_segment(*b0, nullptr);
  for (std::size_t k = 0; k < n_; ++k) {
    if (k % kCouplingBlock == 0) coupling_start_[k / kCouplingBlock] = t;
    const Mat3 s_k = symmetric_inverse(a);
    const Vec3 c_k = s_k * eta;
    diag(k) = s_k;  // the information block of p_k was read at step k - 1
    eta_[k] = c_k;
    const Mat3 w = k + 1 < n_ ? step_info_[k].full() : Mat3::Zero();  // the (k, k+1) block is -W
    if (!segment_b_.empty()) {
      const Mat3 p_k = s_k * t;  // P_k
      acc += symmetric_product(t.transpose(), p_k);  // T^T S T
      acc_eta.noalias() += t.transpose() * c_k;
      if (k + 1 < n_) t = w * p_k;  // T_{k+1} (an event at k + 1 resets it below)
    }
    if (k + 1 == n_) break;
    a = diag(k + 1) - symmetric_product(w * s_k, w);
    eta = eta_[k + 1] + w * c_k;
    if (const MatX* b = mixed_at(k + 1)) {
      if (segment_b_.empty()) {
        open_segment(*b, nullptr);
      } else {
        const MatX carried = segment_b_.back();
        open_segment(*b, &carried);
      }
    }
  }
  close_segment();

  const Eigen::LDLT<MatX> static_solver(d);
  m_mean_ = static_solver.solve(eta_m);
  m_cov_ = static_solver.solve(MatX::Identity(q, q));
  // Per segment: B_e m, B_e Sigma_mm and B_e Sigma_mm B_e^T.
  bm_.clear();
  b_sigma_.clear();
  b_sigma_b_.clear();
  for (const MatX& b : segment_b_) {
    bm_.push_back(b * m_mean_);
    b_sigma_.push_back(b * m_cov_);
    b_sigma_b_.push_back(b_sigma_.back() * b.transpose());
  }
  backward_means();
}

std::vector<double> ArrowheadChain::take_covariances() {
  if (stage_ != Stage::covariances)
    throw std::logic_error("ArrowheadChain::take_covariances: solve_covariances() first, once per set of factors");
  stage_ = Stage::taken;
  return std::move(diag_);
}

void ArrowheadChain::solve_covariances() {
  require_steps("solve_covariances");
  if (stage_ != Stage::means)
    throw std::logic_error("ArrowheadChain::solve_covariances: solve_means() first, once per set of factors");
  stage_ = Stage::covariances;
  backward_covariances();
  release_segments();  // (with biases every step is a segment: not kept to the peak)
}

int ArrowheadChain::segment_of(std::size_t k) const {
  return static_cast<int>(std::upper_bound(events_.begin(), events_.end(), k) - events_.begin()) - 1;
}

// Backward, the means: p_k = c_k - L_k p_{k+1} - P_k B_e m with L_k = -S_k W_k and P_k =
// S_k T_k, that is p_k = c_k + S_k (W_k p_{k+1} - v_k) with v_k = T_k B_e m. The v_k follow
// T_k's recursion (B_e m at an event, W_{k-1} S_{k-1} v_{k-1} after), recomputed block by
// block from the T_k kept at each block's start: 3-vectors where the covariance pass needs
// the 3x3 P_k (a third of the arithmetic). diag_ holds S_k, and keeps it for the
// covariance pass.
[[gnu::flatten]] void ArrowheadChain::backward_means() {
  std::vector<Vec3> coupled(std::min(n_, kCouplingBlock));  // v_k of a block's steps
  const auto recompute_coupled = [&](std::size_t first, std::size_t end) {
    int segment = segment_of(first);
    auto next_event = static_cast<std::size_t>(segment + 1);  // the first event after `first`
    Vec3 v = segment < 0 ? Vec3::Zero() : (coupling_start_[first / kCouplingBlock] * bm_[static_cast<std::size_t>(segment)]).eval();
    for (std::size_t k = first; k < end; ++k) {
      if (next_event < events_.size() && events_[next_event] == k) {
        v = bm_[static_cast<std::size_t>(++segment)];  // T_k = I
        ++next_event;
      } else if (k > first) {
        v = step_info_[k - 1].full() * (diag(k - 1) * v).eval();  // (zero before the first event)
      }
      coupled[k - first] = v;
    }
  };
  for (std::size_t k = n_; k-- > 0;) {
    if (k + 1 == n_ || (k + 1) % kCouplingBlock == 0) recompute_coupled(k - k % kCouplingBlock, k + 1);
    // eta_[k + 1] holds the mean of p_{k+1} by now, eta_[k] still c_k.
    Vec3 r = -coupled[k % kCouplingBlock];
    if (k + 1 < n_) r += step_info_[k].full() * eta_[k + 1];
    eta_[k] += diag(k) * r;
  }
}

// Backward, the covariances. Within a segment the cross covariance X_{k} = Cov(p_k, m) is
// alpha_k Z + beta_k B_e Sigma_mm, with Z = X at the step after the segment; only Y_k =
// X_{k+1} B_e^T (3x3) is needed per step.
[[gnu::flatten]] void ArrowheadChain::backward_covariances() {
  const auto q = static_cast<Eigen::Index>(q_);
  // P_k of the steps of a block, recomputed as the forward pass computed them. Their
  // S_k are still in diag_: the backward pass has not reached the block yet.
  std::vector<Mat3> coupling(std::min(n_, kCouplingBlock));
  const auto recompute_coupling = [&](std::size_t first, std::size_t end) {
    int segment = segment_of(first);
    auto next_event = static_cast<std::size_t>(segment + 1);  // the first event after `first`
    Mat3 t_k = coupling_start_[first / kCouplingBlock];
    for (std::size_t k = first; k < end; ++k) {
      const bool event = next_event < events_.size() && events_[next_event] == k;
      if (event) {
        ++segment;
        ++next_event;
      }
      if (segment < 0) continue;  // before the first event: no coupling
      if (k > first) t_k = event ? Mat3::Identity().eval() : (step_info_[k - 1].full() * coupling[k - 1 - first]).eval();
      coupling[k - first] = diag(k) * t_k;
    }
  };
  MatX z = MatX::Zero(3, q);  // X_{k+1} in full, valid at segment boundaries
  Mat3 alpha = Mat3::Identity(), beta = Mat3::Zero();  // X_{k+1} = alpha Z + beta B_e Sigma
  Mat3 y_end = Mat3::Zero();                           // Z B_e^T for the current segment
  int current = -2;
  int segment = static_cast<int>(events_.size()) - 1;  // the segment of step k below
  for (std::size_t k = n_; k-- > 0;) {
    if (k + 1 == n_ || (k + 1) % kCouplingBlock == 0) recompute_coupling(k - k % kCouplingBlock, k + 1);
    while (segment >= 0 && events_[static_cast<std::size_t>(segment)] > k) --segment;
    const Mat3 l = k + 1 < n_ ? (-diag(k) * step_info_[k].full()).eval() : Mat3::Zero();
    if (segment != current) {
      // Entering a new segment (going backward): X_{k+1} in full from the previous one.
      if (current >= 0 && k + 1 < n_) z = alpha * z + beta * b_sigma_[static_cast<std::size_t>(current)];
      alpha.setIdentity();
      beta.setZero();
      current = segment;
      if (current >= 0) y_end = z * segment_b_[static_cast<std::size_t>(current)].transpose();
    }
    // diag_[k + 1] holds the covariance of p_{k+1} by now; diag_[k] still holds S_k.
    Mat3 cov = diag(k);
    if (k + 1 < n_) cov += l * diag(k + 1) * l.transpose();
    if (current >= 0) {
      const auto e = static_cast<std::size_t>(current);
      const Mat3& p_k = coupling[k % kCouplingBlock];
      cov += p_k * b_sigma_b_[e] * p_k.transpose();
      if (k + 1 < n_) {
        const Mat3 y = alpha * y_end + beta * b_sigma_b_[e];  // X_{k+1} B_e^T
        const Mat3 cross = l * y * p_k.transpose();
        cov += cross + cross.transpose();
      }
      // X_k = -L_k X_{k+1} - P_k B_e Sigma_mm.
      alpha = (-l * alpha).eval();
      beta = (-l * beta - p_k).eval();
    } else if (k + 1 < n_) {
      alpha = (-l * alpha).eval();  // before the first event: X_k = -L_k X_{k+1}
      beta = (-l * beta).eval();
    }
    diag(k) = 0.5 * (cov + cov.transpose());
    // X_k = alpha Z + beta B_e Sigma_mm (beta is zero before the first event).
    if (column_count_ > 0) {
      const auto first = static_cast<Eigen::Index>(column_first_), count = static_cast<Eigen::Index>(column_count_);
      Eigen::Map<Eigen::Matrix<double, 3, Eigen::Dynamic>> x(cross_columns_.data() + 3 * column_count_ * k, 3, count);
      x.noalias() = alpha * z.middleCols(first, count);
      if (current >= 0) x.noalias() += beta * b_sigma_[static_cast<std::size_t>(current)].middleCols(first, count);
    }
    if (const auto kept = cross_at_.find(k); kept != cross_at_.end()) {
      kept->second = alpha * z;
      if (current >= 0) kept->second += beta * b_sigma_[static_cast<std::size_t>(current)];
    }
  }
}

}  // namespace gesmi
