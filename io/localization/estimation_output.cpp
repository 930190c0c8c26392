#include "io/localization/estimation_output.h"

#include <cstdio>
#include <filesystem>

#include "io/format_error.h"
#include "io/imports/csv_number.h"
#include "io/output/atomic_output.h"
#include "io/report/report_json.h"

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

std::string format(const char* pattern, auto... values) {
  char buffer[512];
  std::snprintf(buffer, sizeof buffer, pattern, values...);
  return buffer;
}

}  // namespace

std::string estimation_summary(const EstimationProblem& p, const EstimationResult& r) {
  std::string s = format("scenario %s: Gaussian density, %zu interval data, epsilon %g\n",
                         p.name.empty() ? "(unnamed)" : p.name.c_str(), p.t.size(), p.epsilon);
  for (const EstimationLevel& level : r.levels) {
    std::size_t unproved = 0;
    for (const OutlierSetPaving& set : level.sets) unproved += set.inner.empty();
    s += format("q = %d: %zu outlier sets of exactly %d data proved (inner boxes)", level.q, level.sets.size() - unproved, level.q);
    s += unproved ? format(", %zu more fit boundary boxes only", unproved) : std::string();
    s += format("; %zu boxes examined, %.3f s%s\n", level.boxes_examined, level.seconds,
                level.limit_hit ? "  WARNING: a box limit was hit" : "");
    for (const OutlierSetPaving& set : level.sets)
      if (!set.inner.empty())
        s += format("  outliers %-14s p1 [%.4f, %.4f]  p2 [%.4f, %.4f]  inner %zu (area %.5g), boundary %zu (area %.5g)\n",
                    set_text(set.outliers).c_str(), set.hull[0].lo(), set.hull[0].hi(), set.hull[1].lo(), set.hull[1].hi(),
                    set.inner.size(), set.inner_volume(), set.boundary.size(), set.outer_volume() - set.inner_volume());
  }
  s += format("%.3f s in all\n", r.seconds);
  return s;
}

nlohmann::json estimation_summary_json(const EstimationProblem& p, const EstimationResult& r) {
  nlohmann::json hypotheses = nlohmann::json::array(), levels = nlohmann::json::array();
  for (const EstimationLevel& level : r.levels) {
    levels.push_back({{"q", level.q}, {"outlier_sets", level.sets.size()}, {"proved_nonempty", level.proved_nonempty()},
                      {"boxes_examined", level.boxes_examined}, {"limit_hit", level.limit_hit}, {"seconds", level.seconds}});
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
  return {{"scenario", p.name},
          {"data_numbering", "position in the scenario's data, from 1"},
          {"epsilon", p.epsilon},
          {"levels", levels},
          {"hypotheses", hypotheses},
          {"timing", {{"seconds", r.seconds}}}};
}

std::string estimation_boxes_csv(const EstimationResult& r) {
  std::string s = "q,outliers,kind,p1_lo,p1_hi,p2_lo,p2_hi\n";
  for (const EstimationLevel& level : r.levels)
    for (const OutlierSetPaving& set : level.sets)
      for (const auto* paving : {&set.inner, &set.boundary})
        for (std::size_t i = 0; i < paving->size(); ++i) {
          const auto b = paving->box(i);
          s += std::to_string(level.q) + ",\"" + set_text(set.outliers) + "\"," + (paving == &set.inner ? "inner" : "boundary");
          for (int d = 0; d < 2; ++d) s += "," + format_number(b[d].lo()) + "," + format_number(b[d].hi());
          s += "\n";
        }
  return s;
}

std::vector<std::string> estimation_output_files(const std::string& folder) {
  const std::string base = (std::filesystem::path(folder) / "").string();
  return {base + "summary.txt", base + "summary.json", base + "boxes.csv"};
}

std::vector<std::string> write_estimation_outputs(const std::string& folder, const EstimationProblem& p,
                                                  const EstimationResult& r) {
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec) throw FormatError(folder + ": cannot create folder: " + ec.message());
  const std::vector<std::string> files = estimation_output_files(folder);
  write_text_file(files[0], estimation_summary(p, r));
  write_text_file(files[1], estimation_summary_json(p, r).dump(2) + "\n");
  write_text_file(files[2], estimation_boxes_csv(r));
  return files;
}

}  // namespace gesmi::io
