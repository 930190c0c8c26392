#include "tools/itl_check/itl_parser.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iterator>

namespace gesmi::itl {
namespace {

struct Token {
  std::string text;
  int line = 0;
};

bool is_punctuation(char c) { return c == '[' || c == ']' || c == ',' || c == ';' || c == '{' || c == '}' || c == '='; }
bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }

// Splits the text into words and punctuation, dropping comments. A decoration
// directly after ']' ("]_com") becomes its own word starting with '_'.
std::vector<Token> tokenize(const std::string& text) {
  std::vector<Token> tokens;
  int line = 1;
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (c == '\n') ++line;
    if (is_space(c)) {
      ++i;
    } else if (text.compare(i, 2, "//") == 0) {
      i = text.find('\n', i);
      if (i == std::string::npos) i = text.size();
    } else if (text.compare(i, 2, "/*") == 0) {
      const std::size_t end = text.find("*/", i + 2);
      if (end == std::string::npos) throw ParseError(line, "unterminated comment");
      for (std::size_t k = i; k < end; ++k) line += text[k] == '\n';
      i = end + 2;
    } else if (is_punctuation(c)) {
      tokens.push_back({std::string(1, c), line});
      ++i;
    } else {
      const std::size_t start = i;
      while (i < text.size() && !is_space(text[i]) && !is_punctuation(text[i]) && text.compare(i, 2, "//") != 0 &&
             text.compare(i, 2, "/*") != 0)
        ++i;
      tokens.push_back({text.substr(start, i - start), line});
    }
  }
  return tokens;
}

// Reads the number in `word` (decimal, hex float, infinity, NaN) as the nearest double.
bool to_number(const std::string& word, double& value) {
  if (word.empty()) return false;
  const char* begin = word.c_str();
  char* end = nullptr;
  errno = 0;
  value = std::strtod(begin, &end);
  return end == begin + word.size();
}

class Parser {
 public:
  explicit Parser(std::vector<Token> tokens) : tokens_(std::move(tokens)) {}

  std::vector<Test> file() {
    std::vector<Test> tests;
    while (!at_end()) {
      expect("testcase");
      const std::string name = word("a test case name");
      expect("{");
      while (!accept("}")) tests.push_back(statement(name));
    }
    return tests;
  }

 private:
  Test statement(const std::string& testcase) {
    Test test;
    test.testcase = testcase;
    test.line = peek().line;
    test.operation = word("an operation name");
    while (!accept("=")) test.args.push_back(value());
    while (!accept(";")) {
      if (accept("signal")) {
        test.signals = true;
        word("an exception name");
        continue;
      }
      test.results.push_back(value());
    }
    if (test.results.empty() && !test.signals) throw ParseError(test.line, "test without an expected result");
    return test;
  }

  Value value() {
    Value v;
    if (accept("[")) {
      v.kind = Value::Kind::interval;
      v.interval = interval_body(v.decorated);
      if (!at_end() && peek().text.size() > 1 && peek().text[0] == '_') {
        const std::string decoration = next().text;
        if (decoration != "_com" && decoration != "_dac" && decoration != "_def" && decoration != "_trv" && decoration != "_ill")
          throw ParseError(line(), "unknown decoration '" + decoration + "'");
        v.decorated = true;
      }
      return v;
    }
    const std::string w = word("a value");
    if (w == "true" || w == "false") {
      v.kind = Value::Kind::boolean;
      v.boolean = (w == "true");
      return v;
    }
    if (!to_number(w, v.number)) throw ParseError(line(), "expected a value, got '" + w + "'");
    return v;
  }

  // After '[': "empty]", "entire]", "nai]", "a, b]" or "a]".
  Interval interval_body(bool& decorated) {
    const std::string first = word("an interval bound");
    if (first == "empty" || first == "entire" || first == "nai") {
      expect("]");
      decorated = (first == "nai");
      return first == "entire" ? Interval::entire() : Interval::empty();
    }
    double lo = 0.0, hi = 0.0;
    if (!to_number(first, lo)) throw ParseError(line(), "expected a number, got '" + first + "'");
    hi = lo;
    if (accept(",")) {
      const std::string second = word("an interval bound");
      if (!to_number(second, hi)) throw ParseError(line(), "expected a number, got '" + second + "'");
    }
    expect("]");
    if (std::isnan(lo) || std::isnan(hi) || lo > hi || lo == kInf || hi == -kInf)
      throw ParseError(line(), "invalid interval [" + first + ", ...]");
    return Interval(lo, hi);
  }

  bool at_end() const { return pos_ >= tokens_.size(); }
  const Token& peek() const {
    if (at_end()) throw ParseError(tokens_.empty() ? 1 : tokens_.back().line, "unexpected end of file");
    return tokens_[pos_];
  }
  const Token& next() {
    const Token& t = peek();
    ++pos_;
    return t;
  }
  int line() const { return pos_ == 0 ? 1 : tokens_[std::min(pos_, tokens_.size()) - 1].line; }
  bool accept(const char* text) {
    if (at_end() || peek().text != text) return false;
    ++pos_;
    return true;
  }
  void expect(const char* text) {
    const Token& t = next();
    if (t.text != text) throw ParseError(t.line, std::string("expected '") + text + "', got '" + t.text + "'");
  }
  std::string word(const char* what) {
    const Token& t = next();
    if (t.text.size() == 1 && is_punctuation(t.text[0]))
      throw ParseError(t.line, std::string("expected ") + what + ", got '" + t.text + "'");
    return t.text;
  }

  std::vector<Token> tokens_;
  std::size_t pos_ = 0;
};

}  // namespace

std::vector<Test> parse(std::istream& in) {
  const std::string text(std::istreambuf_iterator<char>(in), {});
  return Parser(tokenize(text)).file();
}

bool is_decorated(const Test& test) {
  for (const Value& v : test.args)
    if (v.decorated) return true;
  for (const Value& v : test.results)
    if (v.decorated) return true;
  return false;
}

}  // namespace gesmi::itl
