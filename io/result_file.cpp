#include "io/result_file.h"

#include <cmath>

#include "io/atomic_output.h"
#include "io/format_error.h"
#include "io/hdf5/h5_file.h"

namespace gesmi::io {
namespace {

constexpr const char* kFormat = "gesmi-result";

// Interval arrays as N x 3 lower / upper datasets (empty bounds as NaN).
void write_bounds(H5File& f, const std::string& prefix, const std::vector<Interval>* axes[3], std::size_t n) {
  std::vector<double> lower(3 * n), upper(3 * n);
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t c = 0; c < 3; ++c) {
      const Interval& x = (*axes[c])[k];
      lower[3 * k + c] = x.is_empty() ? NAN : x.lo();
      upper[3 * k + c] = x.is_empty() ? NAN : x.hi();
    }
  f.write(prefix + "/lower", lower, n, 3, 2);
  f.write(prefix + "/upper", upper, n, 3, 2);
}

void read_bounds(const H5File& f, const std::string& prefix, std::vector<Interval>* axes[3], std::size_t n) {
  std::vector<double> lower(3 * n), upper(3 * n);
  f.read_doubles_into(prefix + "/lower", lower);
  f.read_doubles_into(prefix + "/upper", upper);
  for (std::size_t c = 0; c < 3; ++c) axes[c]->resize(n);
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t c = 0; c < 3; ++c) {
      const double lo = lower[3 * k + c], hi = upper[3 * k + c];
      if (std::isnan(lo) != std::isnan(hi) || (!std::isnan(lo) && !(lo <= hi)))
        throw FormatError(f.path() + ": " + prefix + ": row " + std::to_string(k) + ": lower bound above upper bound");
      (*axes[c])[k] = std::isnan(lo) ? Interval::empty() : Interval(lo, hi);
    }
}

}  // namespace

void write_result(const SolveResult& r, const std::string& path) {
  AtomicOutput out(path);
  {
    H5File f = H5File::create(out.temp_path());
    const TubeDomains& d = r.domains;
    const std::size_t n = d.size();
    f.write("/time", r.time, r.time.size());
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
    const std::size_t k = static_cast<std::size_t>(r.mine_count);
    f.write("/waterfall/lower", r.waterfall.lower, r.waterfall.steps, r.waterfall.mines, 2);
    f.write("/waterfall/upper", r.waterfall.upper, r.waterfall.steps, r.waterfall.mines, 2);
    std::vector<std::int32_t> candidates(r.candidates.size() * k);
    for (std::size_t j = 0; j < r.candidates.size(); ++j)
      for (std::size_t i = 0; i < k; ++i) candidates[j * k + i] = static_cast<std::int32_t>(r.candidates[j] >> i & 1);
    f.write("/marks/candidates", candidates, r.candidates.size(), k, 2);
    f.write("/marks/outlier", r.outlier, r.outlier.size());
    f.write("/marks/time", r.mark_time, r.mark_time.size());
    f.write("/marks/range", r.mark_range, r.mark_range.size());
    f.write("/marks/mine", r.mark_mine, r.mark_mine.size());
    f.write("/gps/outlier", r.gps_outlier, r.gps_outlier.size());
    f.set_attribute("/", "format", std::string(kFormat));
    f.set_attribute("/", "status", std::string(r.consistent ? "consistent" : "inconsistent"));
    f.set_attribute("/", "inconsistency", r.message);
    f.set_attribute("/", "sweeps", r.sweeps);
    f.set_attribute("/", "converged", std::int64_t{r.converged});
    f.set_attribute("/", "minimal_outliers", r.minimal_outliers);
    f.set_attribute("/", "mine_count", static_cast<std::int64_t>(r.mine_count));
    f.set_attribute("/", "navigation_hash", r.navigation_hash);
    f.set_attribute("/", "bounds_hash", r.bounds_hash);
    f.set_attribute("/", "marks_hash", r.marks_hash);
    f.set_attribute("/", "mark_count", r.mark_count);
    f.set_attribute("/", "gesmi_version", r.version);
    for (const auto& [name, ms] : r.timings_ms) f.set_attribute("/", "timing_" + name + "_ms", ms);
    f.close();
  }
  out.commit();
}

