#pragma once
// Connected components of a SIVIA result: two boxes are connected when they touch
// (closed boxes sharing at least one point), also across the period of a periodic
// dimension (theta near 0 touches theta near 2 pi). Each component of the solution
// set lies inside exactly one component of inner ∪ boundary, so each component is a
// hypothesis (seed 002 section 4, seed 004 section IV).

#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "solver/setinv/paving.h"

namespace gesmi {

struct ComponentOptions {
  int periodic_dimension = -1;
  double period = 0.0;
  /// Lower end of the period window in which wrapped hulls are expressed: the hull's
  /// periodic interval has its midpoint in [origin, origin + period).
  double periodic_origin = 0.0;
  /// Gap still counted as touching across the period (the prior's bounds are
  /// rounded, so 0 and 2 pi do not meet exactly).
  double wrap_tolerance = 1e-9;
};

struct PavingComponent {
  std::vector<std::size_t> inner;     // indices into the inner paving
  std::vector<std::size_t> boundary;  // indices into the boundary paving
  /// Smallest box holding the component; on the periodic dimension the shortest arc,
  /// which may reach outside the prior's window (e.g. [-0.05, 0.05] for a window
  /// [0, 2 pi]).
  Box hull;
  double inner_volume = 0.0;
  double boundary_volume = 0.0;
};

/// Components, largest total volume first (ties: more inner boxes first).
std::vector<PavingComponent> connected_components(const Paving& inner, const Paving& boundary,
                                                  const ComponentOptions& options = {});

/// Boxes are numbered inner first, then boundary. Calls `touching(i, j)`, i < j, for
/// every pair of boxes that touch (across the period too), except pairs for which
/// `skip(i, j)` (optional) returns true before the test.
void for_each_touching_pair(const Paving& inner, const Paving& boundary, const ComponentOptions& options,
                            const std::function<void(std::size_t, std::size_t)>& touching,
                            const std::function<bool(std::size_t, std::size_t)>& skip = {});

/// The components given by a label per box (same numbering; labels below the number
/// of boxes), with hulls and volumes, largest total volume first.
std::vector<PavingComponent> components_from_labels(const Paving& inner, const Paving& boundary,
                                                    std::span<const std::size_t> label, const ComponentOptions& options = {});

/// Shortest arc of period `period` covering every interval (given in any window);
/// its midpoint lies in [origin, origin + period).
Interval wrapped_hull(const std::vector<Interval>& arcs, double period, double origin);

}  // namespace gesmi
