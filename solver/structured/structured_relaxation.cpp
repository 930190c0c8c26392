#include "solver/structured/structured_relaxation.h"

#include <algorithm>
#include <optional>
#include <stdexcept>

#include "solver/lp/clp_program.h"
#include "solver/lp/dual_certificate.h"
#include "solver/network/mission_network.h"
#include "solver/network/sensors/sensor_boxes.h"
#include "solver/structured/affine_track.h"

namespace gesmi {
namespace {

using Form = AffineDisplacement;

// The anchor samples (first, last, and the sample at or before each fix and each mark)
// and each one's box: the tube's, within every fix's box moved back by the displacement
// from the sample to the fix. A mark of mine i ties that mine to its anchor: M_i - P in
// the displacement from the sample to the mark time minus the sonar's offset e = p - m.
struct MarkTie {
  std::size_t sample = 0;
  std::size_t mine = 0;
  std::array<Interval, 2> mine_minus_position;
};

struct Anchors {
  std::vector<std::size_t> sample;
  std::vector<std::array<Interval, 2>> box;
  std::vector<MarkTie> marks;
  std::size_t index_of(std::size_t k) const {
    return static_cast<std::size_t>(std::lower_bound(sample.begin(), sample.end(), k) - sample.begin());
  }
};

// e = p - m that the sonar plane allows for this detection, horizontally: the plane
// contracted with the robot at the origin and the mine anywhere within reach.
std::optional<std::array<Interval, 2>> sonar_offset(const Detection& d) {
  const double reach = add_up(d.range.hi(), add_up(d.plane.frame_slack, 1.0));
  Vec3I q(Interval(0.0), Interval(0.0), Interval(0.0));
  Vec3I mine(Interval(-reach, reach), Interval(-reach, reach), Interval(-reach, reach));
  Interval r = d.range;
  if (!d.plane.contract(q, mine, r)) return std::nullopt;
  return std::array<Interval, 2>{q[0] - mine[0], q[1] - mine[1]};
}

Anchors anchors_of(const MissionNetwork& net, const TubeDomains& tube) {
  const std::size_t last = tube.size() - 1;
  std::vector<std::pair<std::size_t, std::array<Interval, 2>>> found = {{0, {tube.px[0], tube.py[0]}},
                                                                        {last, {tube.px[last], tube.py[last]}}};
  const auto moved_back = [](const TimeLocation& at, const std::array<Interval, 2>& box) {
    return at.on_grid ? box : std::array<Interval, 2>{box[0] - at.forward[0], box[1] - at.forward[1]};
  };
  for (const Anchor& a : net.anchors) {
    const std::array<Interval, 2> fix = moved_back(a.at, {a.fix.box[0], a.fix.box[1]});
    found.push_back({a.at.k, {intersect(fix[0], tube.px[a.at.k]), intersect(fix[1], tube.py[a.at.k])}});
  }
  Anchors out;
  for (const Detection& d : net.detections) {
    if (d.mine < 0) continue;  // (an unassociated mark left out costs width only)
    const auto e = sonar_offset(d);
    if (!e) continue;
    const TimeLocation& at = d.at;  // p(t) - P: at.forward off the grid
    const Interval north = at.on_grid ? Interval(0.0) : at.forward[0],
                   east = at.on_grid ? Interval(0.0) : at.forward[1];
    out.marks.push_back({at.k, static_cast<std::size_t>(d.mine), {north - (*e)[0], east - (*e)[1]}});
    found.push_back({at.k, {tube.px[at.k], tube.py[at.k]}});
  }
  std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [k, box] : found) {
    if (!out.sample.empty() && out.sample.back() == k) {
      out.box.back() = {intersect(out.box.back()[0], box[0]), intersect(out.box.back()[1], box[1])};
    } else {
      out.sample.push_back(k);
      out.box.push_back(box);
    }
  }
  return out;
}

// Columns: the positions at the anchors (2 each), the mines (2 each), the biases.
std::size_t position_column(std::size_t anchor, std::size_t axis) { return 2 * anchor + axis; }
std::size_t mine_column(const Anchors& a, std::size_t mine, std::size_t axis) {
  return 2 * a.sample.size() + 2 * mine + axis;
}

// The program: a row per run and axis, P_i+1 - P_i - coefficient . z within value + rest;
// a row per mark and axis, M - P within its tie.
LinearProgram program_of(const Anchors& a, const std::vector<Form>& runs, const TubeDomains& tube,
                         const StructuredErrors& errors) {
  LinearProgram lp;
  const std::size_t z0 = 2 * a.sample.size() + 2 * tube.mines.size();
  lp.columns = z0 + kBiasTerms;
  for (const auto& box : a.box)
    for (const Interval& x : box) {
      lp.column_lower.push_back(x.lo());
      lp.column_upper.push_back(x.hi());
    }
  for (const Vec3I& mine : tube.mines)
    for (int axis = 0; axis < 2; ++axis) {
      lp.column_lower.push_back(mine[axis].lo());
      lp.column_upper.push_back(mine[axis].hi());
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
  for (const MarkTie& tie : a.marks)
    for (std::size_t axis = 0; axis < 2; ++axis)
      lp.add_row({mine_column(a, tie.mine, axis), position_column(a.index_of(tie.sample), axis)}, {1.0, -1.0},
                 tie.mine_minus_position[axis].lo(), tie.mine_minus_position[axis].hi());
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

// The certified bounds of one column, within its own.
Interval column_bounds(ClpProgram& clp, const LinearProgram& lp, std::size_t column, StructuredBounds& out) {
  std::array<double, 2> side = {lp.column_lower[column], lp.column_upper[column]};
  for (const double sign : {1.0, -1.0}) {
    std::vector<double> c(lp.columns, 0.0);
    c[column] = sign;
    const ClpProgram::Answer a = clp.minimize(c);
    ++out.linear_programs;
    if (a.status != ClpProgram::Status::optimal) continue;
    const double lowest = certified_lower_bound(lp, c, a.multipliers);
    if (sign > 0)
      side[0] = std::max(side[0], lowest);
    else
      side[1] = std::min(side[1], -lowest);
  }
  return Interval(side[0], side[1]);
}

// Every sample of run i, bounded from the anchor before and the one after.
void bound_samples_of_run(ClpProgram& clp, const LinearProgram& lp, const Anchors& a, std::size_t i, StepSums& sums,
                          const StructuredErrors& errors, const RelaxationOptions& options, StructuredBounds& out) {
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

}  // namespace

std::string structured_relaxation_refusal(const Mission& mission) {
  if (!mission.half_widths.empty())
    return "the mission's readings carry their own half-widths, whose split into bias and noise is not known";
  if (mission.model.step_model != StepModel::trapezoid)
    return "the bias-and-noise model needs the trapezoid step model";
  return {};
}

StructuredBounds relax_structured(const Mission& m, const StepRegimes& regimes, const StructuredErrors& errors,
                                  const TubeDomains& tube, const RelaxationOptions& options) {
  if (const std::string why = structured_relaxation_refusal(m); !why.empty()) throw std::invalid_argument(why);
  if (m.size() < 2 || tube.size() != m.size() || tube.mines.size() != static_cast<std::size_t>(m.mine_count))
    throw std::invalid_argument(
        "relax_structured: the tube must have one box per sample and mine, the mission two samples");
  StructuredBounds out;
  out.north = tube.px;
  out.east = tube.py;
  const FrameMargins frame = zone_frame(m);
  const SensorBoxes noise(m, errors.noise, frame), whole(m, m.model, frame, &regimes);
  const MissionNetwork net = build_network(m, m.model, gps_fixes(m), frame, regimes);
  const Anchors a = anchors_of(net, tube);
  StepSums sums(m, noise, whole);
  std::vector<Form> runs;
  for (std::size_t i = 0; i + 1 < a.sample.size(); ++i) {
    sums.clear();
    for (std::size_t k = a.sample[i]; k < a.sample[i + 1]; ++k) sums.add_step(k);
    runs.push_back(sums.form(errors.bias_bound));
  }
  const LinearProgram lp = program_of(a, runs, tube, errors);
  ClpProgram clp(lp);
  if (proved_empty(clp, lp)) {
    out.consistent = false;
    return out;
  }
  const std::size_t z0 = lp.columns - kBiasTerms;
  for (std::size_t t = 0; t < kBiasTerms; ++t) out.bias[t] = column_bounds(clp, lp, z0 + t, out);
  for (std::size_t i = 0; i < tube.mines.size(); ++i)
    out.mines.push_back(
        {column_bounds(clp, lp, mine_column(a, i, 0), out), column_bounds(clp, lp, mine_column(a, i, 1), out)});
  for (std::size_t i = 0; i + 1 < a.sample.size(); ++i) bound_samples_of_run(clp, lp, a, i, sums, errors, options, out);
  for (std::size_t k = 0; k < m.size(); ++k)
    if (out.north[k].is_empty() || out.east[k].is_empty()) out.consistent = false;
  return out;
}

}  // namespace gesmi
