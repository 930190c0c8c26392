#pragma once
// A Gaussian linear system on a chain of 3-D positions p_0..p_{n-1} plus a block of
// static unknowns m (the mines): information contributions are added factor by
// factor, then solved by a forward pass over the chain (an information filter: block
// elimination of p_0, p_1, ...) and a backward pass (back substitution and the
// covariance recursion). On a linear model this gives exactly the smoothed means and
// covariances of a Kalman filter followed by Rauch-Tung-Striebel smoothing, with 3x3
// blocks along the chain: O(n q^2) time for q static unknowns, no n x n matrix.

#include <Eigen/Core>
#include <map>
#include <span>
#include <stdexcept>
#include <vector>

namespace gesmi {

class ArrowheadChain {
 public:
  using Mat3 = Eigen::Matrix3d;
  using Vec3 = Eigen::Vector3d;
  using MatX = Eigen::MatrixXd;
  using VecX = Eigen::VectorXd;
  using Row3 = Eigen::RowVector3d;

  /// A symmetric 3x3 block by its upper triangle: six numbers where a Mat3 takes nine
  /// (the steps' information was a third of the smoother's memory at 10^7 steps).
  struct Symmetric3 {
    double xx = 0.0, xy = 0.0, xz = 0.0, yy = 0.0, yz = 0.0, zz = 0.0;
    /// m's upper triangle (its lower one is not read).
    static Symmetric3 upper_of(const Mat3& m) { return {m(0, 0), m(0, 1), m(0, 2), m(1, 1), m(1, 2), m(2, 2)}; }
    /// The block, its lower triangle mirrored from the upper one.
    Mat3 full() const {
      Mat3 m;
      m << xx, xy, xz, xy, yy, yz, xz, yz, zz;
      return m;
    }
    friend Symmetric3 operator+(const Symmetric3& a, const Symmetric3& b) {
      return {a.xx + b.xx, a.xy + b.xy, a.xz + b.xz, a.yy + b.yy, a.yz + b.yz, a.zz + b.zz};
    }
  };

  /// n positions, q static unknowns (with a weak prior of information prior_info on
  /// each, so that unknowns no factor reaches stay finite).
  ArrowheadChain(std::size_t n, std::size_t q, double prior_info = 1e-12);
  /// The same with the steps' information W_k (n - 1 of them, std::invalid_argument
  /// otherwise) given, as kept by reset_keeping_steps() after add_step(k, W_k, ...) for
  /// every k: the next call is reset_keeping_steps(). For an odometry computed before
  /// the chain's other blocks are allocated (what kalman_smooth() releases in between).
  ArrowheadChain(std::size_t n, std::size_t q, std::vector<Symmetric3> step_information, double prior_info = 1e-12);

  /// Removes every factor, keeping the memory: a relinearised system is built again in
  /// the same buffers (at 10^7 steps, reallocating them cost more than the solve). The
  /// solve works in place, so factors are added again only after reset().
  void reset();
  /// reset() but for the steps' information W_k (add_step), which stays for
  /// add_steps_again(), the next call: an odometry that does not change between
  /// linearisations (no biases) is computed once. add_step() is refused until the next
  /// reset() (it would add to the kept W_k).
  void reset_keeping_steps();
  /// Once after reset_keeping_steps(), before any other factor (std::logic_error
  /// otherwise; it writes every block, which reset_keeping_steps() leaves as they were):
  /// the steps p_{k+1} - p_k = delta[k] again, with the information kept, for unknowns taken as
  /// corrections from a reference point (p_k = r_k + x_k, r_k the three numbers
  /// reference[3k..3k+2]): x_{k+1} - x_k = relative_step(delta[k], r_k, r_{k+1}). The same
  /// system, bit for bit, as add_step(k, W_k, that step) for every k.
  void add_steps_again(std::span<const Vec3> delta, std::span<const double> reference);
  /// A step p_{k+1} - p_k = delta in terms of corrections from `from` (at p_k) and `to`
  /// (at p_{k+1}). Small against the positions once the reference is close: solving for
  /// corrections keeps the chain's rounding to the corrections' size (docs/comparison.md,
  /// "When the smoother stops").
  static Vec3 relative_step(const Vec3& delta, const Vec3& from, const Vec3& to) { return delta - (to - from); }
  /// W_k of the step from p_k to p_{k+1}, as the chain holds it (add_step's upper
  /// triangle, mirrored); meaningful until release_workspace().
  Mat3 step_information(std::size_t k) const { return step_info_[k].full(); }
  /// Frees what only the solves need, once no further solve follows: the steps'
  /// information and what the forward pass left for the backward passes (the means and
  /// covariances stay). Solving or adding steps again is refused afterwards, until
  /// reset().
  void release_workspace();