SolveResult read_result(const std::string& path, bool with_waterfall) {
  const H5File f = H5File::open_read(path);
  if (f.string_attribute("/", "format") != std::optional<std::string>(kFormat))
    throw FormatError(path + ": not a gesmi result file (attribute 'format' is not '" + kFormat + "')");
  SolveResult r;
  const auto text = [&](const char* name) {
    const auto v = f.string_attribute("/", name);
    if (!v) throw FormatError(path + ": /: missing attribute " + name);
    return *v;
  };
  const auto integer = [&](const char* name) {
    const auto v = f.int_attribute("/", name);
    if (!v) throw FormatError(path + ": /: missing attribute " + name);
    return *v;
  };
  r.consistent = text("status") == "consistent";
  r.message = text("inconsistency");
  r.sweeps = integer("sweeps");
  r.converged = integer("converged") != 0;
  r.minimal_outliers = integer("minimal_outliers");
  r.mine_count = static_cast<int>(integer("mine_count"));
  if (r.mine_count < 0 || r.mine_count > 64) throw FormatError(path + ": /: mine_count out of range");
  r.navigation_hash = text("navigation_hash");
  r.bounds_hash = text("bounds_hash");
  r.marks_hash = text("marks_hash");
  r.mark_count = integer("mark_count");
  r.version = text("gesmi_version");
  for (const char* name : {"load", "build", "propagate", "waterfall", "write"})
    if (const auto ms = f.double_attribute("/", std::string("timing_") + name + "_ms")) r.timings_ms[name] = *ms;
  r.time = f.read_doubles("/time");
  const std::size_t n = r.time.size();
  if (n < 2) throw FormatError(path + ": /time: expected at least 2 samples");
  TubeDomains& d = r.domains;
  std::vector<Interval>* tube[3] = {&d.px, &d.py, &d.pz};
  read_bounds(f, "/tube", tube, n);
  std::vector<Interval>* increments[3] = {&d.dx, &d.dy, &d.dz};
  read_bounds(f, "/increments", increments, n - 1);
  std::vector<Interval> mx, my, mz;
  std::vector<Interval>* mines[3] = {&mx, &my, &mz};
  const std::size_t k = static_cast<std::size_t>(r.mine_count);
  read_bounds(f, "/mines", mines, k);
  for (std::size_t i = 0; i < k; ++i) d.mines.emplace_back(mx[i], my[i], mz[i]);
  const H5Shape cs = f.shape("/marks/candidates");
  if (cs.rows != static_cast<std::size_t>(r.mark_count) || (cs.rows > 0 && cs.columns != k))
    throw FormatError(path + ": /marks/candidates: expected " + std::to_string(r.mark_count) + " x " + std::to_string(k));
  const std::vector<std::int32_t> candidates = f.read_ints("/marks/candidates");
  r.candidates.assign(cs.rows, 0);
  for (std::size_t j = 0; j < cs.rows; ++j)
    for (std::size_t i = 0; i < k; ++i)
      if (candidates[j * k + i]) r.candidates[j] |= std::uint64_t{1} << i;
  r.outlier = f.read_ints("/marks/outlier");
  r.mark_time = f.read_doubles("/marks/time");
  r.mark_range = f.read_doubles("/marks/range");
  r.mark_mine = f.read_ints("/marks/mine");
  const auto marks = static_cast<std::size_t>(r.mark_count);
  if (r.outlier.size() != marks || r.mark_time.size() != marks || r.mark_range.size() != marks || r.mark_mine.size() != marks)
    throw FormatError(path + ": /marks: expected " + std::to_string(marks) + " rows in every dataset");
  r.gps_outlier = f.read_ints("/gps/outlier");
  if (with_waterfall) {
    const H5Shape ws = f.shape("/waterfall/lower");
    if (ws.rows != n || (k > 0 && ws.columns != k))
      throw FormatError(path + ": /waterfall/lower: expected " + std::to_string(n) + " x " + std::to_string(k));
    r.waterfall.steps = n;
    r.waterfall.mines = k;
    r.waterfall.lower = f.read_doubles("/waterfall/lower");
    r.waterfall.upper = f.read_doubles("/waterfall/upper");
    if (r.waterfall.upper.size() != r.waterfall.lower.size())
      throw FormatError(path + ": /waterfall/upper: shape differs from /waterfall/lower");
  }
  return r;
}

}  // namespace gesmi::io
