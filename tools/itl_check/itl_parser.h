#pragma once
// Parser of the ITL test format of ITF1788 (tests/data/itf1788/README.md):
//   testcase NAME { OPERATION ARG... = RESULT... [signal NAME]; ... }
// with // and /* */ comments, intervals [lo,hi], [empty], [entire], [nai],
// decorations (_com, _dac, _def, _trv), decimal and C99 hex floats, infinity.
// Numbers are read as the nearest double, as the ITF1788 back ends do.

#include <istream>
#include <stdexcept>
#include <string>
#include <vector>

#include "solver/interval/interval.h"

namespace gesmi::itl {

struct Value {
  enum class Kind { interval, number, boolean };
  Kind kind = Kind::number;
  Interval interval;
  double number = 0.0;
  bool boolean = false;
  bool decorated = false;  // a decoration suffix, or [nai]
};

struct Test {
  std::string testcase;
  std::string operation;
  std::vector<Value> args;
  std::vector<Value> results;
  bool signals = false;  // expects an exception ("signal NAME")
  int line = 0;
};

/// A malformed file: the message names the line.
class ParseError : public std::runtime_error {
 public:
  ParseError(int line, const std::string& what) : std::runtime_error("line " + std::to_string(line) + ": " + what) {}
};

/// All tests of an ITL text, in order. Throws ParseError.
std::vector<Test> parse(std::istream& in);

/// A test is decorated when any argument or result is.
bool is_decorated(const Test& test);

}  // namespace gesmi::itl
