#pragma once
// Options of the reference-like mission simulator.

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace gesmi {

/// uniform: errors drawn in the bounds; worst_case: a bias at 99 % of the bound, one
/// sign per sensor; at_samples: at 99 % of the bound against the motion of the step
/// that follows, so that a sample's box holds at its instant but not over the step
/// (what the paper's step convention assumes away; docs/model.md); drifting: a slow
/// sinusoid per sensor, 0.99 * bound * sin(2 pi t / T_s + phi_s), with its period T_s
/// uniform in [600 s, 2400 s] and its phase phi_s uniform in [0, 2 pi) drawn from the
/// seed: always inside the bounds (the interval guarantee holds), but not the constant
/// bias the bias-aware Kalman smoother assumes (docs/comparison.md); corners: at 99.9 %
/// of the bound on the side that puts the truth on its box's corner where the
/// trapezoid rule is weakest (the sign of the truth's second difference at the sample:
/// adversarial for the jerk bound); bias_noise: what sensor datasheets state, a bias
/// at a share of the bound plus noise within the rest (reading_errors.h).
enum class SimulatedErrors { uniform, worst_case, at_samples, drifting, corners, bias_noise };
inline constexpr std::array kAllSimulatedErrors = {SimulatedErrors::uniform,  SimulatedErrors::worst_case,
                                                   SimulatedErrors::at_samples, SimulatedErrors::drifting,
                                                   SimulatedErrors::corners,  SimulatedErrors::bias_noise};
/// "uniform", "worst-case", "at-samples", "drifting", "corners", "bias-noise"; parse
/// returns false for another name.
const char* simulated_errors_name(SimulatedErrors errors);
bool parse_simulated_errors(std::string_view name, SimulatedErrors& errors);
/// Every name, for a message: "uniform, worst-case, ... or bias-noise".
std::string simulated_errors_names();

/// How the biases of the bias-noise mode change: not at all, linearly from their value
/// at the start to its opposite at the end (ramp), or to their opposite at the middle of
/// the mission (flip).
enum class BiasDrift { none, ramp, flip };
/// "none", "ramp", "flip"; parse returns false for another name.
const char* bias_drift_name(BiasDrift drift);
bool parse_bias_drift(std::string_view name, BiasDrift& drift);

struct SimulationOptions {
  std::uint64_t seed = 1;
  SimulatedErrors errors = SimulatedErrors::uniform;
  double bias_share = 0.9;           // bias_noise: the bias's share of each bound, in [0, 1]
  BiasDrift drift = BiasDrift::none;  // bias_noise
  double duration = 5999.4;  // s, t0 = 0 to tf (the reference mission's times)
  double rate = 10.0;        // Hz
  int mines = 6;             // the reference layout first, extra mines in the survey area
  double missed = 0.0;       // probability that a detection is dropped (stored in the truth)
  double unassociated = 0.0; // probability that a mark loses its mine number
  int outliers = 0;          // marks whose range is corrupted beyond its bound
  // The surface (docs/model.md, "The surface"): the robot waits this long at the surface
  // before the dive and after surfacing (0: the reference mission, submerged throughout),
  // with GPS fixes at 1 Hz, in waves of this height and period.
  double surface = 0.0;       // s
  double wave_height = 0.0;   // m
  double wave_period = 6.0;   // s
  bool surface_dvl = false;   // the DVL keeps bottom lock at the surface (else it has no reading there)
  // Vertical jerk bursts of 1 s while submerged, evenly spread (extra_motion.h).
  int bursts = 0;
  double burst_jerk = 10.0;   // m/s³
  /// Empty when usable; otherwise the reason.
  std::string validate() const;
};

}  // namespace gesmi
