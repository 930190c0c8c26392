#include "io/files/result_file.h"

#include <array>
#include <cmath>
#include <limits>
#include <map>

#include "io/output/atomic_output.h"
#include "io/text/csv_number.h"
#include "io/format_error.h"
#include "io/files/mission_digest.h"
#include "io/io_version.h"
#include "io/files/model_attributes.h"
#include "io/files/provenance.h"
#include "io/time/utc_time.h"
#include "io/hdf5/h5_digest.h"
#include "io/hdf5/h5_file.h"
#include "io/hdf5/h5_format.h"
#include "solver/network/mission_network.h"
#include "solver/solve/unchecked_inputs.h"

namespace gesmi::io {
namespace {

constexpr const char* kResultFormatName = "gesmi-result";
// 1: before digests (no format_version attribute); 2: per-dataset and root SHA-256;
// 3: the waterfall stored as its feasible cells only; 4: the model keys of mission
// format 3 (max_depth_rate, max_altitude_rate) and the mission's epoch_utc; 5: the
// mission's origin (origin_latitude, origin_longitude, datum), for geodetic exports;
// 6: XXH3-128 digests (attributes `xxh128`, `navigation_xxh128`, ...) instead of SHA-256;
// 7: the model keys of mission format 4 (max_speed, the surface regime's) and the step
// regimes' report (/regimes).
constexpr H5FormatVersions kResultVersions{.current = kResultFormat, .oldest = 1, .when_absent = 1};

// The mission format whose model keys a result of this format holds.
int model_keys_version(std::int64_t format_version) { return format_version >= 7 ? 4 : format_version >= 4 ? 3 : 2; }

// Every dataset of a result, in the order the root digest lists them (format 3;
// format 2 has no /waterfall/step and /waterfall/mine, its waterfall being dense).
const char* const kDatasets[] = {"/time",          "/tube/lower",       "/tube/upper",     "/increments/lower",
                                 "/increments/upper", "/mines/lower",   "/mines/upper",    "/waterfall/step",
                                 "/waterfall/mine", "/waterfall/lower", "/waterfall/upper", "/marks/candidates",
                                 "/marks/outlier",  "/marks/time",      "/marks/range",    "/marks/mine",
                                 "/marks/side",     "/gps/outlier"};

// Units of the result's datasets (provenance.h) but its times (write_time_units).
constexpr DatasetUnits kResultUnits[] = {
    {"/tube/lower", "m, m, m", "lower bounds of the position: north, east, down (local frame)"},
    {"/tube/upper", "m, m, m", "upper bounds of the position: north, east, down (local frame)"},
    {"/increments/lower", "m, m, m", "lower bounds of the displacement p(k+1) - p(k): north, east, down"},
    {"/increments/upper", "m, m, m", "upper bounds of the displacement p(k+1) - p(k): north, east, down"},
    {"/mines/lower", "m, m, m", "lower bounds of the mine positions: north, east, down"},
    {"/mines/upper", "m, m, m", "upper bounds of the mine positions: north, east, down"},
    {"/waterfall/step", "1", "sample of a feasible waterfall cell"},
    {"/waterfall/mine", "1", "mine of a feasible waterfall cell"},
    {"/waterfall/lower", "m", "smallest slant range at which the mine can appear"},
    {"/waterfall/upper", "m", "largest slant range at which the mine can appear"},
    {"/marks/candidates", "1", "1 where the mine is still a possible association of the mark"},
    {"/marks/outlier", "1", "1 when every tolerated-outlier hypothesis removes the mark"},
    {"/marks/range", "m", "measured slant range"},
    {"/marks/mine", "1", "mine number of the mark (-1: not associated)"},
    {"/marks/side", "1", "sonar side: +1 starboard, -1 port"},
    {"/gps/outlier", "1", "1 when every tolerated-outlier hypothesis removes the fix"},
};

bool format_3_only(std::string_view name) { return name == "/waterfall/step" || name == "/waterfall/mine"; }

// The root attributes holding the input digests, named after their kind
// (navigation_xxh128, ...; navigation_sha256, ... in formats 2 to 5).
struct InputDigestNames {
  std::string navigation, bounds, marks;
};
InputDigestNames input_digest_names(DigestKind kind) {
  const std::string name = digest_name(kind);
  return {"navigation_" + name, "bounds_" + name, "marks_" + name};
}

// The readings' check (SolveReport::regimes) as root attributes (format 7): counts, and
// the first times as shortest decimals separated by commas.
struct RegimeAttributes {
  std::size_t StepRegimeReport::*count;
  std::vector<double> StepRegimeReport::*times;
  const char* count_name;
  const char* times_name;
};
constexpr RegimeAttributes kRegimeAttributes[] = {
    {&StepRegimeReport::fallback_steps, &StepRegimeReport::fallback_times, "fallback_steps", "fallback_times"},
    {&StepRegimeReport::speed_exceeded, &StepRegimeReport::speed_exceeded_times, "speed_exceeded_samples",
     "speed_exceeded_times"},
};

std::string times_text(const std::vector<double>& times) {
  std::string text;
  for (const double t : times) text += (text.empty() ? "" : ",") + format_number(t);
  return text;
}

void add_regime_fields(const StepRegimeReport& g, std::vector<std::pair<std::string, std::string>>& fields) {
  fields.emplace_back("surface_steps", std::to_string(g.surface_steps));
  for (const RegimeAttributes& a : kRegimeAttributes) {
    fields.emplace_back(a.count_name, std::to_string(g.*a.count));
    fields.emplace_back(a.times_name, times_text(g.*a.times));
  }
}

void write_regimes(H5File& f, const StepRegimeReport& g) {
  f.set_attribute("/", "surface_steps", static_cast<std::int64_t>(g.surface_steps));
  for (const RegimeAttributes& a : kRegimeAttributes) {
    f.set_attribute("/", a.count_name, static_cast<std::int64_t>(g.*a.count));
    f.set_attribute("/", a.times_name, times_text(g.*a.times));
  }
}

// The inputs nothing else checks, for a reader of the file's attributes: "mines 3 (mark
// 12), 5 (mark 40); GPS fix 0", empty when there are none.
std::string unchecked_inputs_text(const UncheckedInputs& u) {
  std::string text;
  for (std::size_t i = 0; i < u.mines.size(); ++i) {
    text += i ? ", " : u.mines.size() == 1 ? "mine " : "mines ";
    text += std::to_string(u.mines[i]) + " (mark " + std::to_string(u.marks[i]) + ")";
  }
  for (const std::size_t fix : u.gps_fixes) text += (text.empty() ? "GPS fix " : "; GPS fix ") + std::to_string(fix);
  return text;
}

// The root attributes the root digest covers (timings are informative and left out).
// `format_version`: the layout the fields are listed for (a result is always written
// as today's, whatever format it was read from).
std::vector<std::pair<std::string, std::string>> root_fields(const SolveResult& r, std::int64_t format_version) {
  const MissionSolution& s = r.solution;
  const InputDigestNames inputs = input_digest_names(result_digest_kind(format_version));
  std::vector<std::pair<std::string, std::string>> fields = {
          {"status", s.report.consistent ? "consistent" : "inconsistent"},
          {"mode", solve_mode_name(s.report.mode)},
          {"inconsistency", s.report.message},
          {"sweeps", std::to_string(s.report.sweeps)},
          {"converged", std::to_string(int{s.report.converged})},
          {"minimal_outliers", std::to_string(s.report.minimal_outliers)},
          {"mine_count", std::to_string(s.mine_count)},
          {inputs.navigation, r.navigation_digest},
          {inputs.bounds, r.bounds_digest},
          {inputs.marks, r.marks_digest},
          {"mark_count", std::to_string(s.mark_count())},
          {"gesmi_version", r.version}};
  if (r.epoch) fields.emplace_back("epoch_utc", format_iso8601(*r.epoch));
  if (format_version >= 5) {
    fields.emplace_back("origin_latitude", format_number(r.origin->latitude));
    fields.emplace_back("origin_longitude", format_number(r.origin->longitude));
    fields.emplace_back("datum", kDatum);
  }
  if (format_version >= 7) add_regime_fields(s.report.regimes, fields);
  // The /model attributes, exactly (shortest round-trip text): those the file's format has.
  const int model_version = model_keys_version(format_version);
  for (const SensorModelField& f : sensor_model_fields())
    if (f.since_version <= model_version) fields.emplace_back("/model/" + std::string(f.key), format_number(s.model.*f.member));
  for (const SensorModelChoice& c : sensor_model_choices())
    fields.emplace_back("/model/" + std::string(c.key), std::string(c.get(s.model)));
  return fields;
}

SolveMode mode_named(const std::string& name) {
  for (const SolveMode m : {SolveMode::cold, SolveMode::warm, SolveMode::outliers, SolveMode::minimal_outliers})
    if (name == solve_mode_name(m)) return m;
  return SolveMode::cold;
}

// Interval arrays as N x 3 lower / upper datasets (empty bounds as NaN), written in
// blocks of rows: no row-major copy of the whole array (240 MB at 10^7 steps).
void write_bounds(H5File& f, const std::string& prefix, const std::vector<Interval>* axes[3], std::size_t n) {
  for (const bool upper : {false, true})
    write_digested_in_blocks(f, prefix + (upper ? "/upper" : "/lower"), n, 3, 2, kResultDigest,
                             [&](std::size_t first, std::size_t count, std::span<double> rows) {
                               for (std::size_t k = 0; k < count; ++k)
                                 for (std::size_t c = 0; c < 3; ++c) {
                                   const Interval& x = (*axes[c])[first + k];
                                   rows[3 * k + c] = x.is_empty() ? NAN : (upper ? x.hi() : x.lo());
                                 }
                             });
}

[[noreturn]] void bad(const H5File& f, const std::string& object, const std::string& reason) {
  throw FormatError(f.path() + ": " + object + ": " + reason);
}

StepRegimeReport read_regimes(const H5File& f) {
  StepRegimeReport g;
  const auto count = [&](const char* name) {
    const auto v = f.int_attribute("/", name);
    if (!v || *v < 0) bad(f, "/", std::string("attribute ") + name + " must be a count (format 7)");
    return static_cast<std::size_t>(*v);
  };
  g.surface_steps = count("surface_steps");
  for (const RegimeAttributes& a : kRegimeAttributes) {
    g.*a.count = count(a.count_name);
    const auto text = f.string_attribute("/", a.times_name);
    if (!text) bad(f, "/", std::string("missing attribute ") + a.times_name);
    std::size_t at = 0;
    while (at < text->size()) {
      const std::size_t end = std::min(text->find(',', at), text->size());
      const std::optional<double> t = parse_number(std::string_view(*text).substr(at, end - at));
      if (!t || (g.*a.times).size() == StepRegimeReport::kShownTimes)
        bad(f, "/", std::string("attribute ") + a.times_name + " must list at most 5 times separated by commas");
      (g.*a.times).push_back(*t);
      at = end + 1;
    }
  }
  return g;
}

// Reads N x 3 bounds; an interval is [lo, hi] with lo <= hi, lo < +inf, hi > -inf,
// or empty (both NaN). The lower and upper datasets are read in step, in blocks: no
// whole copy of either (240 MB at 10^7 steps). Each block's intervals go to the three
// arrays `into(first, count)` gives for its rows, then `done(first, count)` is called. A
// changed digest is reported before a bad row (the row may be the edit): the first bad
// row is kept until both are checked. Returns whether some interval was empty.
template <class Into, class Done>
bool read_bound_blocks(const H5File& f, const std::string& prefix, std::size_t n, std::optional<DigestKind> verified,
                       Into&& into, Done&& done) {
  H5File::RowBlocks lower(f, prefix + "/lower", 3), upper(f, prefix + "/upper", 3);
  for (const H5File::RowBlocks* bounds : {&lower, &upper})
    if (bounds->rows() != n)
      bad(f, prefix + (bounds == &lower ? "/lower" : "/upper"),
          "expected " + std::to_string(n) + " rows, found " + std::to_string(bounds->rows()));
  std::optional<DatasetDigest> lower_digest, upper_digest;
  if (verified) {
    lower_digest.emplace(prefix + "/lower", n, 3, *verified);
    upper_digest.emplace(prefix + "/upper", n, 3, *verified);
  }
  std::string first_bad_row;
  bool any_empty = false;
  for (std::span<const double> lo_rows = lower.next(), hi_rows = upper.next(); !lo_rows.empty();
       lo_rows = lower.next(), hi_rows = upper.next()) {
    if (verified) {
      lower_digest->add(lo_rows);
      upper_digest->add(hi_rows);
    }
    const std::size_t first = lower.first(), count = lo_rows.size() / 3;
    const std::array<Interval*, 3> axes = into(first, count);
    for (std::size_t i = 0; i < lo_rows.size(); ++i) {
      const double lo = lo_rows[i], hi = hi_rows[i];
      const bool empty = std::isnan(lo) && std::isnan(hi);
      any_empty = any_empty || empty;
      if (!empty && !(lo <= hi && lo < INFINITY && hi > -INFINITY) && first_bad_row.empty())
        first_bad_row = "row " + std::to_string(first + i / 3) + ": not an interval (lower " + format_number(lo) +
                        ", upper " + format_number(hi) + ")";
      axes[i % 3][i / 3] = empty ? Interval::empty() : Interval(lo, hi);
    }
    done(first, count);
  }
  if (verified) {
    lower_digest->verify(f);
    upper_digest->verify(f);
  }
  if (!first_bad_row.empty()) bad(f, prefix, first_bad_row);
  return any_empty;
}

// read_bound_blocks() into three whole arrays; whether some interval was empty.
bool read_bounds(const H5File& f, const std::string& prefix, std::vector<Interval>* axes[3], std::size_t n,
                 std::optional<DigestKind> verified) {
  for (std::size_t c = 0; c < 3; ++c) axes[c]->resize(n);
  return read_bound_blocks(
      f, prefix, n, verified,
      [&](std::size_t first, std::size_t) {
        return std::array<Interval*, 3>{axes[0]->data() + first, axes[1]->data() + first, axes[2]->data() + first};
      },
      [](std::size_t, std::size_t) {});
}

// read_bound_blocks() handing each block to `rows` (ResultParts::tube_rows); whether
// some interval was empty.
bool read_bounds_streamed(const H5File& f, const std::string& prefix, std::size_t n, std::optional<DigestKind> verified,
                          const SolveResult& so_far, const TubeRows& rows) {
  std::vector<Interval> block[3];
  return read_bound_blocks(
      f, prefix, n, verified,
      [&](std::size_t, std::size_t count) {
        for (std::vector<Interval>& axis : block) axis.resize(count);
        return std::array<Interval*, 3>{block[0].data(), block[1].data(), block[2].data()};
      },
      [&](std::size_t first, std::size_t) { rows(so_far, first, block[0], block[1], block[2]); });
}

void expect_flags(const H5File& f, const std::string& dataset, const std::vector<std::int32_t>& values) {
  for (std::size_t i = 0; i < values.size(); ++i)
    if (values[i] != 0 && values[i] != 1) bad(f, dataset, "row " + std::to_string(i) + ": expected 0 or 1");
}

// The feasible cells of the waterfall in (step, mine) order: most of a dense waterfall
// is NaN (97.5 % at 10^7 steps), a mine being within the sonar's reach on few steps.
void write_waterfall_cells(H5File& f, const Waterfall& w, std::size_t steps_in_tube, std::size_t mine_count,
                           const std::string& path) {
  // Cells not written would read back as "no mine can appear there".
  if (w.steps != steps_in_tube || w.mines != mine_count)
    throw FormatError(path + ": the solution has no waterfall to write (solve with the waterfall computed)");
  write_digested(f, "/waterfall/step", w.step, w.cells(), kResultDigest);
  write_digested(f, "/waterfall/mine", w.mine, w.cells(), kResultDigest);
  write_digested(f, "/waterfall/lower", w.lower, w.cells(), kResultDigest);
  write_digested(f, "/waterfall/upper", w.upper, w.cells(), kResultDigest);
}

// The waterfall of n steps and k mines from its cells (format 3), checked: equal
// lengths, steps and mines in range, cells in strictly increasing order, finite bounds
// in order.
void read_waterfall_cells(const H5File& f, std::size_t n, std::size_t k, Waterfall& w, DigestKind kind) {
  std::vector<std::int32_t> steps = f.read_ints("/waterfall/step", 1), mines = f.read_ints("/waterfall/mine", 1);
  std::vector<double> lower = f.read_doubles("/waterfall/lower", 1), upper = f.read_doubles("/waterfall/upper", 1);
  const std::size_t cells = steps.size();
  for (const auto& [name, size] : {std::pair{"/waterfall/mine", mines.size()}, std::pair{"/waterfall/lower", lower.size()},
                                   std::pair{"/waterfall/upper", upper.size()}})
    if (size != cells) bad(f, name, std::to_string(size) + " rows where /waterfall/step has " + std::to_string(cells));
  verify_digest(f, "/waterfall/step", steps, cells, 1, kind);
  verify_digest(f, "/waterfall/mine", mines, cells, 1, kind);
  verify_digest(f, "/waterfall/lower", lower, cells, 1, kind);
  verify_digest(f, "/waterfall/upper", upper, cells, 1, kind);
  std::size_t previous = 0;
  for (std::size_t c = 0; c < cells; ++c) {
    const std::string row = "row " + std::to_string(c);
    if (steps[c] < 0 || static_cast<std::size_t>(steps[c]) >= n)
      bad(f, "/waterfall/step", row + ": step " + std::to_string(steps[c]) + " is not one of the " + std::to_string(n));
    if (mines[c] < 0 || static_cast<std::size_t>(mines[c]) >= k)
      bad(f, "/waterfall/mine", row + ": mine " + std::to_string(mines[c]) + " is not one of the " + std::to_string(k));
    const std::size_t cell = static_cast<std::size_t>(steps[c]) * k + static_cast<std::size_t>(mines[c]);
    if (c > 0 && cell <= previous) bad(f, "/waterfall/step", row + ": cells must be in increasing (step, mine) order");
    previous = cell;
    if (!std::isfinite(lower[c]) || !std::isfinite(upper[c]) || !(lower[c] <= upper[c]))
      bad(f, "/waterfall/lower", row + ": bounds must be finite with lower <= upper");
  }
  w.steps = n;
  w.mines = k;
  w.step = std::move(steps);
  w.mine = std::move(mines);
  w.lower = std::move(lower);
  w.upper = std::move(upper);
}

// A root attribute the file must have.
std::string required_text(const H5File& f, const char* name) {
  const auto v = f.string_attribute("/", name);
  if (!v) bad(f, "/", std::string("missing attribute ") + name);
  return *v;
}

std::int64_t required_integer(const H5File& f, const char* name, std::int64_t lowest, std::int64_t highest) {
  const auto v = f.int_attribute("/", name);
  if (!v) bad(f, "/", std::string("missing attribute ") + name);
  if (*v < lowest || *v > highest)
    bad(f, "/", std::string("attribute ") + name + " must be between " + std::to_string(lowest) + " and " +
                    std::to_string(highest) + ", found " + std::to_string(*v));
  return *v;
}

double required_degrees(const H5File& f, const char* name, double limit) {
  const auto v = f.double_attribute("/", name);
  if (!v) bad(f, "/", std::string("missing attribute ") + name);
  if (!(std::abs(*v) <= limit)) bad(f, "/", std::string("attribute ") + name + " must be within +-" + format_number(limit) + " degrees");
  return *v;
}

// The solve's report and the result's counts and version, from the root attributes;
// returns the mark count.
std::int64_t read_report_attributes(const H5File& f, SolveResult& r) {
  MissionSolution& s = r.solution;
  const std::string status = required_text(f, "status");
  if (status != "consistent" && status != "inconsistent") bad(f, "/", "attribute status must be consistent or inconsistent");
  s.report.consistent = status == "consistent";
  s.report.message = required_text(f, "inconsistency");
  s.report.sweeps = static_cast<int>(required_integer(f, "sweeps", 0, std::numeric_limits<std::int32_t>::max()));
  s.report.converged = required_integer(f, "converged", 0, 1) != 0;
  s.report.minimal_outliers =
      static_cast<int>(required_integer(f, "minimal_outliers", -1, std::numeric_limits<std::int32_t>::max()));
  s.mine_count = static_cast<int>(required_integer(f, "mine_count", 0, kMaxMines));
  const std::int64_t mark_count = required_integer(f, "mark_count", 0, static_cast<std::int64_t>(kMaxDatasetValues));
  r.version = required_text(f, "gesmi_version");
  return mark_count;
}

// The mission's epoch (when recorded) and its origin (format 5).
void read_epoch_and_origin(const H5File& f, SolveResult& r) {
  if (const auto epoch = f.string_attribute("/", "epoch_utc")) {
    r.epoch = parse_epoch_utc(*epoch);
    if (!r.epoch || r.format_version < 4)
      bad(f, "/", "attribute epoch_utc is not a UTC time YYYY-MM-DDThh:mm:ssZ of a format-4 result");
  }
  if (r.format_version >= 5) {
    r.origin = GeoOrigin{required_degrees(f, "origin_latitude", 90.0), required_degrees(f, "origin_longitude", 180.0)};
    if (required_text(f, "datum") != kDatum) bad(f, "/", std::string("attribute datum must be ") + kDatum);
  }
}

// What a result with digests (format 2 on) also records: the sensor model, the solve
// mode and the input digests.
void read_model_mode_and_inputs(const H5File& f, DigestKind verified, SolveResult& r) {
  MissionSolution& s = r.solution;
  s.model = read_model_attributes(f, "/model", model_keys_version(r.format_version));
  const std::string mode = required_text(f, "mode");
  s.report.mode = mode_named(mode);
  if (mode != solve_mode_name(s.report.mode)) bad(f, "/", "attribute mode is not one gesmi writes");
  const InputDigestNames inputs = input_digest_names(verified);
  r.navigation_digest = required_text(f, inputs.navigation.c_str());
  r.bounds_digest = required_text(f, inputs.bounds.c_str());
  r.marks_digest = required_text(f, inputs.marks.c_str());
}

void read_timings(const H5File& f, std::map<std::string, double>& timings_ms) {
  for (const char* name : {"load", "build", "propagate", "waterfall", "write"})
    if (const auto ms = f.double_attribute("/", std::string("timing_") + name + "_ms")) timings_ms[name] = *ms;
}

// The sample times: at least two, finite and increasing.
std::vector<double> read_times(const H5File& f, std::optional<DigestKind> verified) {
  std::vector<double> time = f.read_doubles("/time", 1);
  const std::size_t n = time.size();
  if (verified) verify_digest(f, "/time", time, n, 1, *verified);
  if (n < 2) bad(f, "/time", "expected at least 2 samples");
  for (std::size_t k = 0; k < n; ++k)
    if (!std::isfinite(time[k]) || (k > 0 && !(time[k] > time[k - 1])))
      bad(f, "/time", "row " + std::to_string(k) + ": times must be finite and increase");
  return time;
}

// The tube and increments of n steps, those `parts` asks for (the tube's rows handed
// over when it says so); whether some interval was empty, as read or handed over.
bool read_tube(const H5File& f, std::size_t n, std::optional<DigestKind> verified, const ResultParts& parts,
               SolveResult& r) {
  TubeDomains& d = r.solution.domains;
  bool empty_domain = false;
  if (parts.tube_rows) {
    empty_domain = read_bounds_streamed(f, "/tube", n, verified, r, parts.tube_rows);
  } else if (parts.tube) {
    std::vector<Interval>* tube[3] = {&d.px, &d.py, &d.pz};
    empty_domain = read_bounds(f, "/tube", tube, n, verified);
  }
  if (parts.keeps_increments()) {
    std::vector<Interval>* increments[3] = {&d.dx, &d.dy, &d.dz};
    empty_domain = read_bounds(f, "/increments", increments, n - 1, verified) || empty_domain;
  }
  return empty_domain;
}

void read_mine_boxes(const H5File& f, std::size_t k, std::optional<DigestKind> verified, std::vector<Vec3I>& boxes) {
  std::vector<Interval> mx, my, mz;
  std::vector<Interval>* mines[3] = {&mx, &my, &mz};
  read_bounds(f, "/mines", mines, k, verified);
  for (std::size_t i = 0; i < k; ++i) boxes.emplace_back(mx[i], my[i], mz[i]);
}

// Each mark's candidate mines (marks x k flags) as bit sets.
std::vector<std::uint64_t> read_candidates(const H5File& f, std::size_t marks, std::size_t k,
                                           std::optional<DigestKind> verified) {
  const H5Shape cs = f.shape("/marks/candidates");
  if (cs.rows != marks || (cs.rows > 0 && cs.columns != k))
    bad(f, "/marks/candidates", "expected " + std::to_string(marks) + " x " + std::to_string(k));
  const std::vector<std::int32_t> candidates = f.read_ints("/marks/candidates");
  if (verified) verify_digest(f, "/marks/candidates", candidates, cs.rows, cs.columns, *verified);
  expect_flags(f, "/marks/candidates", candidates);
  std::vector<std::uint64_t> sets(cs.rows, 0);
  for (std::size_t j = 0; j < cs.rows; ++j)
    for (std::size_t i = 0; i < k; ++i)
      if (candidates[j * k + i]) sets[j] |= std::uint64_t{1} << i;
  return sets;
}

// The marks' rows (candidates, outlier flags, times, ranges, mines, sides) and the GPS
// fixes' outlier flags, checked.
void read_marks_and_fixes(const H5File& f, std::size_t marks, std::optional<DigestKind> verified, MissionSolution& s) {
  s.candidates = read_candidates(f, marks, static_cast<std::size_t>(s.mine_count), verified);
  s.mark_outlier = f.read_ints("/marks/outlier", 1);
  s.mark_time = f.read_doubles("/marks/time", 1);
  s.mark_range = f.read_doubles("/marks/range", 1);
  s.mark_mine = f.read_ints("/marks/mine", 1);
  // Results of gesmi 0.1 kept no sides: a warm start needs them, and refuses those anyway.
  s.mark_side = verified ? f.read_ints("/marks/side", 1) : std::vector<std::int32_t>(marks, 0);
  if (s.mark_outlier.size() != marks || s.mark_time.size() != marks || s.mark_range.size() != marks ||
      s.mark_mine.size() != marks || s.mark_side.size() != marks)
    bad(f, "/marks", "expected " + std::to_string(marks) + " rows in every dataset");
  s.gps_outlier = f.read_ints("/gps/outlier", 1);
  if (verified) {
    verify_digest(f, "/marks/outlier", s.mark_outlier, marks, 1, *verified);
    verify_digest(f, "/marks/time", s.mark_time, marks, 1, *verified);
    verify_digest(f, "/marks/range", s.mark_range, marks, 1, *verified);
    verify_digest(f, "/marks/mine", s.mark_mine, marks, 1, *verified);
    verify_digest(f, "/marks/side", s.mark_side, marks, 1, *verified);
    verify_digest(f, "/gps/outlier", s.gps_outlier, s.gps_outlier.size(), 1, *verified);
  }
  expect_flags(f, "/marks/outlier", s.mark_outlier);
  expect_flags(f, "/gps/outlier", s.gps_outlier);
  for (std::size_t j = 0; j < marks; ++j) {
    const std::string row = "row " + std::to_string(j);
    if (!std::isfinite(s.mark_time[j])) bad(f, "/marks/time", row + ": time must be finite");
    if (!std::isfinite(s.mark_range[j]) || s.mark_range[j] < 0.0) bad(f, "/marks/range", row + ": range must be finite and >= 0");
    if (s.mark_mine[j] < -1 || s.mark_mine[j] >= s.mine_count)
      bad(f, "/marks/mine", row + ": mine " + std::to_string(s.mark_mine[j]) + " is not one of the result's " +
                                std::to_string(s.mine_count) + " mines (-1 for unknown)");
    if (verified && s.mark_side[j] != 1 && s.mark_side[j] != -1) bad(f, "/marks/side", row + ": side must be +1 or -1");
  }
}

// The waterfall of n steps and k mines of formats 1 and 2, checked.
void read_dense_waterfall(const H5File& f, std::size_t n, std::size_t k, std::optional<DigestKind> verified,
                          Waterfall& w) {
  const H5Shape ws = f.shape("/waterfall/lower");
  if (ws.rows != n || (k > 0 && ws.columns != k))
    bad(f, "/waterfall/lower", "expected " + std::to_string(n) + " x " + std::to_string(k));
  // Formats 1 and 2: a dense steps x mines table, NaN where a mine cannot appear.
  const std::vector<double> lower = f.read_doubles("/waterfall/lower"), upper = f.read_doubles("/waterfall/upper");
  if (upper.size() != lower.size()) bad(f, "/waterfall/upper", "shape differs from /waterfall/lower");
  if (k == 0 && !lower.empty()) bad(f, "/waterfall/lower", "cells in a result without mines");
  if (verified) {
    verify_digest(f, "/waterfall/lower", lower, ws.rows, ws.columns, *verified);
    verify_digest(f, "/waterfall/upper", upper, ws.rows, ws.columns, *verified);
  }
  w.steps = n;
  w.mines = k;
  for (std::size_t c = 0; c < lower.size(); ++c) {
    const double lo = lower[c], hi = upper[c];
    if (std::isnan(lo) && std::isnan(hi)) continue;
    if (!(lo <= hi)) bad(f, "/waterfall", "cell " + std::to_string(c) + ": lower bound above upper bound");
    w.add(c / k, c % k, lo, hi);
  }
}

// The root digest, over the root attributes and every dataset's recorded digest.
void verify_root_digest(const H5File& f, const SolveResult& r, DigestKind verified) {
  const std::string kind = digest_name(verified);
  std::vector<std::pair<std::string, std::string>> fields = root_fields(r, r.format_version);
  for (const char* dataset : kDatasets) {
    if (r.format_version < 3 && format_3_only(dataset)) continue;
    const auto stored = f.string_attribute(dataset, kind);
    if (!stored) bad(f, dataset, "has no " + kind + " attribute (edited or damaged)");
    fields.emplace_back(dataset, *stored);
  }
  if (f.string_attribute("/", kind) != digest_of_fields(fields, verified))
    bad(f, "/", "attributes or dataset digests " + differ_from_recorded(verified));
}

// The datasets a partial read leaves out (ResultParts), checked all the same, in blocks:
// a result edited anywhere is refused by every command that reads it.
void verify_unread(const H5File& f, std::size_t n, std::size_t k, const ResultParts& parts, int format_version,
                   DigestKind verified) {
  const auto check_bounds = [&](const std::string& prefix, std::size_t rows) {
    std::vector<Interval> block[3];
    read_bound_blocks(
        f, prefix, rows, verified,
        [&](std::size_t, std::size_t count) {
          for (std::vector<Interval>& axis : block) axis.resize(count);
          return std::array<Interval*, 3>{block[0].data(), block[1].data(), block[2].data()};
        },
        [](std::size_t, std::size_t) {});
  };
  if (!parts.reads_tube()) check_bounds("/tube", n);
  if (!parts.keeps_increments()) check_bounds("/increments", n == 0 ? 0 : n - 1);
  if (parts.waterfall) return;
  Waterfall unused;
  if (format_version >= 3)
    read_waterfall_cells(f, n, k, unused, verified);
  else
    read_dense_waterfall(f, n, k, verified, unused);
}

// A consistent result has no empty interval in its tube, increments or mine boxes.
void check_consistent_domains(const H5File& f, bool empty_domain, const std::vector<Vec3I>& mine_boxes) {
  if (empty_domain) bad(f, "/tube", "a consistent result with an empty domain (edited or damaged)");
  for (const Vec3I& m : mine_boxes)
    for (int c = 0; c < 3; ++c)
      if (m[c].is_empty()) bad(f, "/mines", "a consistent result with an empty mine box (edited or damaged)");
}

}  // namespace

void record_inputs(SolveResult& r, const Mission& mission, std::string navigation) {
  r.format_version = kResultFormat;  // the kind of the digests recorded, and the file's layout
  r.navigation_digest = navigation.empty() ? navigation_digest(mission, kResultDigest) : std::move(navigation);
  r.bounds_digest = bounds_digest(mission.model, kResultDigest);
  r.marks_digest = marks_digest(mission, r.solution.mark_count(), kResultDigest);
  r.version = std::string(version());
  r.epoch = mission.epoch;
  r.origin = mission.origin;
}

void write_result(const SolveResult& r, const std::string& path) {
  if (!r.origin) throw FormatError(path + ": the result has no origin to record (record_inputs() gives it)");
  // The input digests must be of today's kind (a result read from an earlier format holds
  // SHA-256 ones).
  if (r.format_version != kResultFormat)
    throw FormatError(path + ": the result's input digests are those of format " + std::to_string(r.format_version) +
                      " (record_inputs() records today's)");
  const MissionSolution& s = r.solution;
  AtomicOutput out(path);
  {
    H5File f = H5File::create(out.temp_path(), out.final_path());
    const TubeDomains& d = s.domains;
    const std::size_t n = d.size();
    write_digested(f, "/time", s.time, s.time.size(), kResultDigest);
    const std::vector<Interval>* tube[3] = {&d.px, &d.py, &d.pz};
    write_bounds(f, "/tube", tube, n);
    const std::vector<Interval>* increments[3] = {&d.dx, &d.dy, &d.dz};
    write_bounds(f, "/increments", increments, d.dx.size());
    std::vector<Interval> mx, my, mz;
    for (const Vec3I& m : d.mines) {
      mx.push_back(m[0]);
      my.push_back(m[1]);
      mz.push_back(m[2]);
    }
    const std::vector<Interval>* mines[3] = {&mx, &my, &mz};
    write_bounds(f, "/mines", mines, d.mines.size());
    const std::size_t k = static_cast<std::size_t>(s.mine_count);
    write_waterfall_cells(f, s.waterfall, n, k, path);
    std::vector<std::int32_t> candidates(s.candidates.size() * k);
    for (std::size_t j = 0; j < s.candidates.size(); ++j)
      for (std::size_t i = 0; i < k; ++i) candidates[j * k + i] = static_cast<std::int32_t>(s.candidates[j] >> i & 1);
    write_digested(f, "/marks/candidates", candidates, s.candidates.size(), kResultDigest, k, 2);
    write_digested(f, "/marks/outlier", s.mark_outlier, s.mark_outlier.size(), kResultDigest);
    write_digested(f, "/marks/time", s.mark_time, s.mark_time.size(), kResultDigest);
    write_digested(f, "/marks/range", s.mark_range, s.mark_range.size(), kResultDigest);
    write_digested(f, "/marks/mine", s.mark_mine, s.mark_mine.size(), kResultDigest);
    write_digested(f, "/marks/side", s.mark_side, s.mark_side.size(), kResultDigest);
    write_digested(f, "/gps/outlier", s.gps_outlier, s.gps_outlier.size(), kResultDigest);
    write_format(f, kResultFormatName, kResultVersions);
    write_model_attributes(f, "/model", s.model);
    const std::vector<std::pair<std::string, std::string>> fields = root_fields(r, kResultFormat);
    const std::string digest = digest_name(kResultDigest);
    f.set_attribute("/", "status", std::string(s.report.consistent ? "consistent" : "inconsistent"));
    f.set_attribute("/", "mode", std::string(solve_mode_name(s.report.mode)));
    f.set_attribute("/", "inconsistency", s.report.message);
    f.set_attribute("/", "sweeps", std::int64_t{s.report.sweeps});
    f.set_attribute("/", "converged", std::int64_t{s.report.converged});
    f.set_attribute("/", "minimal_outliers", std::int64_t{s.report.minimal_outliers});
    f.set_attribute("/", "mine_count", static_cast<std::int64_t>(s.mine_count));
    const InputDigestNames inputs = input_digest_names(kResultDigest);
    f.set_attribute("/", inputs.navigation, r.navigation_digest);
    f.set_attribute("/", inputs.bounds, r.bounds_digest);
    f.set_attribute("/", inputs.marks, r.marks_digest);
    f.set_attribute("/", "mark_count", static_cast<std::int64_t>(s.mark_count()));
    f.set_attribute("/", "gesmi_version", r.version);
    if (r.epoch) f.set_attribute("/", "epoch_utc", format_iso8601(*r.epoch));
    write_origin(f, *r.origin);
    write_regimes(f, s.report.regimes);
    for (const auto& [name, ms] : s.timings_ms) f.set_attribute("/", "timing_" + name + "_ms", ms);
    std::vector<std::pair<std::string, std::string>> digested = fields;
    for (const char* dataset : kDatasets) digested.emplace_back(dataset, *f.string_attribute(dataset, digest));
    f.set_attribute("/", digest, digest_of_fields(digested, kResultDigest));
    // Informative, outside the digests: what a reader recomputes from the candidates and
    // fixes, how the file was made, and its units.
    f.set_attribute("/", "unchecked_inputs", unchecked_inputs_text(unchecked_inputs(s)));
    write_provenance(f, "trajectory");
    write_units(f, kResultUnits);
    write_time_units(f, "/time", "sample time", r.epoch);
    write_time_units(f, "/marks/time", "sonar mark time", r.epoch);
    f.close();
  }
  out.commit();
}

SolveResult read_result(const std::string& path, ResultParts parts) {
  const H5File f = H5File::open_read(path);
  SolveResult r;
  MissionSolution& s = r.solution;
  r.format_version = check_format(f, kResultFormatName, "gesmi result", kResultVersions);
  // The digests to check: none in format 1.
  const std::optional<DigestKind> verified =
      r.format_version >= 2 ? std::optional(result_digest_kind(r.format_version)) : std::nullopt;
  const auto marks = static_cast<std::size_t>(read_report_attributes(f, r));
  read_epoch_and_origin(f, r);
  if (r.format_version >= 7) s.report.regimes = read_regimes(f);
  if (verified) read_model_mode_and_inputs(f, *verified, r);
  read_timings(f, s.timings_ms);

  s.time = read_times(f, verified);
  const std::size_t n = s.time.size();
  const bool empty_domain = read_tube(f, n, verified, parts, r);  // in the tube or the increments
  const std::size_t k = static_cast<std::size_t>(s.mine_count);
  read_mine_boxes(f, k, verified, s.domains.mines);

  read_marks_and_fixes(f, marks, verified, s);
  if (parts.waterfall && r.format_version >= 3) read_waterfall_cells(f, n, k, s.waterfall, *verified);
  if (parts.waterfall && r.format_version < 3) read_dense_waterfall(f, n, k, verified, s.waterfall);
  if (verified) {
    verify_root_digest(f, r, *verified);  // first: it also covers a dataset digest recomputed with its edit
    if (parts.check_unread) verify_unread(f, n, k, parts, r.format_version, *verified);
  }
  if (s.report.consistent) check_consistent_domains(f, empty_domain, s.domains.mines);
  return r;
}

}  // namespace gesmi::io
