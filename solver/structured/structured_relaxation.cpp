#include "solver/structured/structured_relaxation.h"

#include <algorithm>
#include <stdexcept>

#include "solver/lp/clp_program.h"
#include "solver/lp/dual_certificate.h"
#include "solver/network/sensors/sensor_boxes.h"
#include "solver/structured/affine_track.h"

namespace gesmi {
namespace {

using Form = AffineDisplacement;

// The anchor samples (first, last, and the sample at or before each fix within the
// navigation) and each one's box: the tube's, within every fix's box moved back by the
// displacement from the sample to the fix.
struct Anchors {
  std::vector<std::size_t> sample;
  std::vector<std::array<Interval, 2>> box;
};

Anchors anchors_of(const Mission& m, const SensorBoxes& whole, const std::vector<Interval>& north,
                   const std::vector<Interval>& east) {
  std::vector<std::pair<std::size_t, std::array<Interval, 2>>> found = {{0, {north[0], east[0]}},
                                                                        {m.size() - 1, {north.back(), east.back()}}};
  for (std::size_t g = 0; g < m.gps_time.size(); ++g) {
    const double t = m.gps_time[g];
    if (t < m.time.front() || t > m.time.back()) continue;  // (an unused fix costs width only)
    const auto k = static_cast<std::size_t>(std::upper_bound(m.time.begin(), m.time.end(), t) - m.time.begin()) - 1;
    std::array<Interval, 2> fix = {Interval::around(m.gps_north[g], m.gps_north_halfwidth[g]),
                                   Interval::around(m.gps_east[g], m.gps_east_halfwidth[g])};
    if (t > m.time[k]) {
      Vec3I forward, backward;
      whole.offsets_between(k, Interval(t) - Interval(m.time[k]), Interval(m.time[k + 1]) - Interval(t), forward,
                            backward);
      fix = {fix[0] - forward[0], fix[1] - forward[1]};
    }
    found.push_back({k, {intersect(fix[0], north[k]), intersect(fix[1], east[k])}});
  }
  std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  Anchors a;
  for (const auto& [k, box] : found) {
    if (!a.sample.empty() && a.sample.back() == k) {
      a.box.back() = {intersect(a.box.back()[0], box[0]), intersect(a.box.back()[1], box[1])};
    } else {
      a.sample.push_back(k);
      a.box.push_back(box);
    }
  }
  return a;
}

std::size_t position_column(std::size_t anchor, std::size_t axis) { return 2 * anchor + axis; }

// The program: positions at the anchors and the biases; a row per run and axis,
// P_i+1 - P_i - coefficient . z within value + rest.
LinearProgram program_of(const Anchors& a, const std::vector<Form>& runs, const StructuredErrors& errors) {
  LinearProgram lp;
  const std::size_t z0 = 2 * a.sample.size();
  lp.columns = z0 + kBiasTerms;
  for (const auto& box : a.box)
    for (const Interval& x : box) {
      lp.column_lower.push_back(x.lo());
      lp.column_upper.push_back(x.hi());
    }
  for (const double b : errors.bias_bound) {
    lp.column_lower.push_back(-b);
    lp.column_upper.push_back(b);
  }
  for (std::size_t i = 0; i < runs.size(); ++i)
    for (std::size_t axis = 0; axis < 2; ++axis) {
      std::vector<std::size_t> columns = {position_column(i + 1, axis), position_column(i, axis)};
      std::vector<double> values = {1.0, -1.0};
      for (std::size_t t = 0; t < kBiasTerms; ++t) {
        columns.push_back(z0 + t);
        values.push_back(-runs[i].coefficient[axis][t]);
      }
      const Interval bounds = Interval(runs[i].value[axis]) + runs[i].rest[axis];
      lp.add_row(columns, values, bounds.lo(), bounds.hi());
    }
  return lp;
}

// Lower bound (sign +1) or upper bound (sign -1) of one axis of the samples of a run,
// from the anchor before them (sigma +1: p_k = P_i + d) or after them (sigma -1:
// p_k = P_i+1 - d), with the multipliers of each grid point's sample for its part of the run.
struct Variant {
  std::size_t anchor, axis;
  double sign, sigma;
};

void bound_run(ClpProgram& clp, const LinearProgram& lp, const Variant& v, std::size_t first,
               const std::vector<Form>& forms, const RelaxationOptions& options, StructuredBounds& out) {
  const std::size_t z0 = lp.columns - kBiasTerms, grid = std::max<std::size_t>(options.grid, 1);
  std::vector<std::size_t> varying = {position_column(v.anchor, v.axis)};
  for (std::size_t t = 0; t < kBiasTerms; ++t) varying.push_back(z0 + t);
  const auto objective_at = [&](const Form& f) {
    std::array<double, 1 + kBiasTerms> c{v.sign};
    for (std::size_t t = 0; t < kBiasTerms; ++t) c[1 + t] = v.sign * v.sigma * f.coefficient[v.axis][t];
    return c;
  };
  std::vector<Interval>& bounds = v.axis == 0 ? out.north : out.east;
  for (std::size_t from = 0; from < forms.size(); from += grid) {
    const std::size_t to = std::min(forms.size(), from + grid);
    const auto c = objective_at(forms[(from + to) / 2]);
    std::vector<double> dense(lp.columns, 0.0);
    for (std::size_t j = 0; j < varying.size(); ++j) dense[varying[j]] = c[j];
    const ClpProgram::Answer answer = clp.minimize(dense);
    ++out.linear_programs;
    if (answer.status != ClpProgram::Status::optimal) continue;  // (the tube stays)
    const DualCertificate certificate(lp, answer.multipliers, varying);
    for (std::size_t r = from; r < to; ++r) {
      const Form& f = forms[r];
      const Interval lowest(certificate.lower_bound(objective_at(f)));
      const Interval shift = Interval(v.sigma) * (Interval(f.value[v.axis]) + f.rest[v.axis]);
      Interval& x = bounds[first + r];
      x = v.sign > 0 ? intersect(x, Interval((lowest + shift).lo(), kInf))
                     : intersect(x, Interval(-kInf, (shift - lowest).hi()));
    }
  }
}

// Whether the program is empty, by CLP's ray checked as a Farkas certificate (either sign).
bool proved_empty(ClpProgram& clp, const LinearProgram& lp) {
  const ClpProgram::Answer a = clp.minimize(std::vector<double>(lp.columns, 0.0));
  if (a.status != ClpProgram::Status::infeasible || a.multipliers.empty()) return false;
  std::vector<double> flipped(a.multipliers);
  for (double& x : flipped) x = -x;
  return certifies_empty(lp, a.multipliers) || certifies_empty(lp, flipped);
}

std::array<Interval, kBiasTerms> bias_bounds(ClpProgram& clp, const LinearProgram& lp, StructuredBounds& out) {
  std::array<Interval, kBiasTerms> bias;
  const std::size_t z0 = lp.columns - kBiasTerms;
  for (std::size_t t = 0; t < kBiasTerms; ++t) {
    std::array<double, 2> side{};
    for (const double sign : {1.0, -1.0}) {
      std::vector<double> c(lp.columns, 0.0);
      c[z0 + t] = sign;
      const ClpProgram::Answer a = clp.minimize(c);
      ++out.linear_programs;
      const double lowest =
          a.status == ClpProgram::Status::optimal ? certified_lower_bound(lp, c, a.multipliers) : -kInf;
      side[sign > 0 ? 0 : 1] =
          sign > 0 ? std::max(lowest, lp.column_lower[z0 + t]) : std::min(-lowest, lp.column_upper[z0 + t]);
    }
    bias[t] = Interval(side[0], side[1]);
  }
  return bias;
}

}  // namespace

std::string structured_relaxation_refusal(const Mission& mission) {
  if (!mission.half_widths.empty())
    return "the mission's readings carry their own half-widths, whose split into bias and noise is not known";
  if (mission.model.step_model != StepModel::trapezoid)
    return "the bias-and-noise model needs the trapezoid step model";
  return {};
}

StructuredBounds relax_structured(const Mission& m, const StepRegimes& regimes, const StructuredErrors& errors,
                                  const std::vector<Interval>& north, const std::vector<Interval>& east,
                                  const RelaxationOptions& options) {
  if (const std::string why = structured_relaxation_refusal(m); !why.empty()) throw std::invalid_argument(why);
  if (m.size() < 2 || north.size() != m.size() || east.size() != m.size())
    throw std::invalid_argument("relax_structured: the tube must have one box per sample, and the mission two samples");
  StructuredBounds out;
  out.north = north;
  out.east = east;
  const FrameMargins frame = zone_frame(m);
  const SensorBoxes noise(m, errors.noise, frame), whole(m, m.model, frame, &regimes);
  const Anchors a = anchors_of(m, whole, north, east);
  StepSums sums(m, noise, whole);
  std::vector<Form> runs;
  for (std::size_t i = 0; i + 1 < a.sample.size(); ++i) {
    sums.clear();
    for (std::size_t k = a.sample[i]; k < a.sample[i + 1]; ++k) sums.add_step(k);
    runs.push_back(sums.form(errors.bias_bound));
  }
  const LinearProgram lp = program_of(a, runs, errors);
  ClpProgram clp(lp);
  if (proved_empty(clp, lp)) {
    out.consistent = false;
    return out;
  }
  out.bias = bias_bounds(clp, lp, out);
  for (std::size_t i = 0; i + 1 < a.sample.size(); ++i) {
    const std::size_t first = a.sample[i], length = a.sample[i + 1] - first + 1;
    std::vector<Form> forward(length), backward(length);
    sums.clear();
    for (std::size_t r = 1; r < length; ++r) {
      sums.add_step(first + r - 1);
      forward[r] = sums.form(errors.bias_bound);
    }
    sums.clear();
    for (std::size_t r = length - 1; r-- > 0;) {
      sums.add_step(first + r);
      backward[r] = sums.form(errors.bias_bound);
    }
    for (std::size_t axis = 0; axis < 2; ++axis)
      for (const double sign : {1.0, -1.0}) {
        bound_run(clp, lp, {i, axis, sign, 1.0}, first, forward, options, out);
        bound_run(clp, lp, {i + 1, axis, sign, -1.0}, first, backward, options, out);
      }
  }
  for (std::size_t k = 0; k < m.size(); ++k)
    if (out.north[k].is_empty() || out.east[k].is_empty()) out.consistent = false;
  return out;
}

}  // namespace gesmi
