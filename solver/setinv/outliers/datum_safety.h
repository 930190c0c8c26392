#pragma once
// Remark 6 of seed 004: the safety of datum i is the ratio of the volume of S* to
// that of the feasible set obtained when datum i is discarded. We read "the feasible
// set" with the same number q of outliers allowed among the remaining data:
//     S^(i) = {p : at most q of the data other than i are inconsistent with p}.
// Then S* ⊆ S^(i) (dropping a datum never adds an outlier), so the safety lies in
// [0, 1] as the remark states; 1 means the other data alone give the same set. (The
// other reading, the minimal-outlier set of the remaining data, can be smaller than
// S*, giving ratios above 1.)
//
// Both volumes are known through pavings only, so the safety is an interval:
//     [vol inner(S*) / vol outer(S^(i)),  min(1, vol outer(S*) / vol inner(S^(i)))].

#include <span>
#include <vector>

#include "solver/setinv/datum_tests.h"
#include "solver/setinv/outliers/gomne.h"
#include "solver/setinv/sivia.h"

namespace gesmi {

struct DatumSafety {
  Interval safety = Interval(0.0, 1.0);
  double inner_volume = 0.0;  // of S^(i)
  double outer_volume = 0.0;
  bool limit_hit = false;     // S^(i)'s SIVIA hit a limit: its outer volume still holds
};

/// Enclosure of vol(S) / vol(S^(i)) from the volumes of their inner and outer pavings,
/// knowing S ⊆ S^(i).
Interval safety_ratio(double inner, double outer, double inner_without, double outer_without);

/// The safety of one datum from the pavings of S^(i), against S's volumes.
inline DatumSafety datum_safety_from(const SiviaResult& without, double inner, double outer) {
  DatumSafety s;
  s.inner_volume = without.inner.volume();
  s.outer_volume = s.inner_volume + without.boundary.volume();
  s.limit_hit = without.report.limit_hit();
  s.safety = safety_ratio(inner, outer, s.inner_volume, s.outer_volume);
  return s;
}

/// A DatumTests with one datum discarded: it is reported consistent everywhere.
template <DatumTests Data>
class WithoutDatum {
 public:
  WithoutDatum(Data& data, std::size_t discarded) : data_(data), discarded_(discarded) {}
  std::size_t datum_count() const { return data_.datum_count(); }
  void evaluate(const Box& box, int depth, std::span<IBool> out, int false_budget) {
    // One more false allowed: the discarded datum may use it.
    data_.evaluate(box, depth, out, false_budget + 1);
    out[discarded_] = true;
  }

 private:
  Data& data_;
  std::size_t discarded_;
};

/// Remark 6 for every datum: S^(i) by SIVIA(q) (options.epsilon, no contractor) over
/// the priors, against the pavings `estimate` of S_q.
template <DatumTests Data, class Prior = NoPriorConstraint>
std::vector<DatumSafety> datum_safety(Data& data, double estimate_inner_volume, double estimate_outer_volume, int q,
                                      std::span<const Box> priors, const SiviaOptions& options, const Prior& prior = {}) {
  std::vector<DatumSafety> out;
  for (std::size_t i = 0; i < data.datum_count(); ++i) {
    WithoutDatum<Data> without(data, i);
    out.push_back(datum_safety_from(sivia_q(without, q, priors, options, prior), estimate_inner_volume,
                                    estimate_outer_volume));
  }
  return out;
}

}  // namespace gesmi