  /// Information W and mean term on p_k alone: adds W to the block and W * mean.
  void add_position(std::size_t k, const Mat3& information, const Vec3& mean);
  /// p_{k+1} - p_k = delta with information W (the odometry between two samples), read
  /// from its upper triangle (W is symmetric; its lower triangle is not read).
  void add_step(std::size_t k, const Mat3& information, const Vec3& delta);
  /// One scalar measurement z = hp . p_k with information w.
  void add_position_row(std::size_t k, const Row3& hp, double z, double w);
  /// One scalar measurement z = hp . p_k + hm . m with information w (hm has q entries).
  void add_mixed(std::size_t k, const Row3& hp, const Eigen::RowVectorXd& hm, double z, double w);
  /// One scalar measurement z = m_j of static unknown j alone (a prior) with information w.
  void add_static(std::size_t j, double z, double w);

  /// Before solve(): also keep the cross covariance Cov(p_k, m) (3 x q) at these steps
  /// (the residual tests of the measurements there need it) ...
  void keep_cross_covariance_at(std::vector<std::size_t> steps);
  /// ... and Cov(p_k, m_j) for j in [first, first + count) at every step (the biases,
  /// which turn the positions relative to them back into positions).
  void keep_cross_covariance_columns(std::size_t first, std::size_t count);

  /// Solves, once per set of factors (std::logic_error otherwise: the factors were
  /// overwritten); afterwards mean(k), covariance(k), static_mean(), static_covariance().
  /// The same as solve_means() then solve_covariances().
  void solve();
  /// The means alone (and the static unknowns' covariance), for a linearisation that
  /// needs no covariance: the backward pass without its covariance recursion, which is
  /// most of its arithmetic. covariance(k) and the cross covariances are meaningless
  /// until solve_covariances().
  void solve_means();
  /// After solve_means() (std::logic_error otherwise): the covariances, as solve()'s.
  void solve_covariances();
  /// The smoothed mean of p_k, meaningful after solve_means() (or solve()), and its
  /// covariance, meaningful after solve_covariances() (or solve()).
  const Vec3& mean(std::size_t k) const { return eta_[k]; }
  Eigen::Map<const Mat3> covariance(std::size_t k) const {
    if (stage_ == Stage::taken) throw std::logic_error("ArrowheadChain::covariance: handed over by take_covariances()");
    return Eigen::Map<const Mat3>(diag_.data() + 9 * k);
  }
  /// After solve_covariances() (std::logic_error otherwise): every covariance, 9 numbers
  /// per step, moved out of the chain (no copy, no fresh memory: at 10^7 steps a new
  /// 720 MB array cost the kernel's zeroing). Each block is symmetric bit for bit, so its
  /// column-major order is also its row-major one. covariance(k) and adding factors are
  /// refused afterwards (std::logic_error), until reset().
  std::vector<double> take_covariances();
  const VecX& static_mean() const { return m_mean_; }
  const MatX& static_covariance() const { return m_cov_; }
  /// Cov(p_k, m) at a step given to keep_cross_covariance_at (std::out_of_range otherwise).
  const MatX& cross_covariance_at(std::size_t k) const { return cross_at_.at(k); }
  /// Cov(p_k, m_j), j in the columns given to keep_cross_covariance_columns: 3 x count.
  Eigen::Map<const Eigen::Matrix<double, 3, Eigen::Dynamic>> cross_covariance_columns(std::size_t k) const {
    const auto count = static_cast<Eigen::Index>(column_count_);
    return {cross_columns_.data() + 3 * column_count_ * k, 3, count};
  }
  std::size_t size() const { return n_; }

