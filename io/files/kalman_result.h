#pragma once
// The Kalman smoother's result file (docs/formats.md): /time, /kalman/mean (N x 3),
// /kalman/cov (N x 3 x 3), /kalman/mines/mean (K x 3), /kalman/mines/cov (K x 3 x 3),
// the residual tests under /kalman/tests, the biases under /kalman/biases, and
// attributes (timings, options, convergence, the chi-square check, containment on
// simulated missions, the sensor model under /model, the origin, provenance and units:
// io/files/provenance.h).

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "solver/kalman/kalman_smoother.h"
#include "solver/mission/mission.h"

namespace gesmi::io {

struct KalmanFile {
  std::vector<double> time;
  KalmanResult result;
  KalmanOptions options;
  std::map<std::string, double> timings_ms;
  Containment containment;  // where the truth lies (simulated missions; NaN without truth)
  std::optional<std::int64_t> epoch;  // the mission's UTC epoch of t = 0, when it has one
  GeoOrigin origin;                   // the mission's local frame origin (WGS84)
  SensorModel model;                  // the bounds the noise variances come from
};

void write_kalman_result(const KalmanFile& file, const std::string& path);

}  // namespace gesmi::io
