#include "tools/gesmi/kalman_report.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "io/report/report_json.h"

namespace gesmi::cli {

std::string input_name(const ConstraintRef& input) {
  return (input.kind == ConstraintRef::Kind::mark ? "mark " : "GPS fix ") + std::to_string(input.row);
}

void print_kalman_checks(const KalmanResult& r) {
  const KalmanConsistency& c = r.consistency;
  if (!std::isnan(c.chi2_per_dof)) {
    const char* verdict = c.consistent ? "consistent"
                          : c.chi2_per_dof > c.band_high
                              ? "REJECTED: the residuals exceed the noise model, so its sigmas are too small to trust"
                              : "REJECTED: the residuals are smaller than the noise model (its sigmas are pessimistic, "
                                "or the errors are not independent)";
    std::printf("consistency: chi2/dof = %.3g on %.0f degrees of freedom, expected within [%.4g, %.4g] (%.0f %%): %s\n",
                c.chi2_per_dof, c.dof, c.band_low, c.band_high, 100.0 * kChiSquareBandProbability, verdict);
  }
  std::size_t untestable = 0, flagged = 0;
  for (const InputTest& t : r.tests) {
    untestable += std::isnan(t.chi2);
    if (!t.flagged) continue;
    ++flagged;
    std::printf("flagged: %s at t = %.1f s: leave-one-out chi2 %.3g on %d dof (largest normalised residual %.3g)\n",
                input_name(t.input).c_str(), t.time, t.chi2, t.dof, t.max_normalised);
  }
  std::printf("residual tests: %zu input(s), %zu flagged beyond the %.2f %% quantile, %zu not testable (an input that "
              "alone determines what it measures: a mine's only mark, a lone GPS fix)\n",
              r.tests.size(), flagged, 100.0 * kResidualTestProbability, untestable);
  if (!r.biases) return;
  for (int b = 0; b < kBiasCount; ++b) {
    const BiasDescription& d = bias_descriptions()[static_cast<std::size_t>(b)];
    std::printf("bias %-12s %+.4g %s (sigma %.3g, prior sigma %.3g)%s\n", std::string(d.name).c_str(), r.bias_estimate[b],
                std::string(d.unit).c_str(), r.bias_sigma[b], r.bias_prior_sigma[b],
                r.bias_sigma[b] > 0.9 * r.bias_prior_sigma[b] ? "  not determined by the data (sigma near its prior)" : "");
  }
}

void add_kalman_checks(nlohmann::json& kalman, const KalmanResult& r) {
  const KalmanConsistency& c = r.consistency;
  kalman["consistency"] = {{"chi2", io::number_json(c.chi2)},
                           {"dof", io::number_json(c.dof)},
                           {"chi2_per_dof", io::number_json(c.chi2_per_dof)},
                           {"band_low", io::number_json(c.band_low)},
                           {"band_high", io::number_json(c.band_high)},
                           {"band_probability", kChiSquareBandProbability},
                           {"consistent", c.consistent}};
  nlohmann::json tests = nlohmann::json::array();
  for (const InputTest& t : r.tests)
    tests.push_back({{"kind", t.input.kind == ConstraintRef::Kind::mark ? "mark" : "gps_fix"},
                     {"row", t.input.row},
                     {"time", t.time},
                     {"dof", t.dof},
                     {"chi2", io::number_json(t.chi2)},
                     {"max_normalised", io::number_json(t.max_normalised)},
                     {"flagged", t.flagged}});
  kalman["tests"] = tests;
  kalman["test_probability"] = kResidualTestProbability;
  if (!r.biases) return;
  nlohmann::json biases = nlohmann::json::array();
  for (int b = 0; b < kBiasCount; ++b) {
    const BiasDescription& d = bias_descriptions()[static_cast<std::size_t>(b)];
    biases.push_back({{"name", d.name},
                      {"unit", d.unit},
                      {"estimate", r.bias_estimate[b]},
                      {"sigma", r.bias_sigma[b]},
                      {"prior_sigma", r.bias_prior_sigma[b]}});
  }
  kalman["bias_estimates"] = biases;
}

}  // namespace gesmi::cli