 private:
  // Memory (10^7 steps): solve() works in place. Its forward
  // pass overwrites diag_[k] with the conditional covariance S_k and eta_[k] with the
  // conditional mean c_k, each once it has been read for the last time; the means' backward
  // pass overwrites eta_[k] with the mean, the covariances' diag_[k] with the covariance. The
  // coupling P_k = S_k T_k of a step to its segment's unknowns and the gain L_k = -S_k W_k
  // are not stored (P_k took 80 B/step): the backward passes recompute them block by block
  // from a T_k kept every kCouplingBlock steps (the covariances' P_k with the same
  // operations in the same order as the forward pass; the means' only its action on the
  // segment's B_e m, a 3-vector).
  static constexpr std::size_t kCouplingBlock = 256;
  enum class Stage { factors, means, covariances, taken };  // what the buffers hold
  // The steps' information: accumulating (add_step), kept for add_steps_again(), added
  // again, or released.
  enum class Steps { building, kept, added_again, released };
  void backward_means();
  void backward_covariances();
  int segment_of(std::size_t k) const;  // the last event at or before step k (-1: none)
  // add_step's terms of the system, for the information already in step_info_[k].
  void add_step_terms(std::size_t k, const Mat3& w, const Vec3& delta);
  void require_steps(const char* caller) const;
  // Factors are added before a solve only: it works in place, and take_covariances() empties
  // the blocks (std::logic_error otherwise, until reset()).
  void require_factors(const char* caller) const;
  void clear_factors();     // every factor but the steps' information
  void clear_static_factors();  // the mixed factors and the static unknowns' information
  void release_segments();  // what the forward pass left for the backward passes

  std::size_t n_, q_;
  double prior_info_;
  // The 3x3 block of p_k, column-major, 9 numbers a step (a plain array, so that
  // take_covariances() can hand it over): its information; then S_k; then the covariance.
  std::vector<double> diag_;
  Eigen::Map<Mat3> diag(std::size_t k) { return Eigen::Map<Mat3>(diag_.data() + 9 * k); }
  std::vector<Vec3> eta_;         // information vector of p_k; then c_k; then the mean
  std::vector<Symmetric3> step_info_;  // W_k between p_k and p_k+1
  std::map<std::size_t, MatX> mixed_;  // B_k (3 x q) at the few steps with a mixed factor
  MatX d_;                        // information of m
  VecX eta_m_;
  // Results.
  VecX m_mean_;
  MatX m_cov_;
  std::map<std::size_t, MatX> cross_at_;  // Cov(p_k, m) at the steps asked for
  std::size_t column_first_ = 0, column_count_ = 0;
  std::vector<double> cross_columns_;     // n x 3 x count, column-major per step
  Stage stage_ = Stage::factors;  // past `factors`, they were overwritten; reset() clears it
  Steps steps_ = Steps::building;
  // What the forward pass leaves for the backward passes: the steps with a mixed factor
  // (events), T_k at each kCouplingBlock, per segment B_e, B_e m, B_e Sigma_mm and
  // B_e Sigma_mm B_e^T.
  std::vector<std::size_t> events_;
  std::vector<Mat3> coupling_start_;
  std::vector<MatX> segment_b_, b_sigma_;
  std::vector<Vec3> bm_;
  std::vector<Mat3> b_sigma_b_;
};

}  // namespace gesmi
