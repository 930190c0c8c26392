#include "io/localization/localization_hdf5.h"

#include <cstdint>
#include <vector>

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
  file.close();
  out.commit();
}

}  // namespace gesmi::io
