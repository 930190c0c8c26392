// Start-up localization by set inversion in Python (as `gesmi localize`).

#include <pybind11/stl.h>

#include "io/localization/localization_scenario.h"
#include "solver/setinv/localization/localization_problem.h"
#include "tools/python/bindings.h"

namespace gesmi::python {

void bind_localize(py::module_& m) {
  m.def(
      "localize",
      [](const std::string& scenario, bool safety) {
        const LocalizationProblem problem = io::read_localization_scenario(scenario);
        LocalizationResult r;
        {
          py::gil_scoped_release release;
          r = localize(problem);
          if (safety && r.found) r.safety = localization_safety(problem, r);
        }
        py::dict out;
        out["found"] = r.found;
        out["q"] = r.q;
        out["inner"] = paving_boxes(r.paving.inner);
        out["boundary"] = paving_boxes(r.paving.boundary);
        out["truth_enclosed"] = r.truth_enclosed;
        out["seconds"] = r.seconds;
        py::list hypotheses;
        for (const LocalizationHypothesis& h : r.hypotheses) {
          py::dict d;
          std::vector<std::pair<double, double>> hull;
          for (const Interval& x : h.component.hull) hull.emplace_back(x.lo(), x.hi());
          d["hull"] = hull;
          d["outliers"] = h.outliers.outliers;
          d["outliers_determined"] = h.outliers.determined;
          d["agreed_outliers"] = h.outliers.outliers;
          d["agreed_inliers"] = h.outliers.agreed_inliers;
          d["outlier_sets"] = h.outliers.sets;
          d["outlier_sets_complete"] = h.outliers.sets_complete;
          d["possible_outlier_sets"] = h.outliers.possible_sets;
          d["contains_truth"] = h.contains_truth;
          hypotheses.append(d);
        }
        out["hypotheses"] = hypotheses;
        out["q_lower"] = r.q_lower;
        py::list sets;
        for (const OutlierSetPaving& s : r.outlier_sets.sets) {
          py::dict d;
          d["outliers"] = s.outliers;
          d["inner"] = paving_boxes(s.inner);
          d["boundary"] = paving_boxes(s.boundary);
          std::vector<std::pair<double, double>> hull;
          for (const Interval& x : s.hull) hull.emplace_back(x.lo(), x.hi());
          d["hull"] = hull;
          sets.append(d);
        }
        out["outlier_sets"] = sets;
        out["unresolved"] = paving_boxes(r.outlier_sets.unresolved);
        if (!r.safety.empty()) {
          std::vector<std::pair<double, double>> per_datum;
          for (const DatumSafety& s : r.safety) per_datum.emplace_back(s.safety.lo(), s.safety.hi());
          out["safety"] = per_datum;
        }
        return out;
      },
      py::arg("scenario"), py::arg("safety") = false,
      "Static localization by set inversion from a scenario file (as `gesmi localize`): the pavings "
      "(inner and boundary boxes, (B, 3, 2)), q, the hypotheses (hull, agreed outliers and inliers, "
      "outlier sets), S_q split by outlier set (outlier_sets, unresolved) and, with safety=True, "
      "Remark 6's safety interval of each datum (one more SIVIA per datum)");
}

}  // namespace gesmi::python
