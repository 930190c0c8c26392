#include "io/localization/localization_hdf5.h"

#include <cstdint>
#include <vector>

#include "io/files/provenance.h"
#include "io/output/atomic_output.h"
#include "io/hdf5/h5_file.h"

namespace gesmi::io {
namespace {

void write_paving(H5File& file, const std::string& group, const Paving& paving, const std::vector<std::int32_t>& component) {
  std::vector<double> boxes;
  boxes.reserve(paving.size() * 6);
  for (std::size_t i = 0; i < paving.size(); ++i)
    for (const Interval& x : paving.box(i)) {
      boxes.push_back(x.lo());
      boxes.push_back(x.hi());
    }
  file.write(group + "/boxes", boxes, paving.size(), 6, 2);
  file.write(group + "/component", component, component.size());
}

}  // namespace

constexpr DatasetUnits kLocalizationUnits[] = {
    {"/inner/boxes", "m, m, m, m, rad, rad", "inner boxes: x_lo, x_hi, y_lo, y_hi, theta_lo, theta_hi"},
    {"/inner/component", "1", "hypothesis (component) of each inner box, from 1"},
    {"/boundary/boxes", "m, m, m, m, rad, rad", "boundary boxes: x_lo, x_hi, y_lo, y_hi, theta_lo, theta_hi"},
    {"/boundary/component", "1", "hypothesis (component) of each boundary box, from 1 (0: none)"},
    {"/components/hull", "m, m, m, m, rad, rad", "hull of each hypothesis: x_lo, x_hi, y_lo, y_hi, theta_lo, theta_hi"},
    {"/components/inner_boxes", "1", "inner boxes of each hypothesis"},
    {"/components/boundary_boxes", "1", "boundary boxes of each hypothesis"},
    {"/components/holds_truth", "1", "1 when the hypothesis holds the scenario's true pose"},
    {"/components/outliers_determined", "1", "1 when the hypothesis holds exactly one outlier set, proved present (the list of its sets is complete)"},
    {"/components/outliers", "1", "1 where the datum (ranges first, then bearings) is an outlier in every set the hypothesis may hold (agreed outlier)"},
    {"/data/range_sensor", "1", "range sensor of each range measurement"},
    {"/data/range", "m", "measured range d (feasible: [d (1 - precision), d (1 + precision)]); +inf: no echo within the sensor's max range"},
    {"/data/range_precision", "1", "relative precision of each range measurement's sensor"},
    {"/data/range_max_range", "m", "max range of each range measurement's sensor (+inf: none; feasible set of no echo: [max_range (1 - precision), +inf])"},
    {"/data/range_blind_distance", "m", "blind distance of each range measurement's sensor (0: none)"},
    {"/data/bearing_sensor", "1", "bearing sensor of each bearing measurement"},
    {"/data/bearing", "rad", "measured bearing in the sensor frame"},
    {"/data/bearing_precision", "rad", "half-width of each bearing measurement's sensor"},
};

// The data and the sensors' precisions the pavings were computed from.
void write_data(H5File& file, const LocalizationProblem& p) {
  std::vector<std::int32_t> range_sensor, bearing_sensor;
  std::vector<double> range, range_precision, range_max_range, range_blind_distance, bearing, bearing_precision;
  for (const RangeMeasurement& m : p.ranges) {
    range_sensor.push_back(static_cast<std::int32_t>(m.sensor));
    range.push_back(m.range);
    range_precision.push_back(p.range_sensors[m.sensor].precision);
    range_max_range.push_back(p.range_sensors[m.sensor].max_range);
    range_blind_distance.push_back(p.range_sensors[m.sensor].blind_distance);
  }
  for (const BearingMeasurement& m : p.bearings) {
    bearing_sensor.push_back(static_cast<std::int32_t>(m.sensor));
    bearing.push_back(m.bearing);
    bearing_precision.push_back(p.bearing_sensors[m.sensor].precision);
  }
  file.write("/data/range_sensor", range_sensor, range_sensor.size());
  file.write("/data/range", range, range.size());
  file.write("/data/range_precision", range_precision, range_precision.size());
  file.write("/data/range_max_range", range_max_range, range_max_range.size());
  file.write("/data/range_blind_distance", range_blind_distance, range_blind_distance.size());
  file.write("/data/bearing_sensor", bearing_sensor, bearing_sensor.size());
  file.write("/data/bearing", bearing, bearing.size());
  file.write("/data/bearing_precision", bearing_precision, bearing_precision.size());
  file.set_attribute("/data", "epsilon", p.epsilon);
  file.set_attribute("/data", "theta_scale", p.theta_scale);
}

void write_localization_hdf5(const std::string& path, const LocalizationProblem& p, const LocalizationResult& r) {
  std::vector<std::int32_t> inner(r.paving.inner.size(), 0), boundary(r.paving.boundary.size(), 0);
  const std::size_t count = r.hypotheses.size(), n = p.datum_count();
  std::vector<double> hull;
  std::vector<std::int32_t> inner_boxes, boundary_boxes, truth, determined, outliers(count * n, 0);
  for (std::size_t k = 0; k < count; ++k) {
    const LocalizationHypothesis& h = r.hypotheses[k];
    for (std::size_t i : h.component.inner) inner[i] = static_cast<std::int32_t>(k + 1);
    for (std::size_t i : h.component.boundary) boundary[i] = static_cast<std::int32_t>(k + 1);
    for (const Interval& x : h.component.hull) {
      hull.push_back(x.lo());
      hull.push_back(x.hi());
    }
    inner_boxes.push_back(static_cast<std::int32_t>(h.component.inner.size()));
    boundary_boxes.push_back(static_cast<std::int32_t>(h.component.boundary.size()));
    truth.push_back(h.contains_truth);
    determined.push_back(h.outliers.determined);
    for (std::size_t i : h.outliers.outliers) outliers[k * n + i] = 1;
  }
  AtomicOutput out(path);
  H5File file = H5File::create(out.temp_path(), out.final_path());
  write_paving(file, "/inner", r.paving.inner, inner);
  write_paving(file, "/boundary", r.paving.boundary, boundary);
  file.write("/components/hull", hull, count, 6, 2);
  file.write("/components/inner_boxes", inner_boxes, count);
  file.write("/components/boundary_boxes", boundary_boxes, count);
  file.write("/components/holds_truth", truth, count);
  file.write("/components/outliers_determined", determined, count);
  file.write("/components/outliers", outliers, count, n, 2);
  file.set_attribute("/", "scenario", p.name);
  file.set_attribute("/", "q", static_cast<std::int64_t>(r.q));
  file.set_attribute("/", "found", static_cast<std::int64_t>(r.found));
  file.set_attribute("/", "seconds", r.seconds);
  write_data(file, p);
  write_provenance(file);
  write_units(file, kLocalizationUnits);
  file.close();
  out.commit();
}

}  // namespace gesmi::io
