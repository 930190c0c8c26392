#pragma once
// A LinearProgram handed to COIN-OR CLP once, then minimised for many objectives, each
// from the previous basis. CLP's answer is a hint: bounds come from its multipliers
// through DualCertificate (dual_certificate.h), never from its objective value.

#include <memory>
#include <span>
#include <vector>

#include "solver/lp/linear_program.h"

class ClpSimplex;

namespace gesmi {

class ClpProgram {
 public:
  explicit ClpProgram(const LinearProgram& lp);
  ~ClpProgram();
  ClpProgram(const ClpProgram&) = delete;
  ClpProgram& operator=(const ClpProgram&) = delete;

  enum class Status { optimal, infeasible, other };
  struct Answer {
    Status status = Status::other;
    /// One multiplier per row: CLP's duals when optimal, its infeasibility ray when
    /// infeasible (a Farkas certificate to check with certifies_empty), else empty.
    std::vector<double> multipliers;
  };
  /// Minimises objective . z (one coefficient per column).
  Answer minimize(std::span<const double> objective);

 private:
  std::unique_ptr<ClpSimplex> model_;
};

}  // namespace gesmi
