#include "tools/itl_check/itl_runner.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <map>
#include <string_view>

#include "solver/interval/interval.h"
#include "solver/interval/interval_reverse.h"

namespace gesmi::itl {
namespace {

using Values = std::vector<Value>;

Value of(const Interval& x) {
  Value v;
  v.kind = Value::Kind::interval;
  v.interval = x;
  return v;
}
Value of_number(double x) {
  Value v;
  v.number = x;
  return v;
}
Value of_bool(bool b) {
  Value v;
  v.kind = Value::Kind::boolean;
  v.boolean = b;
  return v;
}

// An operation: its argument kinds ('I' interval, 'N' integer) and its evaluation.
struct Operation {
  std::string_view signature;
  std::function<Values(const Values&)> evaluate;
};

int integer(const Value& v) { return static_cast<int>(v.number); }

using Unary = Interval (*)(const Interval&);
using Binary = Interval (*)(const Interval&, const Interval&);
Operation unary(Unary f) {
  return {"I", [f](const Values& a) { return Values{of(f(a[0].interval))}; }};
}
Operation binary(Binary f) {
  return {"II", [f](const Values& a) { return Values{of(f(a[0].interval, a[1].interval))}; }};
}
template <class F>
Operation number(F f) {
  return {"I", [f](const Values& a) { return Values{of_number(f(a[0].interval))}; }};
}
template <class F>
Operation predicate(std::string_view signature, F f) {
  return {signature, [f](const Values& a) {
            return Values{of_bool(a.size() == 1 ? f(a[0].interval, a[0].interval) : f(a[0].interval, a[1].interval))};
          }};
}

// The IEEE 1788 names the library implements, mapped to its functions.
const std::map<std::string_view, Operation>& operations() {
  static const std::map<std::string_view, Operation> table = {
      {"pos", unary([](const Interval& x) { return x; })},
      {"neg", unary([](const Interval& x) { return -x; })},
      {"add", binary([](const Interval& x, const Interval& y) { return x + y; })},
      {"sub", binary([](const Interval& x, const Interval& y) { return x - y; })},
      {"mul", binary([](const Interval& x, const Interval& y) { return x * y; })},
      {"div", binary([](const Interval& x, const Interval& y) { return x / y; })},
      {"recip", unary(recip)},
      {"sqr", unary(sqr)},
      {"sqrt", unary(sqrt)},
      {"pown", {"IN", [](const Values& a) { return Values{of(pow(a[0].interval, integer(a[1])))}; }}},
      {"exp", unary(exp)},
      {"log", unary(log)},
      {"sin", unary(sin)},
      {"cos", unary(cos)},
      {"tan", unary(tan)},
      {"atan", unary(atan)},
      {"atan2", binary(atan2)},
      {"abs", unary([](const Interval& x) { return abs(x); })},
      {"min", binary([](const Interval& x, const Interval& y) { return min(x, y); })},
      {"max", binary([](const Interval& x, const Interval& y) { return max(x, y); })},
      {"intersection", binary([](const Interval& x, const Interval& y) { return intersect(x, y); })},
      {"convexHull", binary([](const Interval& x, const Interval& y) { return hull(x, y); })},
      {"inf", number([](const Interval& x) { return x.lo(); })},
      {"sup", number([](const Interval& x) { return x.hi(); })},
      {"mid", number([](const Interval& x) { return x.mid(); })},
      {"wid", number([](const Interval& x) { return x.width(); })},
      {"rad", number([](const Interval& x) { return x.rad(); })},
      {"mag", number([](const Interval& x) { return x.mag(); })},
      {"mig", number([](const Interval& x) { return x.mig(); })},
      {"isEmpty", predicate("I", [](const Interval& x, const Interval&) { return x.is_empty(); })},
      {"isEntire", predicate("I", [](const Interval& x, const Interval&) { return x.is_entire(); })},
      {"subset", predicate("II", [](const Interval& x, const Interval& y) { return x.is_subset(y); })},
      {"interior", predicate("II", [](const Interval& x, const Interval& y) { return x.is_interior_subset(y); })},
      {"equal", predicate("II", [](const Interval& x, const Interval& y) { return x == y; })},
      {"disjoint", predicate("II", [](const Interval& x, const Interval& y) { return !x.intersects(y); })},
      {"precedes", predicate("II", precedes)},
      {"strictPrecedes", predicate("II", strictly_precedes)},
      {"less", predicate("II", weakly_less)},
      {"strictLess", predicate("II", strictly_less)},
      {"sqrRev", unary([](const Interval& c) { return sqr_rev(c); })},
      {"sqrRevBin", binary([](const Interval& c, const Interval& x) { return sqr_rev(c, x); })},
      {"absRev", unary([](const Interval& c) { return abs_rev(c); })},
      {"absRevBin", binary([](const Interval& c, const Interval& x) { return abs_rev(c, x); })},
      {"sinRev", unary([](const Interval& c) { return sin_rev(c); })},
      {"sinRevBin", binary([](const Interval& c, const Interval& x) { return sin_rev(c, x); })},
      {"cosRev", unary([](const Interval& c) { return cos_rev(c); })},
      {"cosRevBin", binary([](const Interval& c, const Interval& x) { return cos_rev(c, x); })},
      {"tanRev", unary([](const Interval& c) { return tan_rev(c); })},
      {"tanRevBin", binary([](const Interval& c, const Interval& x) { return tan_rev(c, x); })},
      {"mulRev", binary([](const Interval& b, const Interval& c) { return mul_rev(b, c); })},
      {"mulRevTen",
       {"III", [](const Values& a) { return Values{of(mul_rev(a[0].interval, a[1].interval, a[2].interval))}; }}},
      {"mulRevToPair", {"II", [](const Values& a) {
                          const auto [first, second] = mul_rev_to_pair(a[0].interval, a[1].interval);
                          return Values{of(first), of(second)};
                        }}},
      {"pownRev",
       {"IN", [](const Values& a) { return Values{of(pow_rev(a[0].interval, Interval::entire(), integer(a[1])))}; }}},
      {"pownRevBin",
       {"IIN", [](const Values& a) { return Values{of(pow_rev(a[0].interval, a[1].interval, integer(a[2])))}; }}},
  };
  return table;
}

bool matches(std::string_view signature, const Values& args) {
  if (signature.size() != args.size()) return false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const Value& a = args[i];
    if (signature[i] == 'I' && a.kind != Value::Kind::interval) return false;
    if (signature[i] == 'N' && (a.kind != Value::Kind::number || a.number != std::trunc(a.number) ||
                                std::fabs(a.number) > 2147483647.0))
      return false;
  }
  return true;
}

// Monotone map of doubles to integers: consecutive doubles differ by 1.
std::int64_t ordinal(double x) {
  const auto bits = std::bit_cast<std::int64_t>(x);
  return bits < 0 ? std::numeric_limits<std::int64_t>::min() - bits : bits;
}

double interval_excess(const Interval& got, const Interval& expected) {
  if (expected.is_empty()) return got.is_empty() ? 0.0 : kInf;
  return ulp_distance(got.lo(), expected.lo()) + ulp_distance(expected.hi(), got.hi());
}

bool same_number(double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; }

// Checks one result; returns an empty string when it is acceptable.
std::string check(const Value& got, const Value& expected, double& excess) {
  if (got.kind != expected.kind) return "result of another kind";
  switch (expected.kind) {
    case Value::Kind::interval:
      if (!got.interval.is_superset(expected.interval)) return "does not contain the expected interval";
      excess += interval_excess(got.interval, expected.interval);
      return {};
    case Value::Kind::number:
      return same_number(got.number, expected.number) ? std::string() : "number differs";
    case Value::Kind::boolean:
      return got.boolean == expected.boolean ? std::string() : "Boolean differs";
  }
  return {};
}

std::string list(const Values& values) {
  std::string s;
  for (const Value& v : values) s += (s.empty() ? "" : " ") + to_string(v);
  return s;
}

}  // namespace

