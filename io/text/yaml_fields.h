#pragma once
// Typed fields of a strict YAML document (strict_yaml.h), each error naming the file,
// the line and the key path in one line (a FormatError): the scenario readers'
// common vocabulary.

#include <yaml-cpp/yaml.h>

#include <set>
#include <string>
#include <vector>

#include "solver/interval/interval.h"

namespace gesmi::io {

class YamlFields {
 public:
  explicit YamlFields(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const YAML::Node& node, const std::string& key, const std::string& reason) const;
  /// The node is a mapping whose keys are all in `allowed`.
  void only_keys(const YAML::Node& map, const std::string& key, const std::set<std::string>& allowed) const;
  YAML::Node required(const YAML::Node& map, const std::string& key, const std::string& name) const;
  /// A finite number.
  double number(const YAML::Node& n, const std::string& key) const;
  double number_or(const YAML::Node& map, const std::string& key, const std::string& name, double fallback) const;
  long long integer(const YAML::Node& n, const std::string& key) const;
  std::string text(const YAML::Node& n, const std::string& key) const;
  std::vector<double> numbers(const YAML::Node& n, const std::string& key, std::size_t count) const;
  /// [lower, upper] times `unit`, lower strictly below upper.
  Interval range(const YAML::Node& n, const std::string& key, double unit) const;
  /// [lower, upper], lower at most upper (a degenerate interval is a point).
  Interval interval(const YAML::Node& n, const std::string& key) const;

  static std::string join(const std::string& a, const std::string& b) { return a.empty() ? b : a + "." + b; }
  /// A key from the file as part of a key path: as it is when it is a plain name.
  static std::string shown_key(const std::string& name);
  static std::string item(const std::string& key, std::size_t i) { return key + "[" + std::to_string(i) + "]"; }

 private:
  std::string source_;
};

}  // namespace gesmi::io
