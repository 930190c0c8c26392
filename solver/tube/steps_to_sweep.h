#pragma once
// Which steps of a tube's three chains a sweep must take again (chain_sweep.h). After
// the first sweeps of a mission solve most of the tube no longer moves: of the 59,994
// steps of the reference mission, the third and later sweeps of a pass narrow 0.5 to
// 24 % (docs/performance.md, "Chain sweeps over marked steps").
//
// A step not taken would leave its domains as they are, so sweeps over the marked steps
// end with the bounds of full sweeps (as numbers; a zero may keep its other sign):
//  - forward, x(k+1) := x(k+1) ∩ (x(k) + v(k)): after it x(k+1) lies within x(k) + v(k),
//    and narrowing x(k+1) afterwards keeps it there; only a narrower x(k) or v(k) can
//    move it again;
//  - backward, x(k) := x(k) ∩ (x(k+1) - v(k)) then v(k) := v(k) ∩ (x(k+1) - x(k)): done
//    once, both hold (the narrower v(k) still allows all of x(k), rounding included),
//    and narrowing either afterwards keeps them; only a narrower x(k), x(k+1) or v(k)
//    can move them again.
// So a forward step is marked when its x(k) or v(k) was narrowed since a forward sweep
// last took it, a backward step when its x(k), x(k+1) or v(k) was. The sweeps mark what
// they narrow for the other direction; whatever else narrows a position between sweeps
// (a fix, a detection) must say so with narrowed().

#include <cstddef>
#include <cstdint>
#include <vector>

namespace gesmi {

class StepsToSweep {
 public:
  /// For a tube of `samples` samples (samples - 1 steps), every step marked both ways.
  explicit StepsToSweep(std::size_t samples);

  /// Sample k's position was narrowed on some chain outside the sweeps.
  void narrowed(std::size_t k);
  /// Every step marked both ways again: after a sweep that kept no marks (one over every
  /// step, or one that stopped at an empty domain with its marks half cleared).
  void mark_all();

  std::size_t samples() const { return samples_; }
  /// One flag per step (1: take it), and one spare at the end that the sweeps may set
  /// (never read): the kernels' view (chain_sweep_kernel.cpp).
  std::uint8_t* forward() { return forward_.data(); }
  std::uint8_t* backward() { return backward_.data(); }

 private:
  std::size_t samples_;
  std::vector<std::uint8_t> forward_, backward_;
};

}  // namespace gesmi
