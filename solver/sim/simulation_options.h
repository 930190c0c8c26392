#pragma once
// Options of the reference-like mission simulator (issue: mission data).

#include <cstdint>
#include <string>

namespace gesmi {

enum class SimulatedErrors { uniform, worst_case };

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
