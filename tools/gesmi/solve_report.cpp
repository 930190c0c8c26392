#include "tools/gesmi/solve_report.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>

#include "io/text/csv_number.h"
#include "solver/network/inconsistency_text.h"
#include "solver/solve/unchecked_inputs.h"

namespace gesmi::cli {

namespace {

std::string times_text(const std::vector<double>& times, std::size_t count) {
  std::string text;
  for (const double t : times) text += (text.empty() ? "" : ", ") + io::format_number(std::round(t * 10.0) / 10.0) + " s";
  return count > times.size() ? text + ", ..." : text;
}

}  // namespace

void print_regime_notes(const StepRegimeReport& r) {
  if (r.fallback_steps > 0)
    std::fprintf(stderr,
                 "gesmi solve: warning: at %zu steps the readings change faster than max_jerk (or the rate bounds) allow, "
                 "from t = %s: those steps are bounded by the speed alone (max_speed, surface_max_speed); if the robot "
                 "really moved so, raise the bound in --config, else check those readings\n",
                 r.fallback_steps, times_text(r.fallback_times, r.fallback_steps).c_str());
  if (r.speed_exceeded > 0)
    std::fprintf(stderr,
                 "gesmi solve: warning: at %zu samples the readings exceed the speed bound (max_speed, or surface_max_speed "
                 "near the surface), at t = %s: the bounds resting on it do not hold there; raise it in --config\n",
                 r.speed_exceeded, times_text(r.speed_exceeded_times, r.speed_exceeded).c_str());
}

void print_unchecked_notes(const MissionSolution& s) {
  const UncheckedInputs u = unchecked_inputs(s);
  if (!u.mines.empty()) {
    std::string mines, marks;
    for (std::size_t i = 0; i < u.mines.size(); ++i) {
      mines += (i ? ", " : "") + std::to_string(u.mines[i]);
      marks += (i ? ", " : "") + std::to_string(u.marks[i]);
    }
    const bool one = u.mines.size() == 1;
    const bool tolerant = s.report.mode == SolveMode::outliers || s.report.mode == SolveMode::minimal_outliers;
    std::fprintf(stderr, "gesmi solve: warning: %s %s rest%s on one mark%s (mark%s %s): a wrong mark there cannot be detected%s\n",
                 one ? "mine" : "mines", mines.c_str(), one ? "s" : "", one ? "" : " each", one ? "" : "s", marks.c_str(),
                 tolerant ? "" : "; --max-outliers 1 keeps the mines enclosed even if one such mark is wrong");
  }
  if (!u.gps_fixes.empty())
    std::fprintf(stderr,
                 "gesmi solve: warning: GPS fix %zu is the mission's only one: nothing else checks it, and a wrong fix "
                 "would move the whole tube undetected\n",
                 u.gps_fixes.front());
}

void print_solve_notes(const MissionSolution& s) {
  const SolveReport& r = s.report;
  if (r.cold_fallback) std::fprintf(stderr, "gesmi solve: %s; solving cold\n", r.cold_fallback->c_str());
  if (r.beyond_frame_zone == std::numeric_limits<double>::infinity())
    std::fprintf(stderr,
                 "gesmi solve: warning: the tube is unbounded in places (no fix bounds it), so it cannot show that the "
                 "robot stayed within the local frame's zone; the frame's bounds there assume it did\n");
  else if (r.beyond_frame_zone > 0.0)
    std::fprintf(stderr,
                 "gesmi solve: warning: the tube reaches %.0f m from the origin, beyond the local frame's zone; the frame's "
                 "bounds there assume the robot stayed within it: import the log again with an origin nearer the mission "
                 "(--origin LAT,LON)\n",
                 r.beyond_frame_zone);
  print_regime_notes(r.regimes);
  print_unchecked_notes(s);
  if (!r.consistent || r.minimal_outliers == 0 || r.hypotheses.empty()) return;
  std::fprintf(stderr, "gesmi solve: consistent with %d outlier(s); %zu hypothesis(es) restore consistency:\n",
               r.minimal_outliers, r.hypotheses.size());
  for (const auto& h : r.hypotheses) {
    std::string names;
    for (const ConstraintRef& c : h) names += (names.empty() ? "" : ", ") + describe(c);
    std::fprintf(stderr, "  without %s\n", names.c_str());
  }
}

void print_solve_summary(const Mission& m, const MissionSolution& s, const std::vector<std::string>& written) {
  // Marks without a mine number, in time order: the mines still possible.
  std::vector<std::size_t> rows(m.mark_count());
  std::iota(rows.begin(), rows.end(), std::size_t{0});
  std::stable_sort(rows.begin(), rows.end(), [&](std::size_t a, std::size_t b) { return m.mark_time[a] < m.mark_time[b]; });
  for (const std::size_t j : rows) {
    if (m.mark_mine[j] >= 0) continue;
    std::string mines;
    for (int i = 0; i < m.mine_count; ++i)
      if (s.candidates[j] >> i & 1) mines += (mines.empty() ? "" : ", ") + std::to_string(i);
    const int count = std::popcount(s.candidates[j]);
    std::printf("mark %zu at t = %.1f s: %s %s\n", j, m.mark_time[j], count == 1 ? "mine" : (count == 0 ? "no mine" : "mines"),
                mines.c_str());
  }
  std::string files;
  for (const std::string& f : written) files += (files.empty() ? "" : ", ") + f;
  std::printf("%s: %s after %d sweeps, largest horizontal tube width %.1f m, written to %s\n",
              solve_mode_name(s.report.mode), s.report.consistent ? "consistent" : "INCONSISTENT", s.report.sweeps,
              s.domains.max_horizontal_width(), files.c_str());
}

}  // namespace gesmi::cli
