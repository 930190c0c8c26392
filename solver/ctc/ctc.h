#pragma once
// Contractors: operators that narrow the domains of a box without removing any
// solution of their constraint. A contractor is a small value type with one
// `void contract(Box&) const`; it may leave the box empty (normalised: every
// component empty), which means the constraint has no solution in the box.
// Emptiness is a result, never an exception (docs/concepts.md).

#include <concepts>
#include <memory>
#include <utility>
#include <vector>

#include "solver/interval/box.h"

namespace gesmi {

/// Makes every component of the box empty: the normal form of "no solution".
inline void set_empty(Box& box) {
  for (Interval& x : box) x = Interval::empty();
}

template <class C>
concept Contractor = requires(const C& c, Box& box) {
  { c.contract(box) } -> std::same_as<void>;
};

/// Type-erased contractor, for heterogeneous lists (a network of small problems).
class CtcAny {
 public:
  template <Contractor C>
  CtcAny(C c) : self_(std::make_shared<Model<C>>(std::move(c))) {}  // NOLINT: implicit by design
  void contract(Box& box) const { self_->contract(box); }

 private:
  struct Concept {
    virtual ~Concept() = default;
    virtual void contract(Box& box) const = 0;
  };
  template <class C>
  struct Model final : Concept {
    explicit Model(C c) : ctc(std::move(c)) {}
    void contract(Box& box) const override { ctc.contract(box); }
    C ctc;
  };
  std::shared_ptr<const Concept> self_;
};

}  // namespace gesmi
