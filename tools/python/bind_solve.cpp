// Solving in Python: solve() over every mode of SolveOptions, the solution with its
// domains as numpy views, and result files (read with their digests checked, or as
// a warm start; written exactly as `gesmi solve` writes them).

#include <algorithm>
#include <limits>

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "io/format_error.h"
#include "io/geodesy.h"
#include "io/files/mission_file.h"
#include "io/files/result_file.h"
#include "io/exports/solve_outputs.h"
#include "io/files/warm_start_file.h"
#include "solver/network/inconsistency_text.h"
#include "solver/solve/solve_mission.h"
#include "solver/solve/unchecked_inputs.h"
#include "tools/python/bindings.h"

namespace gesmi::python {
namespace {

py::tuple constraint(const ConstraintRef& c) {
  return py::make_tuple(c.kind == ConstraintRef::Kind::mark ? "mark" : "gps_fix", c.row);
}

py::dict report_dict(const SolveReport& r) {
  py::dict d;
  d["mode"] = solve_mode_name(r.mode);
  d["consistent"] = r.consistent;
  d["sweeps"] = r.sweeps;
  d["converged"] = r.converged;
  d["message"] = r.message;
  d["minimal_outliers"] = r.minimal_outliers;
  py::list hypotheses;
  for (const auto& h : r.hypotheses) {
    py::list refs;
    for (const ConstraintRef& c : h) refs.append(constraint(c));
    hypotheses.append(refs);
  }
  d["hypotheses"] = hypotheses;
  d["removal_sets"] = r.removal_sets;
  d["work_items"] = r.work_items;
  d["beyond_frame_zone"] = r.beyond_frame_zone;
  py::dict regimes;
  regimes["surface_steps"] = r.regimes.surface_steps;
  regimes["fallback_steps"] = r.regimes.fallback_steps;
  regimes["fallback_times"] = r.regimes.fallback_times;
  regimes["speed_exceeded"] = r.regimes.speed_exceeded;
  regimes["speed_exceeded_times"] = r.regimes.speed_exceeded_times;
  d["regimes"] = regimes;
  d["cold_fallback"] = r.cold_fallback ? py::object(py::str(*r.cold_fallback)) : py::object(py::none());
  if (r.explained_by) {
    py::list refs;
    for (const ConstraintRef& c : *r.explained_by) refs.append(constraint(c));
    d["explained_by"] = refs;
  } else {
    d["explained_by"] = py::none();
  }
  if (r.inconsistency) {
    const Inconsistency& inc = *r.inconsistency;
    py::dict i;
    i["kind"] = inc.kind == Inconsistency::Kind::evolution ? "evolution" : inc.kind == Inconsistency::Kind::fix ? "fix" : "detection";
    i["step"] = inc.step;
    i["time"] = inc.time;
    i["source"] = inc.source ? py::object(constraint(*inc.source)) : py::object(py::none());
    i["before"] = inc.before ? py::object(constraint(*inc.before)) : py::object(py::none());
    i["after"] = inc.after ? py::object(constraint(*inc.after)) : py::object(py::none());
    i["mine"] = inc.mine;
    d["inconsistency"] = i;
  } else {
    d["inconsistency"] = py::none();
  }
  return d;
}

// Mine boxes as a (K, 3, 2) array (a copy: they are small).
py::array_t<double> mine_boxes(const TubeDomains& d) {
  py::array_t<double> out({static_cast<py::ssize_t>(d.mines.size()), py::ssize_t{3}, py::ssize_t{2}});
  auto a = out.mutable_unchecked<3>();
  for (std::size_t i = 0; i < d.mines.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      a(static_cast<py::ssize_t>(i), c, 0) = d.mines[i][c].lo();
      a(static_cast<py::ssize_t>(i), c, 1) = d.mines[i][c].hi();
    }
  return out;
}

// One bound of the waterfall as a dense (N, K) array, NaN where the mine cannot appear
// (a copy: the solution keeps the feasible cells only).
py::array_t<double> dense_waterfall(const Waterfall& w, const std::vector<double>& bound) {
  py::array_t<double> out({static_cast<py::ssize_t>(w.steps), static_cast<py::ssize_t>(w.mines)});
  double* a = out.mutable_data();
  std::fill(a, a + w.steps * w.mines, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t c = 0; c < w.cells(); ++c)
    a[static_cast<std::size_t>(w.step[c]) * w.mines + static_cast<std::size_t>(w.mine[c])] = bound[c];
  return out;
}

io::SolveResult as_result(const MissionSolution& s, const Mission& mission) {
  io::SolveResult r;
  r.solution = s;
  io::record_inputs(r, mission);
  return r;
}

}  // namespace

void bind_solve(py::module_& m) {
  py::class_<MissionSolution>(m, "Solution", "The enclosures of a mission solve (tube, increments, mine boxes, waterfall)")
      .def_property_readonly("time", [](py::object self) { return view(self.cast<MissionSolution&>().time, self); })
      .def_property_readonly("north", [](py::object self) { return interval_view(self.cast<MissionSolution&>().domains.px, self); },
                             "tube on the north axis, (N, 2) [lower, upper] in metres")
      .def_property_readonly("east", [](py::object self) { return interval_view(self.cast<MissionSolution&>().domains.py, self); })
      .def_property_readonly("down", [](py::object self) { return interval_view(self.cast<MissionSolution&>().domains.pz, self); })
      .def_property_readonly("mines", [](const MissionSolution& s) { return mine_boxes(s.domains); },
                             "mine boxes, (K, 3, 2): north, east, down x [lower, upper]")
      .def_property_readonly("waterfall_lower",
                             [](const MissionSolution& s) { return dense_waterfall(s.waterfall, s.waterfall.lower); },
                             "lower slant range (m) at which each mine can appear, (N, K), NaN where it cannot (a copy)")
      .def_property_readonly("waterfall_upper",
                             [](const MissionSolution& s) { return dense_waterfall(s.waterfall, s.waterfall.upper); },
                             "upper slant range (m), (N, K), NaN where the mine cannot appear (a copy)")
      .def_property_readonly("candidates",
                             [](const MissionSolution& s) {
                               std::vector<std::vector<int>> out;
                               for (const std::uint64_t c : s.candidates) {
                                 std::vector<int> mines;
                                 for (int i = 0; i < 64; ++i)
                                   if (c >> i & 1) mines.push_back(i);
                                 out.push_back(mines);
                               }
                               return out;
                             }, "per mark row: the mines it may belong to")
      .def_property_readonly("mark_outlier", [](const MissionSolution& s) { return s.mark_outlier; })
      .def_property_readonly("gps_outlier", [](const MissionSolution& s) { return s.gps_outlier; })
      .def_property_readonly("unchecked",
                             [](const MissionSolution& s) {
                               const UncheckedInputs u = unchecked_inputs(s);
                               py::dict out;
                               out["mines"] = u.mines;
                               out["marks"] = u.marks;
                               out["gps_fixes"] = u.gps_fixes;
                               return out;
                             },
                             "inputs nothing else checks: {'mines', 'marks' (the one mark of each), 'gps_fixes'}; a wrong "
                             "one moves its enclosure with no inconsistency to show it")
      .def_property_readonly("report", [](const MissionSolution& s) { return report_dict(s.report); })
      .def_property_readonly("consistent", [](const MissionSolution& s) { return s.report.consistent; })
      .def_property_readonly("timings_ms", [](const MissionSolution& s) { return s.timings_ms; })
      .def("max_horizontal_width", [](const MissionSolution& s) { return s.domains.max_horizontal_width(); });

  m.def(
      "solve",
      [](Mission& mission, int max_sweeps, double tolerance, std::optional<int> max_outliers,
         std::optional<int> minimal_outliers, bool trust_gps, const MissionSolution* warm_from, bool diagnose,
         bool waterfall) {
        io::validate_mission(mission, "mission");
        io::fill_local_gps(mission, "mission");
        SolveOptions o;
        o.propagation.max_sweeps = max_sweeps;
        o.propagation.tolerance = tolerance;
        if (max_outliers && minimal_outliers) throw io::FormatError("solve: give max_outliers or minimal_outliers, not both");
        if (max_outliers) o.max_outliers = *max_outliers;
        if (minimal_outliers) {
          o.max_outliers = *minimal_outliers;
          o.outlier_mode = OutlierMode::minimal;
        }
        o.trust_gps = trust_gps;
        o.warm_from = warm_from;
        o.diagnose = diagnose;
        o.waterfall = waterfall;
        if (const std::string why = o.validate(); !why.empty()) throw io::FormatError("solve: " + why);
        if (warm_from)
          if (const std::string why = warm_start_problem(mission, *warm_from); !why.empty())
            throw io::FormatError("solve: warm_from: " + why);
        py::gil_scoped_release release;
        return solve_mission(mission, o);
      },
      py::arg("mission"), py::arg("max_sweeps") = 100, py::arg("tolerance") = 1e-3, py::arg("max_outliers") = py::none(),
      py::arg("minimal_outliers") = py::none(), py::arg("trust_gps") = false, py::arg("warm_from") = nullptr,
      py::arg("diagnose") = true, py::arg("waterfall") = true,
      "Interval solve of a mission (as `gesmi solve`): cold, warm (warm_from: a solution of this mission "
      "before marks were added), or tolerating outliers (max_outliers: guaranteed while at most Q inputs are "
      "wrong; minimal_outliers: conditional)");
  m.def("read_result", [](const std::string& path) { return io::read_result(path).solution; }, py::arg("path"),
        "Reads a result file, its digests checked");
  m.def("read_warm_start", py::overload_cast<const std::string&, const Mission&>(&io::read_warm_start), py::arg("path"),
        py::arg("mission"),
        "Reads a result file as the warm start of a solve of `mission` (as `gesmi solve --from`)");
  m.def(
      "write_result",
      [](const MissionSolution& s, const Mission& mission, const std::string& path, const std::string& mission_name,
         bool png, bool geojson, bool mines_csv) {
        return io::write_solve_outputs(as_result(s, mission), mission, path, mission_name,
                                       io::SolveSiblings{mines_csv, geojson, png});
      },
      py::arg("solution"), py::arg("mission"), py::arg("path"), py::arg("mission_name") = "mission",
      py::arg("png") = false, py::arg("geojson") = false, py::arg("mines_csv") = false,
      "Writes the result, and the siblings asked for, exactly as `gesmi solve` does; returns the paths written");
}

}  // namespace gesmi::python
