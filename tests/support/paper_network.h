#pragma once
// A plain floating-point propagation of seed 001's own network, written for the
// tests independently of solver/: intervals of two doubles rounded to nearest (no
// outward rounding), the paper's step convention d(k) = dt R([attitude]_k) [v]_k,
// depth from the barometer, GPS fixes, and each mark's equations contracted by
// hand-written forward-backward steps in the world and robot frames. It is the
// tightness reference of the step models (docs/model.md): what the paper's network
// gives, against which gesmi's sound enclosures are measured.
//
// Missions whose fixes and marks lie on sample times only (the simulator's).

#include <vector>

#include "solver/mission/mission.h"

namespace gesmi::test {

struct PaperTube {
  std::vector<double> north_lo, north_hi, east_lo, east_hi;
  std::vector<double> mine_north_width, mine_east_width;
  bool consistent = true;
  int sweeps = 0;
  double max_horizontal_width() const;
};

/// Propagates until no bound moves by more than 1 mm (at most 100 sweeps).
PaperTube propagate_paper_network(const Mission& mission);

}  // namespace gesmi::test
