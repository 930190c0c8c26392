#include "io/files/kalman_result.h"

#include <cstdint>
#include <string>
#include <vector>

#include "io/output/atomic_output.h"
#include "io/hdf5/h5_file.h"
#include "io/io_version.h"
#include "io/files/model_attributes.h"
#include "io/files/provenance.h"
#include "io/time/utc_time.h"

namespace gesmi::io {
namespace {

constexpr DatasetUnits kKalmanUnits[] = {
    {"/kalman/mean", "m, m, m", "smoothed position: north, east, down (local frame)"},
    {"/kalman/cov", "m2", "covariance of the smoothed position (north, east, down)"},
    {"/kalman/mines/mean", "m, m, m", "smoothed mine positions: north, east, down"},
    {"/kalman/mines/cov", "m2", "covariance of each mine position (north, east, down)"},
    {"/kalman/tests/kind", "1", "tested input: 0 GPS fix, 1 mark"},
    {"/kalman/tests/row", "1", "row of the input in the mission's GPS or mark table (from 0)"},
    {"/kalman/tests/time", "s", "time of the input"},
    {"/kalman/tests/dof", "1", "scalar measurements of the input"},
    {"/kalman/tests/chi2", "1", "leave-one-out chi-square of the input (NaN: not testable)"},
    {"/kalman/tests/max_normalised", "1", "largest normalised residual of the input"},
    {"/kalman/tests/flagged", "1", "1 when the chi-square exceeds its test_probability quantile"},
};

constexpr DatasetUnits kBiasUnits[] = {
    {"/kalman/biases/estimate", "rad, 1, 1, 1, m/s, m/s, m/s, 1, m", "estimated sensor biases (bias_names)"},
    {"/kalman/biases/sigma", "rad, 1, 1, 1, m/s, m/s, m/s, 1, m", "standard deviation of each bias estimate"},
    {"/kalman/biases/prior_sigma", "rad, 1, 1, 1, m/s, m/s, m/s, 1, m", "standard deviation of each bias prior"},
};

// The residual tests, one row per input (kalman_consistency.h).
void write_tests(H5File& f, const KalmanResult& r) {
  std::vector<std::int32_t> kind, row, dof, flagged;
  std::vector<double> time, chi2, normalised;
  std::int64_t flagged_fixes = 0, flagged_marks = 0;
  for (const InputTest& t : r.tests) {
    const bool mark = t.input.kind == ConstraintRef::Kind::mark;
    kind.push_back(mark ? 1 : 0);
    row.push_back(static_cast<std::int32_t>(t.input.row));
    dof.push_back(t.dof);
    flagged.push_back(t.flagged ? 1 : 0);
    time.push_back(t.time);
    chi2.push_back(t.chi2);
    normalised.push_back(t.max_normalised);
    (mark ? flagged_marks : flagged_fixes) += t.flagged;
  }
  f.write("/kalman/tests/kind", kind, kind.size());
  f.write("/kalman/tests/row", row, row.size());
  f.write("/kalman/tests/time", time, time.size());
  f.write("/kalman/tests/dof", dof, dof.size());
  f.write("/kalman/tests/chi2", chi2, chi2.size());
  f.write("/kalman/tests/max_normalised", normalised, normalised.size());
  f.write("/kalman/tests/flagged", flagged, flagged.size());
  f.set_attribute("/", "flagged_fixes", flagged_fixes);
  f.set_attribute("/", "flagged_marks", flagged_marks);
  f.set_attribute("/", "test_probability", kResidualTestProbability);
  const KalmanConsistency& c = r.consistency;
  f.set_attribute("/", "chi2", c.chi2);
  f.set_attribute("/", "chi2_dof", c.dof);
  f.set_attribute("/", "chi2_per_dof", c.chi2_per_dof);
  f.set_attribute("/", "chi2_band_low", c.band_low);
  f.set_attribute("/", "chi2_band_high", c.band_high);
  f.set_attribute("/", "chi2_band_probability", kChiSquareBandProbability);
  f.set_attribute("/", "chi2_consistent", static_cast<std::int64_t>(c.consistent));
}

void write_biases(H5File& f, const KalmanResult& r) {
  f.set_attribute("/", "biases", static_cast<std::int64_t>(r.biases));
  if (!r.biases) return;
  const auto values = [](const BiasVec& v) { return std::vector<double>(v.data(), v.data() + kBiasCount); };
  f.write("/kalman/biases/estimate", values(r.bias_estimate), kBiasCount);
  f.write("/kalman/biases/sigma", values(r.bias_sigma), kBiasCount);
  f.write("/kalman/biases/prior_sigma", values(r.bias_prior_sigma), kBiasCount);
  std::string names, units;
  for (const BiasDescription& d : bias_descriptions()) {
    names += (names.empty() ? "" : ",") + std::string(d.name);
    units += (units.empty() ? "" : ",") + std::string(d.unit);
  }
  f.set_attribute("/", "bias_names", names);
  f.set_attribute("/", "bias_units", units);
  write_units(f, kBiasUnits);
}

}  // namespace

void write_kalman_result(const KalmanFile& k, const std::string& path) {
  AtomicOutput out(path);
  {
    H5File f = H5File::create(out.temp_path(), out.final_path());
    const KalmanResult& r = k.result;
    f.write("/time", k.time, k.time.size());
    f.write("/kalman/mean", r.mean, r.steps, 3, 2);
    f.write_3d("/kalman/cov", r.covariance, r.steps, 3, 3);
    f.write("/kalman/mines/mean", r.mine_mean, r.mines, 3, 2);
    f.write_3d("/kalman/mines/cov", r.mine_covariance, r.mines, 3, 3);
    f.set_attribute("/", "format", std::string("gesmi-kalman"));
    f.set_attribute("/", "gesmi_version", std::string(version()));
    if (k.epoch) f.set_attribute("/", "epoch_utc", format_iso8601(*k.epoch));
    f.set_attribute("/", "noise_factor", k.options.noise_factor);
    f.set_attribute("/", "iterations", static_cast<std::int64_t>(r.iterations));
    f.set_attribute("/", "start", std::string(kalman_start_name(k.options.start)));
    f.set_attribute("/", "coarse_iterations", static_cast<std::int64_t>(r.coarse_iterations));
    f.set_attribute("/", "max_iterations", static_cast<std::int64_t>(k.options.max_iterations));
    f.set_attribute("/", "tolerance_m", k.options.tolerance);
    f.set_attribute("/", "last_step_m", r.last_step);
    f.set_attribute("/", "converged", static_cast<std::int64_t>(r.converged));
    f.set_attribute("/", "stall_fraction", k.options.stall_fraction);
    f.set_attribute("/", "last_step_sigmas", r.last_step_sigmas);
    f.set_attribute("/", "stalled", static_cast<std::int64_t>(r.stalled));
    f.set_attribute("/", "containment_3sigma_horizontal", k.containment.horizontal);
    f.set_attribute("/", "containment_3sigma_vertical", k.containment.vertical);
    f.set_attribute("/", "containment_mines", k.containment.mines);
    f.set_attribute("/", "containment_mines_plane", k.containment.mines_plane);
    for (const auto& [name, ms] : k.timings_ms) f.set_attribute("/", "timing_" + name + "_ms", ms);
    write_tests(f, r);
    write_biases(f, r);
    write_origin(f, k.origin);
    write_model_attributes(f, "/model", k.model);
    write_provenance(f, "trajectory");
    write_units(f, kKalmanUnits);
    write_time_units(f, "/time", "sample time", k.epoch);
    f.close();
  }
  out.commit();
}

}  // namespace gesmi::io
