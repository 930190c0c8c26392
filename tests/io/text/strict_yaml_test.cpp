// The strict YAML loader: one document, a mapping, plain keys once each, no anchors,
// bounded nesting; every refusal one line naming the file and the line.

#include "io/text/strict_yaml.h"

#include <gtest/gtest.h>

#include <string>

#include "io/format_error.h"

namespace gesmi::io {
namespace {

// The message of the refusal of `text`, or "" when it is accepted.
std::string refusal(const std::string& text) {
  try {
    load_strict_yaml(text, "f.yaml");
    return "";
  } catch (const FormatError& e) {
    return e.what();
  }
}

TEST(StrictYaml, AcceptsOneMappingAndReadsItAsYamlCppDoes) {
  const YAML::Node n = load_strict_yaml("# model\nheading: 0.01\nside: port\nlist: [1, 2]\nmap: {a: 1}\n...\n", "f.yaml");
  ASSERT_TRUE(n.IsMap());
  EXPECT_EQ(n["heading"].as<double>(), 0.01);
  EXPECT_EQ(n["list"].size(), 2u);
  EXPECT_EQ(n["map"]["a"].as<int>(), 1);
  EXPECT_TRUE(load_strict_yaml("", "f.yaml").IsNull());
  EXPECT_TRUE(load_strict_yaml("# only a comment\n\n", "f.yaml").IsNull());
}

TEST(StrictYaml, RefusesWhatYamlCppWouldSilentlyReadOtherwise) {
  struct Case {
    const char* text;
    const char* expected;  // beginning of the message
  };
  const Case cases[] = {
      {"...\nheading: 1\n", "f.yaml:1: the YAML document is empty"},
      {",,,,\nheading: 1\n", "f.yaml:1: the YAML document is empty"},
      {"---\n", "f.yaml:2: the YAML document is empty"},
      {"~\n", "f.yaml:1: the YAML document is empty"},
      {"heading: 1\n---\nheading: 2\n", "f.yaml:2: a second YAML document"},
      {"heading: 1\n...\nheading: 2\n", "f.yaml:3: a second YAML document"},
      {"a: 1\nb: 2\na: 3\n", "f.yaml:3: key 'a' repeated (first on line 1)"},
      {"m:\n  x: 1\n  x: 2\n", "f.yaml:3: key 'x' repeated (first on line 2)"},
      {"{a: 1}: 3\n", "f.yaml:1: a key must be a name, found a mapping"},
      {"[1, 2]: 3\n", "f.yaml:1: a key must be a name, found a list"},
      {"? [a, b]\n: 3\n", "f.yaml:1: a key must be a name, found a list"},
      {"~: 3\n", "f.yaml:1: a key must be a name, found nothing"},
      {"- 1\n- 2\n", "f.yaml:1: expected a mapping of key: value, found a list"},
      {"just text\n", "f.yaml:1: expected a mapping of key: value, found a value"},
      {"a: &x 1\nb: 2\n", "f.yaml:1: anchors (&name) are not supported"},
      {"a: *x\n", "f.yaml:1: "},
      {"a: [1, 2\n", "f.yaml:2: not valid YAML: "},
  };
  for (const Case& c : cases) {
    const std::string m = refusal(c.text);
    EXPECT_EQ(m.rfind(c.expected, 0), 0u) << "text: " << c.text << "\nmessage: " << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
}

TEST(StrictYaml, NestingIsBoundedBeforeYamlCppRecursesDeeply) {
  const std::string deep = "a: " + std::string(100000, '[') + std::string(100000, ']') + "\n";
  EXPECT_EQ(refusal(deep).rfind("f.yaml:1: ", 0), 0u) << refusal(deep).substr(0, 200);
  const std::string ok = "a: " + std::string(kMaxYamlDepth - 2, '[') + std::string(kMaxYamlDepth - 2, ']') + "\n";
  EXPECT_EQ(refusal(ok), "");
}

TEST(StrictYaml, RepeatedKeysAreEscapedAndCutInTheMessage) {
  const std::string key = "k\x07" + std::string(200, 'y');
  const std::string m = refusal(key + ": 1\n" + key + ": 2\n");
  EXPECT_NE(m.find("key 'k\\x07yyy"), std::string::npos) << m;
  EXPECT_LT(m.size(), 150u) << m;
}

TEST(StrictYaml, FileErrorsNameThePath) {
  try {
    load_strict_yaml_file("/no/such/file.yaml");
    ADD_FAILURE();
  } catch (const FormatError& e) {
    EXPECT_EQ(std::string(e.what()), "/no/such/file.yaml: cannot open the file (does it exist?)");
  }
  try {
    load_strict_yaml_file("/");
    ADD_FAILURE();
  } catch (const FormatError& e) {
    EXPECT_EQ(std::string(e.what()), "/: is a folder, not a file");
  }
}

}  // namespace
}  // namespace gesmi::io
