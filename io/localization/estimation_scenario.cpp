#include "io/localization/estimation_scenario.h"

#include <cmath>
#include <set>

#include "io/format_error.h"
#include "io/text/message_text.h"
#include "io/text/strict_yaml.h"

namespace gesmi::io {
namespace {

class Reader {
 public:
  explicit Reader(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const YAML::Node& node, const std::string& key, const std::string& reason) const {
    const std::string line = node.IsDefined() && node.Mark().line >= 0 ? ":" + std::to_string(node.Mark().line + 1) : "";
    throw FormatError(source_ + line + ": " + key + ": " + reason);
  }
  void only_keys(const YAML::Node& map, const std::string& key, const std::set<std::string>& allowed) const {
    if (!map.IsMap()) fail(map, key, "expected a mapping");
    for (const auto& entry : map)
      if (!allowed.count(entry.first.Scalar()))
        fail(entry.first, (key.empty() ? "" : key + ".") + quoted_input(entry.first.Scalar()), "unknown key");
  }
  YAML::Node required(const YAML::Node& map, const std::string& key, const std::string& name) const {
    const YAML::Node n = map[name];
    if (!n) fail(map, key.empty() ? name : key + "." + name, "missing");
    return n;
  }
  double number(const YAML::Node& n, const std::string& key) const {
    if (!n.IsScalar()) fail(n, key, "expected a number");
    double v = 0.0;
    try {
      v = n.as<double>();
    } catch (const YAML::Exception&) {
      fail(n, key, "expected a number, got " + quoted_input(n.Scalar()));
    }
    if (!std::isfinite(v)) fail(n, key, "must be finite");
    return v;
  }
  long long integer(const YAML::Node& n, const std::string& key) const {
    const double v = number(n, key);
    if (v != std::floor(v) || std::abs(v) > 1e15) fail(n, key, "expected an integer");
    return static_cast<long long>(v);
  }
  Interval interval(const YAML::Node& n, const std::string& key) const {
    if (!n.IsSequence() || n.size() != 2) fail(n, key, "expected [lower, upper]");
    const double lo = number(n[0], key + "[0]"), hi = number(n[1], key + "[1]");
    if (!(lo <= hi)) fail(n, key, "lower bound above upper bound");
    return Interval(lo, hi);
  }

 private:
  std::string source_;
};

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
  r.only_keys(solver, "solver", {"epsilon", "max_boxes"});
  p.epsilon = r.number(r.required(solver, "solver", "epsilon"), "solver.epsilon");
  if (!(p.epsilon > 0.0)) r.fail(solver["epsilon"], "solver.epsilon", "must be positive");
  if (solver["max_boxes"]) {
    const long long n = r.integer(solver["max_boxes"], "solver.max_boxes");
    if (n <= 0) r.fail(solver["max_boxes"], "solver.max_boxes", "must be positive");
    p.max_boxes = static_cast<std::size_t>(n);
  }
  const int n = static_cast<int>(p.t.size());
  if (const YAML::Node outliers = root["outliers"]) {
    r.only_keys(outliers, "outliers", {"levels"});
    const YAML::Node levels = r.required(outliers, "outliers", "levels");
    if (!levels.IsSequence() || levels.size() == 0) r.fail(levels, "outliers.levels", "expected a non-empty list of q");
    for (std::size_t i = 0; i < levels.size(); ++i) {
      const std::string key = "outliers.levels[" + std::to_string(i) + "]";
      const long long q = r.integer(levels[i], key);
      if (q < 0 || q > n) r.fail(levels[i], key, "must be between 0 and " + std::to_string(n));
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
