// The Kalman smoother baseline in Python (as `gesmi kalman`).

#include <pybind11/stl.h>

#include "io/format_error.h"
#include "io/geodesy.h"
#include "io/files/mission_file.h"
#include "solver/kalman/kalman_smoother.h"
#include "tools/python/bindings.h"

namespace gesmi::python {

void bind_kalman(py::module_& m) {
  py::class_<KalmanResult>(m, "KalmanResult", "Smoothed positions and mines with their covariances")
      .def_property_readonly("mean", [](py::object self) { return view(self.cast<KalmanResult&>().mean, self, 3); },
                             "(N, 3) north, east, down (m)")
      .def_property_readonly("covariance",
                             [](py::object self) {
                               KalmanResult& r = self.cast<KalmanResult&>();
                               return py::array_t<double>({static_cast<py::ssize_t>(r.steps), py::ssize_t{3}, py::ssize_t{3}},
                                                          r.covariance.data(), self);
                             })
      .def_property_readonly("mine_mean", [](py::object self) { return view(self.cast<KalmanResult&>().mine_mean, self, 3); })
      .def_property_readonly("mine_covariance",
                             [](py::object self) {
                               KalmanResult& r = self.cast<KalmanResult&>();
                               return py::array_t<double>({static_cast<py::ssize_t>(r.mines), py::ssize_t{3}, py::ssize_t{3}},
                                                          r.mine_covariance.data(), self);
                             })
      .def_readonly("iterations", &KalmanResult::iterations)
      .def_readonly("last_step", &KalmanResult::last_step)
      .def_readonly("converged", &KalmanResult::converged);
  m.def(
      "kalman",
      [](Mission& mission, double noise_factor, int max_iterations, double tolerance) {
        io::validate_mission(mission, "mission");
        io::fill_local_gps(mission, "mission");
        KalmanOptions o;
        o.noise_factor = noise_factor;
        o.max_iterations = max_iterations;
        o.tolerance = tolerance;
        if (const std::string why = o.validate(); !why.empty()) throw io::FormatError("kalman: " + why);
        py::gil_scoped_release release;
        return kalman_smooth(mission, mission.model, gps_fixes(mission), o);
      },
      py::arg("mission"), py::arg("noise_factor") = 1.0, py::arg("max_iterations") = KalmanOptions{}.max_iterations,
      py::arg("tolerance") = KalmanOptions{}.tolerance,
      "The Kalman smoother baseline (EKF + RTS, as `gesmi kalman`)");
  m.def(
      "three_sigma_containment",
      [](const KalmanResult& r, const Mission& mission) {
        const Containment c = three_sigma_containment(r, mission);
        return py::make_tuple(c.trajectory, c.mines);
      },
      py::arg("result"), py::arg("mission"), "Fractions of steps and mines whose truth lies within 3 sigma (NaN without truth)");
}

}  // namespace gesmi::python
