#pragma once
// The global relaxation of the bias-and-noise model (structured_errors.h) over the GPS
// fixes and the marks: one linear program whose unknowns are the positions at the anchor
// samples (the first and last samples and the sample before each fix and mark), the
// mines and the seven biases, with a row pair per run of steps between anchors
// (affine_track.h) and per mark of a numbered mine (its sonar offset, heading bound whole). Each sample's
// north and east bounds come from LP multipliers of a nearby sample of a grid, checked
// as certificates in interval arithmetic (solver/lp/dual_certificate.h): a coarse grid
// costs width, never soundness. The bounds are intersected with the tube given.

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "solver/interval/interval.h"
#include "solver/mission/mission.h"
#include "solver/network/sensors/step_regimes.h"
#include "solver/network/tube_domains.h"
#include "solver/structured/structured_errors.h"

namespace gesmi {

struct StructuredBounds {
  std::vector<Interval> north, east;      // per sample, within the tube given
  std::array<Interval, kBiasTerms> bias;  // certified bounds of each bias (BiasTerm order)
  std::vector<std::array<Interval, 2>> mines;  // north and east of each mine, within the tube's
  /// False when the fixes and the model contradict each other (a certified Farkas ray or
  /// an empty sample box): the model's assumptions do not hold for this mission.
  bool consistent = true;
  std::size_t linear_programs = 0;  // solved, for the benchmarks
};

struct RelaxationOptions {
  std::size_t grid = 200;  // samples between the grid's points within a run
};

/// Why the relaxation cannot take this mission, or empty: per-sample half-widths (their
/// split into bias and noise is not known) or a step model other than the trapezoid.
std::string structured_relaxation_refusal(const Mission& mission);

/// `tube`: the positions and mines to intersect with (the per-sample solve's, or wider;
/// the mines' boxes are the bounds of their columns, so they must be finite to be used);
/// `regimes`: the mission's step regimes. std::invalid_argument with the refusal's text
/// for a mission the relaxation cannot take.
StructuredBounds relax_structured(const Mission& mission, const StepRegimes& regimes, const StructuredErrors& errors,
                                  const TubeDomains& tube, const RelaxationOptions& options = {});

}  // namespace gesmi
