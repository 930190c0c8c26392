#include "solver/tube/steps_to_sweep.h"

#include <algorithm>
#include <stdexcept>

namespace gesmi {

// (samples steps: samples - 1 of them and the spare; at least the spare)
StepsToSweep::StepsToSweep(std::size_t samples)
    : samples_(samples), forward_(std::max<std::size_t>(samples, 1), 1), backward_(std::max<std::size_t>(samples, 1), 1) {}

void StepsToSweep::narrowed(std::size_t k) {
  if (k >= samples_) throw std::out_of_range("StepsToSweep::narrowed: no such sample");
  // Forward step k and backward step k read x(k); backward step k - 1 reads it as its x(k+1).
  // (k = samples - 1 is no forward step: its flag is the spare)
  forward_[k] = 1;
  backward_[k] = 1;
  if (k > 0) backward_[k - 1] = 1;
}

void StepsToSweep::mark_all() {
  std::fill(forward_.begin(), forward_.end(), 1);
  std::fill(backward_.begin(), backward_.end(), 1);
}

}  // namespace gesmi