double ulp_distance(double a, double b) {
  if (a == b) return 0.0;
  if (std::isinf(a) || std::isinf(b)) return kInf;
  if (b < a) return -ulp_distance(b, a);
  // Up to 2^64 - 2 steps between the finite doubles: the difference of the ordinals
  // overflows int64 but is exact in uint64 (modular, and it is non-negative here).
  return static_cast<double>(static_cast<std::uint64_t>(ordinal(b)) - static_cast<std::uint64_t>(ordinal(a)));
}

std::string to_string(const Value& value) {
  char buffer[128];
  switch (value.kind) {
    case Value::Kind::interval:
      if (value.interval.is_empty()) return "[empty]";
      std::snprintf(buffer, sizeof buffer, "[%a, %a]", value.interval.lo(), value.interval.hi());
      return buffer;
    case Value::Kind::number:
      std::snprintf(buffer, sizeof buffer, "%a", value.number);
      return buffer;
    case Value::Kind::boolean:
      return value.boolean ? "true" : "false";
  }
  return {};
}

TestResult run(const Test& test) {
  TestResult result;
  if (is_decorated(test)) return {Outcome::skipped, "decorated", -1.0};
  if (test.signals) return {Outcome::skipped, "expects an exception", -1.0};
  const auto it = operations().find(test.operation);
  if (it == operations().end()) return {Outcome::skipped, "not implemented", -1.0};
  if (!matches(it->second.signature, test.args)) return {Outcome::failed, "arguments do not match the operation", -1.0};
  const Values got = it->second.evaluate(test.args);
  if (got.size() != test.results.size()) return {Outcome::failed, "wrong number of results", -1.0};
  double excess = 0.0;
  bool has_interval = false;
  for (std::size_t i = 0; i < got.size(); ++i) {
    has_interval |= test.results[i].kind == Value::Kind::interval;
    const std::string problem = check(got[i], test.results[i], excess);
    if (!problem.empty()) {
      result.outcome = Outcome::failed;
      result.message = test.operation + " " + list(test.args) + ": expected " + list(test.results) + ", got " +
                       list(got) + " (" + problem + ")";
      return result;
    }
  }
  result.outcome = Outcome::passed;
  result.excess_ulps = has_interval ? excess : -1.0;
  return result;
}

}  // namespace gesmi::itl
