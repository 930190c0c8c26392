#include "io/text/yaml_fields.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "io/format_error.h"
#include "io/text/message_text.h"

namespace gesmi::io {

void YamlFields::fail(const YAML::Node& node, const std::string& key, const std::string& reason) const {
  const std::string line = node.IsDefined() && node.Mark().line >= 0 ? ":" + std::to_string(node.Mark().line + 1) : "";
  throw FormatError(source_ + line + ": " + key + ": " + reason);
}

void YamlFields::only_keys(const YAML::Node& map, const std::string& key, const std::set<std::string>& allowed) const {
  if (!map.IsMap()) fail(map, key, "expected a mapping");
  for (const auto& entry : map) {
    const std::string& name = entry.first.Scalar();  // keys are plain values (strict_yaml.h)
    if (!allowed.count(name)) fail(entry.first, join(key, shown_key(name)), "unknown key");
  }
}

YAML::Node YamlFields::required(const YAML::Node& map, const std::string& key, const std::string& name) const {
  const YAML::Node n = map[name];
  if (!n) fail(map, join(key, name), "missing");
  return n;
}

double YamlFields::number(const YAML::Node& n, const std::string& key) const {
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

double YamlFields::number_or(const YAML::Node& map, const std::string& key, const std::string& name,
                             double fallback) const {
  return map[name] ? number(map[name], join(key, name)) : fallback;
}

long long YamlFields::integer(const YAML::Node& n, const std::string& key) const {
  const double v = number(n, key);
  if (v != std::floor(v) || std::abs(v) > 1e15) fail(n, key, "expected an integer");
  return static_cast<long long>(v);
}

std::string YamlFields::text(const YAML::Node& n, const std::string& key) const {
  if (!n.IsScalar()) fail(n, key, "expected a string");
  return n.Scalar();
}

std::vector<double> YamlFields::numbers(const YAML::Node& n, const std::string& key, std::size_t count) const {
  if (!n.IsSequence() || n.size() != count) fail(n, key, "expected a list of " + std::to_string(count) + " numbers");
  std::vector<double> v;
  for (std::size_t i = 0; i < count; ++i) v.push_back(number(n[i], item(key, i)));
  return v;
}

Interval YamlFields::range(const YAML::Node& n, const std::string& key, double unit) const {
  const std::vector<double> v = numbers(n, key, 2);
  if (!(v[0] < v[1])) fail(n, key, "lower bound must be below upper bound");
  return Interval(v[0] * unit, v[1] * unit);
}

Interval YamlFields::interval(const YAML::Node& n, const std::string& key) const {
  if (!n.IsSequence() || n.size() != 2) fail(n, key, "expected [lower, upper]");
  const double lo = number(n[0], item(key, 0)), hi = number(n[1], item(key, 1));
  if (!(lo <= hi)) fail(n, key, "lower bound above upper bound");
  return Interval(lo, hi);
}

std::string YamlFields::shown_key(const std::string& name) {
  const bool plain = !name.empty() && name.size() <= kQuotedLength && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
  return plain ? name : quoted_input(name);
}

}  // namespace gesmi::io
