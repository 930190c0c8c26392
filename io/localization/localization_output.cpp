#include "io/localization/localization_output.h"

#include <cstdio>
#include <filesystem>

#include "io/output/atomic_output.h"
#include "io/output/output_set.h"
#include "io/format_error.h"
#include "io/text/csv_number.h"
#include "io/localization/localization_hdf5.h"
#include "io/localization/localization_json.h"
#include "io/plot/localization_picture.h"
#include "solver/setinv/localization/range_data.h"
#include "solver/model/angles.h"
#include "io/text/formatted.h"

namespace gesmi::io {
namespace {

constexpr std::size_t kMaxListedSets = 64;  // component_outliers' default max_sets

/// Name of datum i: its number in the scenario file and its sensor's name.
std::string datum_name(const LocalizationProblem& p, std::size_t i) {
  const std::string sensor = i < p.ranges.size() ? p.range_sensors[p.ranges[i].sensor].name
                                                 : p.bearing_sensors[p.bearings[i - p.ranges.size()].sensor].name;
  return "#" + std::to_string(p.file_number(i)) + ":" + sensor;
}

std::string names(const LocalizationProblem& p, const OutlierSet& set) {
  std::string s;
  for (std::size_t i : set) s += (s.empty() ? "" : " ") + datum_name(p, i);
  return s.empty() ? "none" : s;
}

// Determined: the one set, proved. Otherwise what every set agrees on, the sets
// proved present and how many may be.
std::string outlier_lines(const LocalizationProblem& p, const LocalizationHypothesis& h) {
  const ComponentOutliers& o = h.outliers;
  if (o.determined) return "     outliers: " + names(p, o.outliers) + "  (the only outlier set, proved)\n";
  std::string s = "     agreed outliers: " + names(p, o.outliers) + "\n     outlier sets:";
  for (const OutlierSet& set : o.sets) s += " {" + (set.empty() ? std::string() : names(p, set)) + "}";
  if (o.sets.empty()) s += " none proved";
  if (o.sets_complete)
    s += formatted("  (all %zu possible sets proved)\n", o.possible_sets);
  else if (o.possible_sets > kMaxListedSets)
    s += formatted("  (more than %zu possible sets, %zu proved)\n", kMaxListedSets, o.sets.size());
  else
    s += formatted("  (%zu possible sets, %zu proved)\n", o.possible_sets, o.sets.size());
  return s;
}

std::string safety_lines(const LocalizationProblem& p, const LocalizationResult& r) {
  if (r.safety.empty()) return {};
  std::string s = "safety of each datum (Remark 6 of seed 004: vol S / vol S without the datum):\n";
  for (std::size_t i = 0; i < r.safety.size(); ++i)
    s += formatted("  %-16s [%.4f, %.4f]%s\n", datum_name(p, i).c_str(), r.safety[i].safety.lo(),
                   r.safety[i].safety.hi(), r.safety[i].limit_hit ? "  (a limit was hit)" : "");
  return s;
}

/// What explains a range datum: a wall, "beyond" (a "no echo": no wall within range), "-" nothing.
std::string range_association(int wall) {
  if (wall == kNoWallInRange) return "beyond";
  return wall < 0 ? "-" : "w" + std::to_string(wall);
}

std::string association_text(const LocalizationProblem& p, const LocalizationHypothesis& h) {
  std::string s;
  for (std::size_t i = 0; i < h.range_walls.size(); ++i)
    s += (s.empty() ? "" : " ") + datum_name(p, i) + ":" + range_association(h.range_walls[i]);
  for (std::size_t m = 0; m < h.bearing_landmarks.size(); ++m)
    s += (s.empty() ? "" : " ") + datum_name(p, p.ranges.size() + m) + ":" +
         (h.bearing_landmarks[m] < 0 ? "-" : "L" + std::to_string(h.bearing_landmarks[m]));
  return s;
}

std::string interval_text(const Interval& x, double unit) {
  return formatted("[%.4f, %.4f]", x.lo() * unit, x.hi() * unit);
}

}  // namespace

std::string localization_summary(const LocalizationProblem& p, const LocalizationResult& r) {
  std::string s = formatted("scenario %s: %zu range and %zu bearing measurements, %zu walls, %zu landmarks\n",
                            p.name.empty() ? "(unnamed)" : p.name.c_str(), p.ranges.size(), p.bearings.size(),
                            p.map.walls.size(), p.map.landmarks.size());
  if (r.gomne) {
    const GomneResult& g = *r.gomne;
    s += formatted("policy: minimal number of outliers (GOMNE), epsilon0 %g, epsilon_min %g\n", p.epsilon,
                   p.epsilon_min);
    for (const GomneStep& step : g.steps)
      s += formatted("  SIVIA(q=%d) epsilon %-9g inner %8zu  boundary %8zu  boxes examined %10zu  %.3f s\n", step.q,
                     step.epsilon, step.inner_boxes, step.boundary_boxes, step.boxes_visited, step.seconds);
    if (!g.found)
      s += "no consistent pose found for any number of outliers tried\n";
    else if (g.exact() && g.q_star == 0)
      s += "minimal number of outliers q* = 0: every measurement is consistent\n";
    else if (g.exact())
      s += formatted("minimal number of outliers q* = %d (every q < %d proved impossible)\n", g.q_star, g.q_star);
    else
      s += formatted("number of outliers between %d and %d (epsilon_min reached: outer enclosure only)\n", g.q_lower,
                     g.q_star);
    if (g.q_used != g.q_star && g.found)
      s += formatted("paving characterises S_%d (extra margin of %d outliers)\n", g.q_used, p.extra_outliers);
  } else {
    s += formatted("policy: fixed, up to %d outliers allowed; epsilon %g; %zu boxes examined\n", p.outliers, p.epsilon,
                   r.paving.report.boxes_visited);
  }
  const SiviaReport& rep = r.paving.report;
  s += formatted("paving: %zu inner boxes (volume %.6g), %zu boundary boxes (volume %.6g); %.3f s in all\n",
                 r.paving.inner.size(), r.paving.inner.volume(), r.paving.boundary.size(), r.paving.boundary.volume(),
                 r.seconds);
  if (r.limit_hit())
    s += formatted(
        "WARNING: a limit was hit (solver.max_boxes: %zu boxes, solver.max_seconds: %s s): undetermined boxes "
        "were kept unbisected (still an enclosure); raise them in the scenario's solver section to bisect "
        "further\n",
        p.max_boxes, format_number(p.max_seconds).c_str());
  if (rep.boxes_unsplittable > 0)
    s += formatted(
        "NOTE: %zu undetermined boxes were too narrow for doubles to bisect (epsilon is below the spacing of "
        "doubles there): kept as boundary boxes\n",
        rep.boxes_unsplittable);
  s += formatted("hypotheses (connected components): %zu\n", r.hypotheses.size());
  for (std::size_t k = 0; k < r.hypotheses.size(); ++k) {
    const LocalizationHypothesis& h = r.hypotheses[k];
    const Box& b = h.component.hull;
    s += formatted("  #%zu x %s  y %s  theta %s deg  (%zu inner, %zu boundary boxes)%s\n", k + 1,
                   interval_text(b[0], 1).c_str(), interval_text(b[1], 1).c_str(),
                   interval_text(b[2], kDegreesPerRadian).c_str(), h.component.inner.size(),
                   h.component.boundary.size(), h.contains_truth ? "  <- holds the true pose" : "");
    s += outlier_lines(p, h);
    s += "     associations: " + association_text(p, h) + "\n";
  }
  s += safety_lines(p, r);
  if (p.truth)
    s += formatted("true pose (%.4f, %.4f, %.3f deg) %s\n", p.truth->x, p.truth->y, p.truth->theta * kDegreesPerRadian,
                   r.truth_enclosed ? "is enclosed" : "is NOT enclosed");
  return s;
}

std::string paving_csv(const Paving& paving, const std::vector<int>& component_of_box) {
  std::string s = "component,x_lo,x_hi,y_lo,y_hi,theta_lo_rad,theta_hi_rad\n";
  for (std::size_t i = 0; i < paving.size(); ++i) {
    const auto b = paving.box(i);
    s += std::to_string(component_of_box[i]);
    for (int d = 0; d < 3; ++d)
      s += "," + format_number(b[d].lo()) + "," + format_number(b[d].hi());  // exact, shortest
    s += "\n";
  }
  return s;
}

std::string components_csv(const LocalizationProblem& p, const LocalizationResult& r) {
  std::string s =
      "component,inner_boxes,boundary_boxes,x_lo,x_hi,y_lo,y_hi,theta_lo_rad,theta_hi_rad,inner_volume,boundary_volume,"
      "outliers,outliers_determined,associations,holds_truth\n";
  for (std::size_t k = 0; k < r.hypotheses.size(); ++k) {
    const LocalizationHypothesis& h = r.hypotheses[k];
    const Box& b = h.component.hull;
    s += formatted("%zu,%zu,%zu", k + 1, h.component.inner.size(), h.component.boundary.size());
    for (int d = 0; d < 3; ++d) s += "," + format_number(b[d].lo()) + "," + format_number(b[d].hi());
    s += "," + format_number(h.component.inner_volume) + "," + format_number(h.component.boundary_volume) + ",";
    s += "\"" + names(p, h.outliers.outliers) + "\"," + (h.outliers.determined ? "1" : "0") + ",\"" +
         association_text(p, h) + "\"," + (h.contains_truth ? "1" : "0") + "\n";
  }
  return s;
}

std::vector<std::string> localization_output_files(const std::string& folder) {
  const std::string base = (std::filesystem::path(folder) / "").string();
  return {base + "inner.csv",   base + "boundary.csv", base + "components.csv", base + "summary.txt",
          base + "summary.json", base + "paving.h5",  base + "paving.png"};
}

std::vector<std::string> write_localization_outputs(const std::string& folder, const LocalizationProblem& p,
                                                    const LocalizationResult& r) {
  create_output_folder(folder);
  std::vector<int> inner_component(r.paving.inner.size(), 0), boundary_component(r.paving.boundary.size(), 0);
  for (std::size_t k = 0; k < r.hypotheses.size(); ++k) {
    for (std::size_t i : r.hypotheses[k].component.inner) inner_component[i] = static_cast<int>(k + 1);
    for (std::size_t i : r.hypotheses[k].component.boundary) boundary_component[i] = static_cast<int>(k + 1);
  }
  const std::vector<std::string> files = localization_output_files(folder);
  std::vector<std::string> written;
  const auto text = [&](const std::string& path, const std::string& content) {
    write_text_file(path, content);
    written.push_back(path);
  };
  text(files[0], paving_csv(r.paving.inner, inner_component));
  text(files[1], paving_csv(r.paving.boundary, boundary_component));
  text(files[2], components_csv(p, r));
  text(files[3], localization_summary(p, r));
  text(files[4], localization_summary_json(p, r).dump(2) + "\n");
  write_localization_hdf5(files[5], p, r);
  written.push_back(files[5]);
  write_localization_picture(files[6], p, r);
  written.push_back(files[6]);
  return written;
}

}  // namespace gesmi::io
