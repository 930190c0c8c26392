#include "io/localization/estimation_output.h"

#include <cstdio>
#include <filesystem>
#include <optional>

#include "io/format_error.h"
#include "io/text/csv_number.h"
#include "io/output/atomic_output.h"
#include "io/output/output_set.h"
#include "io/report/report_json.h"
#include "io/text/formatted.h"

namespace gesmi::io {
namespace {

// Data numbered from 1, as in the scenario file and the paper.
nlohmann::json numbered(const OutlierSet& set) {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t i : set) out.push_back(i + 1);
  return out;
}

std::string set_text(const OutlierSet& set) {
  std::string s;
  for (std::size_t i : set) s += (s.empty() ? "" : ",") + std::to_string(i + 1);
  return "{" + s + "}";
}

constexpr const char* kLimitConsequence =
    "open boxes were kept unbisected (levels after it keep their prior box whole); the boxes still enclose "
    "every j^-1(q), but fewer sets may be proved; raise it in the scenario's solver section to prove more\n";

std::string limit_text(const EstimationLevel& level) {
  if (level.box_limit_hit && level.time_limit_hit) return "  WARNING: the box and time limits were hit";
  if (level.box_limit_hit) return "  WARNING: the box limit was hit";
  if (level.time_limit_hit) return "  WARNING: the time limit was hit";
  return {};
}

}  // namespace

std::string estimation_summary(const EstimationProblem& p, const EstimationResult& r) {
  std::string s = formatted("scenario %s: Gaussian density, %zu interval data, epsilon %g\n",
                            p.name.empty() ? "(unnamed)" : p.name.c_str(), p.t.size(), p.epsilon);
  for (const EstimationLevel& level : r.levels) {
    std::size_t unproved = 0;
    for (const OutlierSetPaving& set : level.sets) unproved += set.inner.empty();
    s += formatted("q = %d: %zu outlier sets of exactly %d data proved (inner boxes)", level.q,
                   level.sets.size() - unproved, level.q);
    s += unproved ? formatted(", %zu more fit boundary boxes only", unproved) : std::string();
    s += level.unresolved.empty() ? std::string()
                                  : formatted(", %zu boxes fit too many sets to list", level.unresolved.size());
    s += formatted("; %zu boxes examined, %.3f s%s\n", level.boxes_examined, level.seconds, limit_text(level).c_str());
    for (const OutlierSetPaving& set : level.sets)
      if (!set.inner.empty())
        s += formatted(
            "  outliers %-14s p1 [%.4f, %.4f]  p2 [%.4f, %.4f]  inner %zu (area %.5g), boundary %zu (area %.5g)\n",
            set_text(set.outliers).c_str(), set.hull[0].lo(), set.hull[0].hi(), set.hull[1].lo(), set.hull[1].hi(),
            set.inner.size(), set.inner_volume(), set.boundary.size(), set.outer_volume() - set.inner_volume());
  }
  if (r.box_limit_hit())
    s += formatted("WARNING: the box limit (solver.max_boxes: %zu) was hit: ", p.max_boxes) + kLimitConsequence;
  if (r.time_limit_hit())
    s += "WARNING: the time limit (solver.max_seconds: " + format_number(p.max_seconds) +
         " s) was hit: " + kLimitConsequence;
  s += formatted("%zu boxes examined, %.3f s in all\n", r.boxes_examined(), r.seconds);
  return s;
}

nlohmann::json estimation_summary_json(const EstimationProblem& p, const EstimationResult& r) {
  nlohmann::json hypotheses = nlohmann::json::array(), levels = nlohmann::json::array();
  for (const EstimationLevel& level : r.levels) {
    levels.push_back({{"q", level.q}, {"outlier_sets", level.sets.size()}, {"proved_nonempty", level.proved_nonempty()},
                      {"unresolved_boxes", level.unresolved.size()}, {"boxes_examined", level.boxes_examined},
                      {"limit_hit", level.limit_hit()}, {"box_limit_hit", level.box_limit_hit},
                      {"time_limit_hit", level.time_limit_hit}, {"seconds", level.seconds}});
    for (const OutlierSetPaving& set : level.sets) {
      nlohmann::json hull = nlohmann::json::array();
      for (const Interval& x : set.hull) hull.push_back(interval_json(x));
      hypotheses.push_back({{"q", level.q},
                            {"outliers", numbered(set.outliers)},
                            {"outlier_sets", nlohmann::json::array({numbered(set.outliers)})},
                            {"proved", !set.inner.empty()},
                            {"inner_boxes", set.inner.size()},
                            {"boundary_boxes", set.boundary.size()},
                            {"hull", hull},
                            {"inner_volume", set.inner_volume()},
                            {"outer_volume", set.outer_volume()}});
    }
  }
  const std::optional<int> q_star = r.q_star();
  return {{"scenario", p.name},
          {"data_numbering", "position in the scenario's data, from 1"},
          {"epsilon", p.epsilon},
          {"limits", {{"max_boxes", p.max_boxes}, {"max_seconds", p.max_seconds}}},
          {"box_limit_hit", r.box_limit_hit()},
          {"time_limit_hit", r.time_limit_hit()},
          {"q_star", q_star ? nlohmann::json(*q_star) : nlohmann::json(nullptr)},
          {"levels", levels},
          {"hypotheses", hypotheses},
          {"timing", {{"seconds", r.seconds}, {"boxes_examined", r.boxes_examined()}}}};
}

std::string estimation_boxes_csv(const EstimationResult& r) {
  std::string s = "q,outliers,kind,p1_lo,p1_hi,p2_lo,p2_hi\n";
  const auto add = [&](int q, const std::string& outliers, const char* kind, const Paving& paving) {
    for (std::size_t i = 0; i < paving.size(); ++i) {
      const auto b = paving.box(i);
      s += std::to_string(q) + ",\"" + outliers + "\"," + kind;
      for (int d = 0; d < 2; ++d) s += "," + format_number(b[d].lo()) + "," + format_number(b[d].hi());
      s += "\n";
    }
  };
  for (const EstimationLevel& level : r.levels) {
    for (const OutlierSetPaving& set : level.sets) {
      add(level.q, set_text(set.outliers), "inner", set.inner);
      add(level.q, set_text(set.outliers), "boundary", set.boundary);
    }
    add(level.q, "?", "unresolved", level.unresolved);  // may hold any set: part of the enclosure
  }
  return s;
}

std::vector<std::string> estimation_output_files(const std::string& folder) {
  const std::string base = (std::filesystem::path(folder) / "").string();
  return {base + "summary.txt", base + "summary.json", base + "boxes.csv"};
}

std::vector<std::string> write_estimation_outputs(const std::string& folder, const EstimationProblem& p,
                                                  const EstimationResult& r) {
  create_output_folder(folder);
  const std::vector<std::string> files = estimation_output_files(folder);
  write_text_file(files[0], estimation_summary(p, r));
  write_text_file(files[1], estimation_summary_json(p, r).dump(2) + "\n");
  write_text_file(files[2], estimation_boxes_csv(r));
  return files;
}

}  // namespace gesmi::io
