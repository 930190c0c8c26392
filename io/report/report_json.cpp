#include "io/report/report_json.h"

#include <charconv>
#include <cmath>

#include "io/time/utc_time.h"
#include "solver/solve/unchecked_inputs.h"

namespace gesmi::io {

using nlohmann::json;

namespace {

void append_json(const json& value, std::string& out) {
  switch (value.type()) {
    case json::value_t::number_float: {
      const double x = value.get<double>();
      if (!std::isfinite(x)) {
        out += "null";  // as nlohmann writes them; reports carry infinities as "inf" strings
        return;
      }
      char text[32];
      out.append(text, std::to_chars(text, text + sizeof text, x).ptr);
      return;
    }
    case json::value_t::array: {
      out += '[';
      bool first = true;
      for (const json& item : value) {
        if (!first) out += ',';
        first = false;
        append_json(item, out);
      }
      out += ']';
      return;
    }
    case json::value_t::object: {
      out += '{';
      bool first = true;
      for (const auto& [key, item] : value.items()) {
        if (!first) out += ',';
        first = false;
        out += json(key).dump(-1, ' ', false, json::error_handler_t::replace);
        out += ':';
        append_json(item, out);
      }
      out += '}';
      return;
    }
    default:
      // Paths and messages need not be UTF-8 (a file name is bytes): invalid bytes
      // become U+FFFD rather than an exception after the outputs are written.
      out += value.dump(-1, ' ', false, json::error_handler_t::replace);
  }
}

}  // namespace

std::string dump_shortest(const json& value) {
  std::string out;
  append_json(value, out);
  return out;
}

json number_json(double x) {
  if (std::isnan(x)) return nullptr;
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  return x;
}

json interval_json(const Interval& x) {
  if (x.is_empty()) return nullptr;
  return json::array({number_json(x.lo()), number_json(x.hi())});
}

json box_json(const Vec3I& box) { return json::array({interval_json(box[0]), interval_json(box[1]), interval_json(box[2])}); }

json constraint_json(const ConstraintRef& c) {
  return {{"kind", c.kind == ConstraintRef::Kind::mark ? "mark" : "gps_fix"}, {"row", c.row}};
}

namespace {

json optional_constraint(const std::optional<ConstraintRef>& c) { return c ? constraint_json(*c) : json(nullptr); }

json constraints_json(const std::vector<ConstraintRef>& list) {
  json out = json::array();
  for (const ConstraintRef& c : list) out.push_back(constraint_json(c));
  return out;
}

const char* kind_name(Inconsistency::Kind kind) {
  switch (kind) {
    case Inconsistency::Kind::evolution: return "evolution";
    case Inconsistency::Kind::fix: return "fix";
    case Inconsistency::Kind::detection: return "detection";
  }
  return "evolution";
}

}  // namespace

json inconsistency_json(const Inconsistency& c, const std::string& text) {
  json out = {{"text", text}, {"kind", kind_name(c.kind)}, {"step", c.step}, {"time", c.time},
              {"source", optional_constraint(c.source)}};
  switch (c.kind) {
    case Inconsistency::Kind::evolution: {
      static const char* const axes[] = {"north", "east", "down"};
      out["axis"] = c.axis >= 0 && c.axis < 3 ? json(axes[c.axis]) : json(nullptr);
      out["before"] = optional_constraint(c.before);
      out["after"] = optional_constraint(c.after);
      break;
    }
    case Inconsistency::Kind::fix:
      out["fix_box"] = box_json(c.fix_box);
      out["tube"] = box_json(c.tube);
      break;
    case Inconsistency::Kind::detection: {
      out["mine"] = c.mine >= 0 ? json(c.mine) : json(nullptr);
      if (c.mine >= 0) out["mine_box"] = box_json(c.mine_box);
      out["tube"] = box_json(c.tube);
      json distances = json::array();
      for (const auto& [mine, distance] : c.candidate_distances)
        distances.push_back({{"mine", mine}, {"distance_m", interval_json(distance)}});
      out["candidate_distances"] = distances;
      break;
    }
  }
  return out;
}

json mission_json(const Mission& m) {
  json filled = json::array();
  for (std::size_t c = 0; c < nav_channels().size(); ++c) {
    const ChannelFill& f = m.half_widths.fill[c];
    if (f.samples() == 0) continue;
    filled.push_back({{"channel", nav_channels()[c].name},
                      {"key", f.key},
                      {"before_first_reading", f.before},
                      {"between_readings", f.between},
                      {"after_last_reading", f.after},
                      {"first_reading_s", f.first_reading},
                      {"last_reading_s", f.last_reading}});
  }
  return {{"samples", m.size()},
          {"filled", filled},
          {"duration_s", m.size() ? m.time.back() - m.time.front() : 0.0},
          {"gps_fixes", m.gps_time.size()},
          {"marks", m.mark_count()},
          {"mines", m.mine_count},
          {"epoch_utc", m.epoch ? json(format_iso8601(*m.epoch)) : json(nullptr)}};
}

namespace {

json regimes_json(const StepRegimeReport& r) {
  return {{"surface_steps", r.surface_steps},
          {"fallback_steps", r.fallback_steps},
          {"fallback_times_s", r.fallback_times},
          {"speed_exceeded_samples", r.speed_exceeded},
          {"speed_exceeded_times_s", r.speed_exceeded_times}};
}

}  // namespace

json solve_json(const Mission& m, const MissionSolution& s) {
  const SolveReport& r = s.report;
  json out = {{"status", r.consistent ? "consistent" : "inconsistent"},
              {"mode", solve_mode_name(r.mode)},
              {"sweeps", r.sweeps},
              {"converged", r.converged},
              {"steps", m.size()},
              {"mark_count", m.mark_count()},
              {"mine_count", m.mine_count},
              {"max_tube_width_m", number_json(s.domains.max_horizontal_width())},
              {"work_items", r.work_items},
              {"beyond_frame_zone_m", number_json(r.beyond_frame_zone)},
              {"regimes", regimes_json(r.regimes)},
              {"cold_fallback", r.cold_fallback ? json(*r.cold_fallback) : json(nullptr)}};
  out["inconsistency"] = r.inconsistency ? inconsistency_json(*r.inconsistency, r.message) : json(nullptr);
  out["explained_by"] = r.explained_by ? constraints_json(*r.explained_by) : json(nullptr);
  json hypotheses = json::array();
  for (const auto& h : r.hypotheses) hypotheses.push_back(constraints_json(h));
  json flagged_marks = json::array(), flagged_fixes = json::array();
  for (std::size_t j = 0; j < s.mark_outlier.size(); ++j)
    if (s.mark_outlier[j]) flagged_marks.push_back(j);
  for (std::size_t i = 0; i < s.gps_outlier.size(); ++i)
    if (s.gps_outlier[i]) flagged_fixes.push_back(i);
  out["outliers"] = {{"minimal", r.minimal_outliers}, {"hypotheses", hypotheses}, {"marks", flagged_marks},
                     {"gps_fixes", flagged_fixes}};
  json marks = json::array();
  for (std::size_t j = 0; j < m.mark_count() && j < s.candidates.size(); ++j) {
    json candidates = json::array();
    for (int i = 0; i < m.mine_count; ++i)
      if (s.candidates[j] >> i & 1) candidates.push_back(i);
    marks.push_back({{"row", j},
                     {"time", m.mark_time[j]},
                     {"mine", m.mark_mine[j] >= 0 ? json(m.mark_mine[j]) : json(nullptr)},
                     {"candidates", candidates},
                     {"outlier", j < s.mark_outlier.size() && s.mark_outlier[j] != 0}});
  }
  out["marks"] = marks;
  const UncheckedInputs unchecked = unchecked_inputs(s);
  out["unchecked"] = {{"mines", unchecked.mines}, {"marks", unchecked.marks}, {"gps_fixes", unchecked.gps_fixes}};
  json mines = json::array();
  for (std::size_t i = 0; i < s.domains.mines.size(); ++i) mines.push_back({{"mine", i}, {"box_m", box_json(s.domains.mines[i])}});
  out["mines"] = mines;
  return out;
}

}  // namespace gesmi::io
