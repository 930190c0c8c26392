#pragma once
// The Kalman smoother baseline (seed 001, section VI and Fig. 9): Euler angles taken
// as exact, the DVL velocity rotated by the measured attitude drives the position,
// depth and GPS fixes are measurements, and each detection is a range measurement
// linearised at the current estimate (plus the sonar-plane and mine-depth relations);
// a mine is initialised at its first detection from the declared side and the sonar
// geometry. The forward pass is an extended Kalman filter in information form over the
// chain of positions with the mines as static states; the backward pass is the
// Rauch-Tung-Striebel smoothing of that filter (arrowhead_chain.h), iterated with the
// range measurements relinearised at the smoothed estimate until it converges: until
// no position or mine coordinate moves by more than `tolerance` between two
// linearisations (a Gauss-Newton iteration of the batch problem), or the cap is reached.
//
// Noise from the interval bounds: a bound b becomes the variance factor * b^2 / 3, the
// variance of a uniform law on [-b, b] (docs/comparison.md).
//
// With `biases`, nine constant sensor biases join the unknowns (heading; DVL scale and
// offset per axis; depth scale and offset: kalman_measurements.h), each with a zero-mean prior of the
// same variance from its bound; the white noise keeps its variance. Every run ends with
// the consistency checks of kalman_consistency.h.

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "solver/kalman/kalman_consistency.h"
#include "solver/kalman/kalman_measurements.h"
#include "solver/mission/mission.h"
#include "solver/network/mission_network.h"

namespace gesmi {

/// A step at least this fraction of the previous one has stopped shrinking (converging
/// passes shrink it by a third or more).
inline constexpr double kStalledStepRatio = 0.9;

/// Where the linearisations start.
enum class KalmanStart {
  /// The dead reckoning from the first fix, each mine placed at its first detection.
  dead_reckoning,
  /// The same problem solved first on a coarse chain (coarse_start.h): its positions at
  /// every 64th sample and at the fixes' and marks' samples, interpolated in between,
  /// its mines, and every step's depth from all the depth readings. Without biases only
  /// (with them the dead reckoning's): the full chain then converges after one pass on
  /// the reference mission, where it took three. The result is judged by the same rule,
  /// and agrees with the dead reckoning's start within the tolerance.
  coarse,
};

/// "coarse", "dead-reckoning": the option's name for a start; std::nullopt for another text.
const char* kalman_start_name(KalmanStart start);
std::optional<KalmanStart> kalman_start_from_name(std::string_view name);

struct KalmanOptions {
  double noise_factor = 1.0;  // multiplies every variance
  int max_iterations = 20;    // cap on the linearisations of the range measurements (and on the coarse chain's)
  /// m: converged when the last linearisation moved no coordinate more: a millimetre
  /// against metres of uncertainty.
  double tolerance = 1e-3;
  /// The chain solves for corrections (chain_factors.h), so its rounding floor is about
  /// 10^-13 m from 6·10^4 to 10^6 steps (docs/comparison.md, "When the smoother stops");
  /// a tolerance of 0, or a pathological mission, can still reach it. So the
  /// linearisations also stop ("stalled") when the step stops shrinking (at least
  /// kStalledStepRatio of the previous one) although no
  /// coordinate moved more than this fraction of its own smoothed standard deviation:
  /// what is left is noise against the estimate's uncertainty. 0: never stop so.
  double stall_fraction = 0.01;
  bool biases = false;  // the bias-aware variant
  KalmanStart start = KalmanStart::coarse;
  /// Empty when usable; otherwise the reason, starting with the option it is about as
  /// the gesmi command spells it ("max-iterations: must be ...").
  std::string validate() const;
};

struct KalmanResult {
  std::size_t steps = 0, mines = 0;
  std::vector<double> mean;        // steps x 3, row-major (north, east, down)
  std::vector<double> covariance;  // steps x 3 x 3
  std::vector<double> mine_mean;   // mines x 3 (NaN for a mine never detected)
  std::vector<double> mine_covariance;  // mines x 3 x 3
  int iterations = 0;      // linearisations done (of the full chain)
  int coarse_iterations = 0;  // linearisations of the coarse chain it started from (0: the dead reckoning)
  double last_step = 0.0;  // m: the largest coordinate change of the last linearisation
  bool converged = false;  // last_step <= tolerance
  bool stalled = false;    // not converged, but stopped at the rounding floor (stall_fraction)
  double last_step_sigmas = 0.0;  // the last step in units of each coordinate's standard deviation (the largest)
  bool biases = false;     // the bias-aware variant: the bias fields below are filled
  BiasVec bias_estimate = BiasVec::Zero(), bias_sigma = BiasVec::Zero(), bias_prior_sigma = BiasVec::Zero();
  KalmanConsistency consistency;
  std::vector<InputTest> tests;  // every mark (table order) then every GPS fix
};

KalmanResult kalman_smooth(const Mission& mission, const SensorModel& model, std::span<const PositionFix> fixes,
                           const KalmanOptions& options = {});

/// Where the truth of a simulated mission lies (NaN without truth): the fraction of
/// steps whose true position is within 3 sigma on north and on east (horizontal), and
/// on down (vertical); and the fraction of detected mines inside the region of
/// probability kResidualTestProbability (0.9973, as 3 sigma on one axis) of their 3-D
/// Gaussian, and of its north-east marginal (the plane): d^2 = e^T C^-1 e below the
/// chi-square quantile with 3 (14.16) and 2 (11.83) degrees of freedom.
struct Containment {
  double horizontal = 0.0, vertical = 0.0, mines = 0.0, mines_plane = 0.0;
};
Containment three_sigma_containment(const KalmanResult& result, const Mission& mission);

/// three_sigma_containment() with the true positions given row by row, in order, as a
/// reader streams them (the truth of 10^7 steps is 240 MB).
class ContainmentCount {
 public:
  explicit ContainmentCount(const KalmanResult& result) : result_(result) {}
  /// The true position (north, east, down) of step k, the next one.
  void add(std::size_t k, double north, double east, double down);
  /// The fractions, with the true mines (K x 3, row-major); all NaN when no step was
  /// added (a mission without truth). std::logic_error when some steps were missed.
  Containment finish(std::span<const double> truth_mines) const;

 private:
  const KalmanResult& result_;
  std::size_t steps_ = 0, horizontal_ = 0, vertical_ = 0;
};

}  // namespace gesmi
