#pragma once
// The one way io/ loads a YAML file (sensor model, localization scenario). yaml-cpp
// alone accepts files whose meaning differs from what the reader sees: a stray `...`
// or `---` line ends the document and the rest is silently dropped, a second document
// is ignored, a repeated key keeps its first value, a key can be a mapping or a list.
// The strict loader refuses all of these with one line "FILE:LINE: reason":
//
//   - at most one document, and when there is one it is a mapping of key: value;
//   - every key is a plain value (not a mapping, a list or empty), at most once per mapping;
//   - no anchors or aliases (&name, *name), nesting at most kMaxYamlDepth levels.
//
// A text with no document at all (empty, or only comments) gives a null node.

#include <yaml-cpp/yaml.h>

#include <string>

namespace gesmi::io {

inline constexpr int kMaxYamlDepth = 32;

/// The checked document of `text`; `source` names the input in errors.
YAML::Node load_strict_yaml(const std::string& text, const std::string& source);
/// The checked document of the file at path.
YAML::Node load_strict_yaml_file(const std::string& path);

}  // namespace gesmi::io
