#include "io/files/kalman_result.h"

#include <cstdint>

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
};

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
    f.set_attribute("/", "max_iterations", static_cast<std::int64_t>(k.options.max_iterations));
    f.set_attribute("/", "tolerance_m", k.options.tolerance);
    f.set_attribute("/", "last_step_m", r.last_step);
    f.set_attribute("/", "converged", static_cast<std::int64_t>(r.converged));
    f.set_attribute("/", "containment_3sigma_trajectory", k.containment_trajectory);
    f.set_attribute("/", "containment_3sigma_mines", k.containment_mines);
    for (const auto& [name, ms] : k.timings_ms) f.set_attribute("/", "timing_" + name + "_ms", ms);
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
