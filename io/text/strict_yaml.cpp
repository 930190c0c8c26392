#include "io/text/strict_yaml.h"

#include <yaml-cpp/eventhandler.h>

#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include "io/format_error.h"
#include "io/input_file.h"
#include "io/text/message_text.h"

namespace gesmi::io {
namespace {

std::string at(const std::string& source, const YAML::Mark& mark) {
  return mark.line >= 0 ? source + ":" + std::to_string(mark.line + 1) : source;
}

// Checks the parser's events of every document (yaml-cpp's node builder forgets what
// the rules need: document boundaries, repeated keys, anchors).
class StrictEvents : public YAML::EventHandler {
 public:
  explicit StrictEvents(const std::string& source) : source_(source) {}

  void OnDocumentStart(const YAML::Mark& mark) override {
    if (++documents_ > 1)
      fail(mark, "a second YAML document ('---' or '...' ended the first): a file holds one document");
  }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override { node(mark, Kind::null, anchor); }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t) override {
    fail(mark, "aliases (*name) are not supported: write the value");
  }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor, const std::string& value) override {
    node(mark, Kind::scalar, anchor, &value);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor, YAML::EmitterStyle::value) override {
    node(mark, Kind::sequence, anchor);
    levels_.push_back({false, true, {}});
  }
  void OnSequenceEnd() override { levels_.pop_back(); }
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor, YAML::EmitterStyle::value) override {
    node(mark, Kind::mapping, anchor);
    levels_.push_back({true, true, {}});
  }
  void OnMapEnd() override { levels_.pop_back(); }

 private:
  enum class Kind { null, scalar, sequence, mapping };
  struct Level {
    bool mapping;
    bool at_key;                       // the next node of a mapping is a key
    std::map<std::string, int> keys;   // key -> line (1-based)
  };

  [[noreturn]] void fail(const YAML::Mark& mark, const std::string& reason) const {
    throw FormatError(at(source_, mark) + ": " + reason);
  }

  static const char* name(Kind kind) {
    switch (kind) {
      case Kind::null: return "nothing";
      case Kind::scalar: return "a value";
      case Kind::sequence: return "a list";
      default: return "a mapping";
    }
  }

  void node(const YAML::Mark& mark, Kind kind, YAML::anchor_t anchor, const std::string* scalar = nullptr) {
    if (anchor != YAML::NullAnchor) fail(mark, "anchors (&name) are not supported: write the value");
    if (levels_.empty()) {
      if (kind == Kind::null) fail(mark, "the YAML document is empty where a mapping of key: value was expected (a stray line such as '...', '---' or ',,,'?)");
      if (kind != Kind::mapping) fail(mark, std::string("expected a mapping of key: value, found ") + name(kind));
      return;
    }
    if (static_cast<int>(levels_.size()) >= kMaxYamlDepth)
      fail(mark, "nested deeper than " + std::to_string(kMaxYamlDepth) + " levels");
    Level& parent = levels_.back();
    if (!parent.mapping) return;
    parent.at_key = !parent.at_key;
    if (parent.at_key) return;  // this node was the value
    if (kind != Kind::scalar) fail(mark, std::string("a key must be a name, found ") + name(kind));
    const auto [first, inserted] = parent.keys.emplace(*scalar, mark.line + 1);
    if (!inserted)
      fail(mark, "key " + quoted_input(*scalar) + " repeated (first on line " + std::to_string(first->second) + ")");
  }

  const std::string& source_;
  int documents_ = 0;
  std::vector<Level> levels_;
};

}  // namespace

YAML::Node load_strict_yaml(const std::string& text, const std::string& source) {
  try {
    std::istringstream events_in(text);
    YAML::Parser parser(events_in);
    StrictEvents events(source);
    while (parser.HandleNextDocument(events)) {
    }
    return YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw FormatError(at(source, e.mark) + ": not valid YAML: " + one_line(e.msg));  // e.msg may hold a NUL
  }
}

YAML::Node load_strict_yaml_file(const std::string& path) {
  require_regular_file(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FormatError(path + ": cannot open the file (does it exist?)");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad() || text.bad()) throw FormatError(path + ": cannot read the file");
  return load_strict_yaml(text.str(), path);
}

}  // namespace gesmi::io
