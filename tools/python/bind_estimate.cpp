// Parameter estimation with outliers in Python (as `gesmi estimate`): data numbered
// from 1 as in the scenario file, like the command's summary.json.

#include <pybind11/stl.h>

#include <optional>

#include "io/localization/estimation_scenario.h"
#include "solver/setinv/estimation_problem.h"
#include "tools/python/bindings.h"

namespace gesmi::python {
namespace {

std::vector<std::size_t> numbered_from_1(const OutlierSet& set) {
  std::vector<std::size_t> out;
  for (std::size_t i : set) out.push_back(i + 1);
  return out;
}

py::dict level_dict(const EstimationLevel& level) {
  py::dict d;
  d["q"] = level.q;
  d["proved_nonempty"] = level.proved_nonempty();
  d["outlier_sets"] = level.sets.size();
  d["unresolved"] = paving_boxes(level.unresolved);
  d["boxes_examined"] = level.boxes_examined;
  d["box_limit_hit"] = level.box_limit_hit;
  d["time_limit_hit"] = level.time_limit_hit;
  d["seconds"] = level.seconds;
  return d;
}

py::dict hypothesis_dict(int q, const OutlierSetPaving& set) {
  py::dict d;
  d["q"] = q;
  d["outliers"] = numbered_from_1(set.outliers);
  d["proved"] = !set.inner.empty();
  d["inner"] = paving_boxes(set.inner);
  d["boundary"] = paving_boxes(set.boundary);
  std::vector<std::pair<double, double>> hull;
  for (const Interval& x : set.hull) hull.emplace_back(x.lo(), x.hi());
  d["hull"] = hull;
  d["inner_volume"] = set.inner_volume();
  d["outer_volume"] = set.outer_volume();
  return d;
}

}  // namespace

void bind_estimate(py::module_& m) {
  m.def(
      "estimate",
      [](const std::string& scenario) {
        const EstimationProblem problem = io::read_estimation_scenario(scenario);
        EstimationResult r;
        {
          py::gil_scoped_release release;
          r = estimate(problem);
        }
        py::dict out;
        py::list levels, hypotheses;
        for (const EstimationLevel& level : r.levels) {
          levels.append(level_dict(level));
          for (const OutlierSetPaving& set : level.sets) hypotheses.append(hypothesis_dict(level.q, set));
        }
        out["levels"] = levels;
        out["hypotheses"] = hypotheses;
        const std::optional<int> q_star = r.q_star();
        out["q_star"] = q_star ? py::object(py::int_(*q_star)) : py::object(py::none());
        out["epsilon"] = problem.epsilon;
        out["boxes_examined"] = r.boxes_examined();
        out["box_limit_hit"] = r.box_limit_hit();
        out["time_limit_hit"] = r.time_limit_hit();
        out["seconds"] = r.seconds;
        return out;
      },
      py::arg("scenario"),
      "Parameter estimation with outliers from a scenario file (as `gesmi estimate`; seed 004, Example 2): "
      "per q asked for, `levels` (proved_nonempty, unresolved boxes (B, 2, 2), boxes_examined, "
      "box_limit_hit, time_limit_hit, seconds) and one hypothesis per outlier set of exactly q data "
      "(`outliers` numbered from 1 as in the file, `proved` when it has inner boxes, `inner`/`boundary` "
      "boxes (B, 2, 2), `hull`, `inner_volume`, `outer_volume`); `q_star`, the smallest q proved "
      "non-empty (None if none); totals and `seconds`");
}

}  // namespace gesmi::python
