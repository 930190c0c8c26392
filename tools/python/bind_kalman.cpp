// The Kalman smoother baseline in Python (as `gesmi kalman`).

#include <pybind11/stl.h>

#include "io/format_error.h"
#include "io/geodesy.h"
#include "io/files/mission_file.h"
#include "solver/kalman/kalman_smoother.h"
#include "tools/python/bindings.h"

namespace gesmi::python {
namespace {

// A numpy view of `values` as `count` 3 x 3 matrices, kept alive by `owner`.
py::array_t<double> matrices_view(std::vector<double>& values, std::size_t count, py::handle owner) {
  return py::array_t<double>({static_cast<py::ssize_t>(count), py::ssize_t{3}, py::ssize_t{3}}, values.data(), owner);
}

py::dict consistency_dict(const KalmanConsistency& c) {
  py::dict d;
  d["chi2"] = c.chi2;
  d["dof"] = c.dof;
  d["chi2_per_dof"] = c.chi2_per_dof;
  d["band_low"] = c.band_low;
  d["band_high"] = c.band_high;
  d["band_probability"] = kChiSquareBandProbability;
  d["consistent"] = c.consistent;
  return d;
}

py::list tests_list(const std::vector<InputTest>& tests) {
  py::list out;
  for (const InputTest& t : tests) {
    py::dict d;
    d["kind"] = t.input.kind == ConstraintRef::Kind::mark ? "mark" : "gps_fix";
    d["row"] = t.input.row;
    d["time"] = t.time;
    d["dof"] = t.dof;
    d["chi2"] = t.chi2;
    d["max_normalised"] = t.max_normalised;
    d["flagged"] = t.flagged;
    out.append(d);
  }
  return out;
}

py::list bias_estimates_list(const KalmanResult& r) {
  py::list out;
  for (int b = 0; b < kBiasCount && r.biases; ++b) {
    py::dict d;
    d["name"] = std::string(bias_descriptions()[static_cast<std::size_t>(b)].name);
    d["unit"] = std::string(bias_descriptions()[static_cast<std::size_t>(b)].unit);
    d["estimate"] = r.bias_estimate[b];
    d["sigma"] = r.bias_sigma[b];
    d["prior_sigma"] = r.bias_prior_sigma[b];
    out.append(d);
  }
  return out;
}

void bind_kalman_result(py::module_& m) {
  py::class_<KalmanResult>(m, "KalmanResult", "Smoothed positions and mines with their covariances")
      .def_property_readonly("mean", [](py::object self) { return view(self.cast<KalmanResult&>().mean, self, 3); },
                             "(N, 3) north, east, down (m)")
      .def_property_readonly("covariance",
                             [](py::object self) {
                               KalmanResult& r = self.cast<KalmanResult&>();
                               return matrices_view(r.covariance, r.steps, self);
                             })
      .def_property_readonly("mine_mean", [](py::object self) { return view(self.cast<KalmanResult&>().mine_mean, self, 3); })
      .def_property_readonly("mine_covariance",
                             [](py::object self) {
                               KalmanResult& r = self.cast<KalmanResult&>();
                               return matrices_view(r.mine_covariance, r.mines, self);
                             })
      .def_readonly("iterations", &KalmanResult::iterations)
      .def_readonly("coarse_iterations", &KalmanResult::coarse_iterations)
      .def_readonly("last_step", &KalmanResult::last_step)
      .def_readonly("converged", &KalmanResult::converged)
      .def_readonly("stalled", &KalmanResult::stalled)
      .def_readonly("last_step_sigmas", &KalmanResult::last_step_sigmas)
      .def_property_readonly(
          "consistency", [](const KalmanResult& r) { return consistency_dict(r.consistency); },
          "chi-square of the fit per degree of freedom and its expected 95 % band")
      .def_property_readonly(
          "tests", [](const KalmanResult& r) { return tests_list(r.tests); },
          "residual test of each mark and GPS fix (leave-one-out chi-square; NaN: not testable)")
      .def_readonly("biases", &KalmanResult::biases, "whether the biases were estimated")
      .def_property_readonly(
          "bias_estimates", [](const KalmanResult& r) { return bias_estimates_list(r); },
          "the estimated sensor biases (empty without biases=True)");
}

// The smoother's options of a kalman() call, checked as `gesmi kalman` checks them.
KalmanOptions kalman_options(double noise_factor, int max_iterations, double tolerance, bool biases,
                             double stall_fraction, const std::string& start) {
  KalmanOptions o;
  o.noise_factor = noise_factor;
  o.max_iterations = max_iterations;
  o.tolerance = tolerance;
  o.biases = biases;
  o.stall_fraction = stall_fraction;
  const auto chosen = kalman_start_from_name(start);
  if (!chosen) throw io::FormatError("kalman: start: expected 'coarse' or 'dead-reckoning', got '" + start + "'");
  o.start = *chosen;
  if (const std::string why = o.validate(); !why.empty()) throw io::FormatError("kalman: " + why);
  return o;
}

py::dict containment_dict(const Containment& c) {
  py::dict d;
  d["horizontal"] = c.horizontal;
  d["vertical"] = c.vertical;
  d["mines"] = c.mines;
  d["mines_plane"] = c.mines_plane;
  return d;
}

}  // namespace

void bind_kalman(py::module_& m) {
  bind_kalman_result(m);
  m.def(
      "kalman",
      [](Mission& mission, double noise_factor, int max_iterations, double tolerance, bool biases,
         double stall_fraction, const std::string& start) {
        io::validate_mission(mission, "mission");
        io::fill_local_gps(mission, "mission");
        const KalmanOptions o = kalman_options(noise_factor, max_iterations, tolerance, biases, stall_fraction, start);
        py::gil_scoped_release release;
        return kalman_smooth(mission, mission.model, gps_fixes(mission), o);
      },
      py::arg("mission"), py::arg("noise_factor") = 1.0, py::arg("max_iterations") = KalmanOptions{}.max_iterations,
      py::arg("tolerance") = KalmanOptions{}.tolerance, py::arg("biases") = false,
      py::arg("stall_fraction") = KalmanOptions{}.stall_fraction,
      py::arg("start") = std::string(kalman_start_name(KalmanOptions{}.start)),
      "The Kalman smoother baseline (EKF + RTS, as `gesmi kalman`; biases=True as `--biases`)");
  m.def(
      "three_sigma_containment",
      [](const KalmanResult& r, const Mission& mission) { return containment_dict(three_sigma_containment(r, mission)); },
      py::arg("result"), py::arg("mission"),
      "Where the truth lies: fractions of steps within 3 sigma (horizontal: north and east; vertical), and of mines "
      "inside their 99.73 % region in 3-D and in the plane (NaN without truth)");
}

}  // namespace gesmi::python
