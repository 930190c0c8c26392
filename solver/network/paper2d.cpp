#include "solver/network/paper2d.h"

#include <cmath>

#include "solver/ctc/ctc_distance.h"
#include "solver/ctc/ctc_add.h"

namespace gesmi {
namespace {

// Variable layout of the box: x(0..4), v(0..3), m, z(1..3).
constexpr int x_index(int k, int j) { return 2 * k + j; }
constexpr int v_index(int k, int j) { return 10 + 2 * k + j; }
constexpr int m_index(int j) { return 18 + j; }
constexpr int z_index(int k) { return 20 + (k - 1); }  // k = 1..3
constexpr int kVariables = 23;

// [a - d, a + 2d] rounded outward; d = inf gives the whole line.
Interval measured(double a, double d) {
  if (d == 0.0) return Interval(a);  // a - 0 and a + 0 are exact
  return Interval(sub_down(a, d), add_up(a, mul_up(2.0, d)));
}

Box to_box(const Paper2dDomains& d) {
  Box box(kVariables);
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 2; ++j) box[x_index(k, j)] = d.x[static_cast<std::size_t>(k)][static_cast<std::size_t>(j)];
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 2; ++j) box[v_index(k, j)] = d.v[static_cast<std::size_t>(k)][static_cast<std::size_t>(j)];
  for (int j = 0; j < 2; ++j) box[m_index(j)] = d.m[static_cast<std::size_t>(j)];
  for (int k = 1; k <= 3; ++k) box[z_index(k)] = d.z[static_cast<std::size_t>(k - 1)];
  return box;
}

Paper2dDomains from_box(const Box& box) {
  Paper2dDomains d;
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 2; ++j) d.x[static_cast<std::size_t>(k)][static_cast<std::size_t>(j)] = box[x_index(k, j)];
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 2; ++j) d.v[static_cast<std::size_t>(k)][static_cast<std::size_t>(j)] = box[v_index(k, j)];
  for (int j = 0; j < 2; ++j) d.m[static_cast<std::size_t>(j)] = box[m_index(j)];
  for (int k = 1; k <= 3; ++k) d.z[static_cast<std::size_t>(k - 1)] = box[z_index(k)];
  return d;
}

}  // namespace

std::string Paper2dDeltas::validate() const {
  const std::pair<const char*, double> all[] = {{"delta-v", v}, {"delta-z", z}, {"delta-x", x}};
  for (const auto& [name, value] : all)
    if (std::isnan(value) || value < 0.0) return std::string(name) + " must be a number >= 0 (inf allowed)";
  return {};
}

Paper2dDomains paper2d_prior(const Paper2dDeltas& deltas, const Paper2dTruth& truth) {
  Paper2dDomains d;  // default intervals are the whole line: x(1..3), m unmeasured
  d.x[0] = {Interval(truth.x[0][0]), Interval(truth.x[0][1])};
  for (std::size_t j = 0; j < 2; ++j) d.x[4][j] = measured(truth.x[4][j], deltas.x);
  for (std::size_t k = 0; k < 4; ++k)
    for (std::size_t j = 0; j < 2; ++j) d.v[k][j] = measured(truth.v[k][j], deltas.v);
  for (std::size_t k = 0; k < 3; ++k) d.z[k] = measured(truth.z[k], deltas.z);
  return d;
}

Paper2dResult solve_paper2d(const Paper2dDomains& prior, const PropagationOptions& options) {
  std::vector<CtcAny> contractors;
  for (int k = 0; k < 4; ++k) {
    for (int j = 0; j < 2; ++j) {
      contractors.emplace_back(CtcAdd(x_index(k + 1, j), x_index(k, j), v_index(k, j)));
    }
  }
  for (int k = 1; k <= 3; ++k)
    contractors.emplace_back(CtcDistance<2>(z_index(k), {x_index(k, 0), x_index(k, 1)}, {m_index(0), m_index(1)}));
  Box box = to_box(prior);
  Paper2dResult result;
  result.report = propagate(contractors, box, options);
  result.domains = from_box(box);
  return result;
}

}  // namespace gesmi
