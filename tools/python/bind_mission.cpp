// Missions in Python: read, write, simulate, the sensor model as a dict-like
// object, the arrays as numpy views, and the mark table's edits.

#include <optional>
#include <string>

#include <pybind11/stl.h>

#include "io/format_error.h"
#include "io/geodesy.h"
#include "io/files/mission_file.h"
#include "solver/sim/simulator.h"
#include "tools/python/bindings.h"

namespace gesmi::python {
namespace {

// The sensor model of a mission as a mapping key -> value (docs/formats.md keys).
struct ModelView {
  py::object owner;  // keeps the mission alive
  SensorModel* model;

  py::object get(const std::string& key) const {
    for (const SensorModelChoice& c : sensor_model_choices())
      if (c.key == key) return py::str(std::string(c.get(*model)));
    for (const SensorModelField& f : sensor_model_fields())
      if (f.key == key) return py::float_(model->*f.member);
    throw py::key_error(key);
  }
  // Through io::change_model, as a --config: the same refusals, margins and GPS boxes.
  void set(const std::string& key, const py::object& value) {
    SensorModel updated = *model;
    bool known = false;
    for (const SensorModelChoice& c : sensor_model_choices())
      if (c.key == key) {
        if (!c.set(updated, py::cast<std::string>(value)))
          throw io::FormatError("sensor model: " + key + ": expected " + choice_names(c));
        known = true;
      }
    for (const SensorModelField& f : sensor_model_fields())
      if (f.key == key) {
        updated.*f.member = py::cast<double>(value);
        known = true;
      }
    if (!known) throw py::key_error(key);
    if (const std::string why = updated.validate(); !why.empty()) throw io::FormatError("sensor model: " + why);
    io::change_model(owner.cast<Mission&>(), updated, "sensor model");
  }
  std::vector<std::string> keys() const {
    std::vector<std::string> k;
    for (const SensorModelField& f : sensor_model_fields()) k.emplace_back(f.key);
    for (const SensorModelChoice& c : sensor_model_choices()) k.emplace_back(c.key);
    return k;
  }
};

// A numpy view of a mission array, and a setter that copies any 1-D array in.
#define GESMI_ARRAY(name) \
  def_property(#name, [](py::object self) { return view(self.cast<Mission&>().name, self); }, \
               [](Mission& mission, const py::array_t<double, py::array::c_style | py::array::forcecast>& a) { mission.name = to_vector(a); })

// The sensor model of a mission as a mapping (ModelView).
void bind_sensor_model(py::module_& m) {
  py::class_<ModelView>(m, "SensorModel", "The sensor error bounds of a mission, as a mapping (docs/formats.md)")
      .def("__getitem__", &ModelView::get)
      .def("__setitem__", &ModelView::set)
      .def("__contains__", [](const ModelView& v, const std::string& k) { const auto keys = v.keys(); return std::find(keys.begin(), keys.end(), k) != keys.end(); })
      .def("__len__", [](const ModelView& v) { return v.keys().size(); })
      .def("__iter__", [](const ModelView& v) { return py::iter(py::cast(v.keys())); })
      .def("keys", &ModelView::keys)
      .def("items", [](const ModelView& v) {
        py::list items;
        for (const std::string& k : v.keys()) items.append(py::make_tuple(k, v.get(k)));
        return items;
      })
      .def("__repr__", [](const ModelView& v) {
        py::dict d;
        for (const std::string& k : v.keys()) d[py::str(k)] = v.get(k);
        return "SensorModel(" + py::repr(d).cast<std::string>() + ")";
      });
}

// Mission.add_mark(): the mark appended to every mark array, then the mission checked;
// a refused mark is taken back off before the error propagates.
void add_checked_mark(Mission& s, double time, double range, const std::string& side, int mine) {
  s.mark_time.push_back(time);
  s.mark_range.push_back(range);
  s.mark_side.push_back(side == "port" ? -1 : side == "starboard" ? 1 : 0);
  s.mark_mine.push_back(mine);
  if (!s.truth_marks_outlier.empty()) s.truth_marks_outlier.push_back(0);
  if (!s.truth_marks_mine.empty()) s.truth_marks_mine.push_back(-1);
  try {
    io::validate_mission(s, "mission");
  } catch (...) {
    for (auto* v : {&s.mark_time, &s.mark_range}) v->pop_back();
    for (auto* v : {&s.mark_side, &s.mark_mine}) v->pop_back();
    if (!s.truth_marks_outlier.empty()) s.truth_marks_outlier.pop_back();
    if (!s.truth_marks_mine.empty()) s.truth_marks_mine.pop_back();
    throw;
  }
}

void bind_mission_class(py::module_& m) {
  py::class_<Mission>(m, "Mission", "A mission's measurements as flat arrays on one time grid (docs/formats.md)")
      .def(py::init<>())
      .GESMI_ARRAY(time).GESMI_ARRAY(roll).GESMI_ARRAY(pitch).GESMI_ARRAY(heading)
      .GESMI_ARRAY(vx).GESMI_ARRAY(vy).GESMI_ARRAY(vz).GESMI_ARRAY(altitude).GESMI_ARRAY(depth)
      .GESMI_ARRAY(gps_time).GESMI_ARRAY(gps_longitude).GESMI_ARRAY(gps_latitude)
      .GESMI_ARRAY(truth_x).GESMI_ARRAY(truth_y).GESMI_ARRAY(truth_z).GESMI_ARRAY(truth_mines)
      .def_property_readonly("mark_time", [](const Mission& s) { return s.mark_time; })
      .def_property_readonly("mark_range", [](const Mission& s) { return s.mark_range; })
      .def_property_readonly("mark_mine", [](const Mission& s) { return s.mark_mine; })
      .def_property_readonly("mark_side", [](const Mission& s) { return s.mark_side; })
      .def_property_readonly("truth_marks_outlier", [](const Mission& s) { return s.truth_marks_outlier; },
                             "1 for a mark whose range the simulator corrupted (empty without truth)")
      .def_readwrite("mine_count", &Mission::mine_count)
      .def_property(
          "origin", [](const Mission& s) { return py::make_tuple(s.origin.latitude, s.origin.longitude); },
          [](Mission& s, std::pair<double, double> o) { s.origin = {o.first, o.second}; })
      .def_property_readonly("model", [](py::object self) { return ModelView{self, &self.cast<Mission&>().model}; })
      .def("__len__", &Mission::size)
      .def("mark_count", &Mission::mark_count)
      .def("validate", [](Mission& s) {
        io::validate_mission(s, "mission");
        io::fill_local_gps(s, "mission");
      }, "Checks the mission as the file reader does (FormatError naming the field) and converts the GPS fixes")
      .def("add_mark", &add_checked_mark, py::arg("time"), py::arg("range"), py::arg("side") = "starboard",
           py::arg("mine") = -1,
           "Adds an operator's mark (mine -1: unknown), checked as the mission file reader checks marks");
}

// simulate(): a reference-like mission with ground truth, as `gesmi simulate` makes it.
Mission simulated_mission(std::uint64_t seed, const std::string& errors, double duration, double rate, int mines,
                          double missed, double unassociated, int outliers, double surface, double wave_height,
                          double wave_period, bool surface_dvl, int bursts, double burst_jerk,
                          std::optional<double> bias_share, std::optional<std::string> drift) {
  SimulationOptions o;
  o.seed = seed;
  if (!parse_simulated_errors(errors, o.errors))
    throw io::FormatError("simulate: errors: expected " + simulated_errors_names());
  if ((bias_share || drift) && o.errors != SimulatedErrors::bias_noise)
    throw io::FormatError("simulate: bias_share and drift go with errors=\"bias-noise\"");
  if (bias_share) o.bias_share = *bias_share;
  if (drift && !parse_bias_drift(*drift, o.drift)) throw io::FormatError("simulate: drift: expected none, ramp or flip");
  o.duration = duration;
  o.rate = rate;
  o.mines = mines;
  o.missed = missed;
  o.unassociated = unassociated;
  o.outliers = outliers;
  o.surface = surface;
  o.wave_height = wave_height;
  o.wave_period = wave_period;
  o.surface_dvl = surface_dvl;
  o.bursts = bursts;
  o.burst_jerk = burst_jerk;
  if (const std::string why = o.validate(); !why.empty()) throw io::FormatError("simulate: " + why);
  Mission s = simulate_mission(o);
  s.origin = {48.212920614, -4.458227931};  // the reference start fix, as `gesmi simulate`
  io::set_geodetic_gps(s);
  io::fill_local_gps(s, "simulated mission");
  return s;
}

}  // namespace

void bind_mission(py::module_& m) {
  bind_sensor_model(m);
  bind_mission_class(m);
  m.def("read_mission", [](const std::string& path) { return io::read_mission(path); }, py::arg("path"),
        "Reads and validates a mission file (HDF5), its truth included");
  m.def("write_mission", [](const Mission& s, const std::string& path) { io::write_mission(s, path); }, py::arg("mission"),
        py::arg("path"), "Writes a mission file atomically");
  m.def("simulate", &simulated_mission, py::arg("seed") = 1, py::arg("errors") = "uniform", py::arg("duration") = 5999.4,
        py::arg("rate") = 10.0, py::arg("mines") = 6, py::arg("missed") = 0.0, py::arg("unassociated") = 0.0,
        py::arg("outliers") = 0, py::arg("surface") = 0.0, py::arg("wave_height") = 0.0, py::arg("wave_period") = 6.0,
        py::arg("surface_dvl") = false, py::arg("bursts") = 0, py::arg("burst_jerk") = 10.0,
        py::arg("bias_share") = std::nullopt, py::arg("drift") = std::nullopt,
        "Simulates a reference-like mission with ground truth (as `gesmi simulate`)");
}

}  // namespace gesmi::python
