#pragma once
// Options of the reference-like mission simulator (issue: mission data).

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
/// bias the bias-aware Kalman smoother assumes (docs/comparison.md).
enum class SimulatedErrors { uniform, worst_case, at_samples, drifting };
/// "uniform", "worst-case", "at-samples", "drifting"; parse returns false for another name.
const char* simulated_errors_name(SimulatedErrors errors);
bool parse_simulated_errors(std::string_view name, SimulatedErrors& errors);

struct SimulationOptions {
  std::uint64_t seed = 1;
  SimulatedErrors errors = SimulatedErrors::uniform;
  double duration = 5999.4;  // s, t0 = 0 to tf (the reference mission's times)
  double rate = 10.0;        // Hz
  int mines = 6;             // the reference layout first, extra mines in the survey area
  double missed = 0.0;       // probability that a detection is dropped (stored in the truth)
  double unassociated = 0.0; // probability that a mark loses its mine number
  int outliers = 0;          // marks whose range is corrupted beyond its bound
  /// Empty when usable; otherwise the reason.
  std::string validate() const;
};

}  // namespace gesmi
