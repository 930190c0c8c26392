#include "io/localization/estimation_scenario.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <span>

#include "io/format_error.h"
#include "io/text/csv_number.h"
#include "io/text/message_text.h"
#include "io/text/strict_yaml.h"
#include "io/text/yaml_fields.h"
#include "solver/setinv/sivia.h"

namespace gesmi::io {
namespace {

using Reader = YamlFields;  // (io/text/yaml_fields.h)

EstimationProblem problem_from(const YAML::Node& root, const std::string& source) {
  const Reader r(source);
  if (root.IsNull()) throw FormatError(source + ": no YAML document: expected an estimation scenario");
  r.only_keys(root, "", {"name", "description", "model", "data", "prior", "solver", "outliers"});
  EstimationProblem p;
  if (root["name"]) {
    if (!root["name"].IsScalar() || one_line(root["name"].Scalar()) != root["name"].Scalar() || root["name"].Scalar().size() > 200)
      r.fail(root["name"], "name", "expected one line of at most 200 characters");
    p.name = root["name"].Scalar();
  }
  const YAML::Node model = r.required(root, "", "model");
  if (!model.IsScalar() || model.Scalar() != "gaussian_density")
    r.fail(model, "model", "expected 'gaussian_density'" + (model.IsScalar() ? ", got " + quoted_input(model.Scalar()) : ""));
  const YAML::Node data = r.required(root, "", "data");
  if (!data.IsSequence() || data.size() == 0) r.fail(data, "data", "expected a non-empty list of {t, y: [lo, hi]}");
  if (data.size() > EstimationProblem::kMaxData)  // memory grows with boxes x data (estimation_problem.h)
    r.fail(data[EstimationProblem::kMaxData], "data", "at most " + std::to_string(EstimationProblem::kMaxData) +
                                                          " data, got " + std::to_string(data.size()));
  for (std::size_t i = 0; i < data.size(); ++i) {
    const std::string key = "data[" + std::to_string(i + 1) + "]";  // numbered from 1, as the outputs
    r.only_keys(data[i], key, {"t", "y"});
    p.t.push_back(r.number(r.required(data[i], key, "t"), key + ".t"));
    p.data.push_back(r.interval(r.required(data[i], key, "y"), key + ".y"));
  }
  const YAML::Node prior = r.required(root, "", "prior");
  if (!prior.IsSequence() || prior.size() != 2) r.fail(prior, "prior", "expected [[p1_lo, p1_hi], [p2_lo, p2_hi]]");
  for (std::size_t k = 0; k < 2; ++k) {
    const std::string key = "prior[" + std::to_string(k) + "]";
    p.prior.push_back(r.interval(prior[k], key));
    if (!(p.prior[k].width() > 0.0)) r.fail(prior[k], key, "must have a positive width");
  }
  const YAML::Node solver = r.required(root, "", "solver");
  r.only_keys(solver, "solver", {"epsilon", "max_boxes", "max_seconds"});
  p.epsilon = r.number(r.required(solver, "solver", "epsilon"), "solver.epsilon");
  if (!(p.epsilon > 0.0)) r.fail(solver["epsilon"], "solver.epsilon", "must be positive");
  // Below this the bisection cannot meet epsilon near the prior's largest coordinates.
  if (const double finest = finest_epsilon(std::span<const Box>(&p.prior, 1), {}); p.epsilon < finest)
    r.fail(solver["epsilon"], "solver.epsilon",
           format_number(p.epsilon) + " is finer than doubles can split over the prior box: at least " +
               format_number(finest));
  if (solver["max_boxes"]) {
    const long long n = r.integer(solver["max_boxes"], "solver.max_boxes");
    if (n <= 0 || static_cast<unsigned long long>(n) > EstimationProblem::kMaxBoxesCeiling)
      r.fail(solver["max_boxes"], "solver.max_boxes",
             "must be between 1 and " + std::to_string(EstimationProblem::kMaxBoxesCeiling) + " (memory grows with it)");
    p.max_boxes = static_cast<std::size_t>(n);
  }
  p.max_seconds = r.number_or(solver, "solver", "max_seconds", p.max_seconds);
  if (!(p.max_seconds > 0.0)) r.fail(solver["max_seconds"], "solver.max_seconds", "must be positive");
  const int n = static_cast<int>(p.t.size());
  if (const YAML::Node outliers = root["outliers"]) {
    r.only_keys(outliers, "outliers", {"levels"});
    const YAML::Node levels = r.required(outliers, "outliers", "levels");
    if (!levels.IsSequence() || levels.size() == 0) r.fail(levels, "outliers.levels", "expected a non-empty list of q");
    for (std::size_t i = 0; i < levels.size(); ++i) {
      const std::string key = "outliers.levels[" + std::to_string(i) + "]";
      const long long q = r.integer(levels[i], key);
      if (q < 0 || q > n) r.fail(levels[i], key, "must be between 0 and " + std::to_string(n));
      if (std::find(p.levels.begin(), p.levels.end(), q) != p.levels.end())
        r.fail(levels[i], key, std::to_string(q) + " is listed twice");
      p.levels.push_back(static_cast<int>(q));
    }
  } else {
    for (int q = 0; q <= n; ++q) p.levels.push_back(q);
  }
  if (const std::string e = p.validate(); !e.empty()) throw FormatError(source + ": " + e);
  return p;
}

}  // namespace

EstimationProblem read_estimation_scenario(const std::string& path) {
  const YAML::Node root = load_strict_yaml_file(path);
  try {
    return problem_from(root, path);
  } catch (const YAML::Exception& e) {
    throw FormatError(path + ":" + std::to_string(e.mark.line + 1) + ": " + e.msg);
  }
}

}  // namespace gesmi::io
