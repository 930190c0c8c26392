#include "io/localization/localization_json.h"

#include "io/report/report_json.h"

namespace gesmi::io {
namespace {

nlohmann::json hull_json(const Box& box) {
  nlohmann::json hull = nlohmann::json::array();
  for (const Interval& x : box) hull.push_back(interval_json(x));
  return hull;
}

struct Numbers {
  const LocalizationProblem& problem;
  DatumNumbering numbering;
  std::size_t operator()(std::size_t i) const { return numbering == DatumNumbering::file ? problem.file_number(i) : i; }
  nlohmann::json operator()(const OutlierSet& set) const {
    nlohmann::json out = nlohmann::json::array();
    for (std::size_t i : set) out.push_back((*this)(i));
    return out;
  }
  nlohmann::json operator()(const std::vector<OutlierSet>& sets) const {
    nlohmann::json out = nlohmann::json::array();
    for (const OutlierSet& s : sets) out.push_back((*this)(s));
    return out;
  }
};

}  // namespace

nlohmann::json localization_json(const LocalizationProblem& p, const LocalizationResult& r, DatumNumbering numbering) {
  const Numbers number{p, numbering};
  nlohmann::json hypotheses = nlohmann::json::array();
  for (const LocalizationHypothesis& h : r.hypotheses) {
    const ComponentOutliers& o = h.outliers;
    hypotheses.push_back({{"outliers", number(o.outliers)},
                          {"outliers_determined", o.determined},
                          {"agreed_outliers", number(o.outliers)},
                          {"agreed_inliers", number(o.agreed_inliers)},
                          {"outlier_sets", number(o.sets)},
                          {"outlier_sets_complete", o.sets_complete},
                          {"possible_outlier_sets", o.possible_sets},
                          {"inner_boxes", h.component.inner.size()},
                          {"boundary_boxes", h.component.boundary.size()},
                          {"hull", hull_json(h.component.hull)},
                          {"inner_volume", h.component.inner_volume},
                          {"outer_volume", h.component.inner_volume + h.component.boundary_volume},
                          {"holds_truth", h.contains_truth}});
  }
  nlohmann::json sets = nlohmann::json::array();
  for (const OutlierSetPaving& s : r.outlier_sets.sets)
    sets.push_back({{"outliers", number(s.outliers)},
                    {"inner_boxes", s.inner.size()},
                    {"boundary_boxes", s.boundary.size()},
                    {"hull", hull_json(s.hull)},
                    {"inner_volume", s.inner_volume()},
                    {"outer_volume", s.outer_volume()}});
  nlohmann::json out{{"found", r.found},       {"q", r.q},         {"q_lower", r.q_lower},
                     {"truth_enclosed", r.truth_enclosed}, {"hypotheses", hypotheses},
                     {"outlier_sets", sets},   {"unresolved_boxes", r.outlier_sets.unresolved.size()},
                     {"limit_hit", r.limit_hit()}};
  if (!r.safety.empty()) {
    nlohmann::json safety = nlohmann::json::array();
    for (std::size_t i = 0; i < r.safety.size(); ++i) {
      const DatumSafety& s = r.safety[i];
      safety.push_back({{"datum", number(i)},
                        {"safety", interval_json(s.safety)},
                        {"inner_volume_without", s.inner_volume},
                        {"outer_volume_without", s.outer_volume},
                        {"limit_hit", s.limit_hit}});
    }
    out["safety"] = safety;
  }
  return out;
}

nlohmann::json localization_summary_json(const LocalizationProblem& p, const LocalizationResult& r) {
  nlohmann::json data = nlohmann::json::array();
  for (std::size_t i = 0; i < p.datum_count(); ++i) {
    const bool range = i < p.ranges.size();
    const std::string sensor = range ? p.range_sensors[p.ranges[i].sensor].name
                                     : p.bearing_sensors[p.bearings[i - p.ranges.size()].sensor].name;
    nlohmann::json datum{{"number", p.file_number(i)}, {"sensor", sensor}, {"kind", range ? "range" : "bearing"}};
    if (range) datum["no_echo"] = p.ranges[i].no_echo();  // seed 002: nothing heard within max_range
    data.push_back(std::move(datum));
  }
  nlohmann::json steps = nlohmann::json::array();
  if (r.gomne)
    for (const GomneStep& s : r.gomne->steps)
      steps.push_back({{"q", s.q}, {"epsilon", s.epsilon}, {"inner_boxes", s.inner_boxes},
                       {"boundary_boxes", s.boundary_boxes}, {"boxes_examined", s.boxes_visited}, {"seconds", s.seconds}});
  nlohmann::json out{{"scenario", p.name},
                     {"data_numbering", "position in the scenario's measurements, from 1"},
                     {"data", data},
                     {"epsilon", r.epsilon},
                     {"timing", {{"seconds", r.seconds}, {"gomne_steps", steps}}}};
  out.update(localization_json(p, r, DatumNumbering::file));
  return out;
}

}  // namespace gesmi::io
