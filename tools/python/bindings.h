#pragma once
// The gesmi Python module (pybind11): one bind_* function per part, and the helpers
// that show C++ arrays to numpy without copying them.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <type_traits>
#include <vector>

#include "solver/interval/interval.h"
#include "solver/setinv/paving.h"

namespace gesmi::python {

namespace py = pybind11;

void bind_mission(py::module_& m);
void bind_solve(py::module_& m);
void bind_kalman(py::module_& m);
void bind_localize(py::module_& m);
void bind_estimate(py::module_& m);

/// A numpy view of a vector (rows x columns, row-major), kept alive by `owner`.
template <class T>
py::array_t<T> view(std::vector<T>& v, py::handle owner, std::size_t columns = 1) {
  const auto rows = static_cast<py::ssize_t>(columns == 0 ? 0 : v.size() / columns);
  if (columns == 1) return py::array_t<T>({rows}, {static_cast<py::ssize_t>(sizeof(T))}, v.data(), owner);
  return py::array_t<T>({rows, static_cast<py::ssize_t>(columns)},
                        {static_cast<py::ssize_t>(columns * sizeof(T)), static_cast<py::ssize_t>(sizeof(T))}, v.data(),
                        owner);
}

/// Intervals as an (N, 2) numpy view of [lower, upper] (an empty interval reads
/// [inf, -inf]).
inline py::array_t<double> interval_view(std::vector<Interval>& v, py::handle owner) {
  static_assert(sizeof(Interval) == 2 * sizeof(double) && std::is_standard_layout_v<Interval>);
  return py::array_t<double>({static_cast<py::ssize_t>(v.size()), py::ssize_t{2}},
                             {static_cast<py::ssize_t>(sizeof(Interval)), static_cast<py::ssize_t>(sizeof(double))},
                             reinterpret_cast<double*>(v.data()), owner);
}

/// The boxes of a paving as a (B, dim, 2) numpy array of [lower, upper] (a copy).
inline py::array_t<double> paving_boxes(const Paving& paving) {
  py::array_t<double> out({static_cast<py::ssize_t>(paving.size()), static_cast<py::ssize_t>(paving.dim()), py::ssize_t{2}});
  auto a = out.mutable_unchecked<3>();
  for (std::size_t i = 0; i < paving.size(); ++i)
    for (std::size_t c = 0; c < paving.dim(); ++c) {
      a(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(c), 0) = paving.box(i)[c].lo();
      a(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(c), 1) = paving.box(i)[c].hi();
    }
  return out;
}

/// A copy of a 1-D numpy array (any numeric type) as a vector.
template <class T>
std::vector<T> to_vector(const py::array_t<T, py::array::c_style | py::array::forcecast>& a) {
  if (a.ndim() != 1) throw py::value_error("expected a 1-D array");
  return std::vector<T>(a.data(), a.data() + a.size());
}

}  // namespace gesmi::python
