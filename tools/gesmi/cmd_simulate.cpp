// gesmi simulate: a reference-like mission with ground truth.

#include <algorithm>
#include <cstdio>

#include "io/output/output_set.h"
#include "io/output/atomic_output.h"
#include "io/geodesy.h"
#include "io/text/message_text.h"
#include "io/files/mission_file.h"
#include "io/files/sensor_model_yaml.h"
#include "solver/sim/simulator.h"
#include "tools/gesmi/input_files.h"
#include "tools/gesmi/cli_args.h"
#include "tools/gesmi/command_report.h"
#include "tools/gesmi/progress.h"
#include "io/report/report_json.h"
#include "tools/gesmi/skip_existing.h"

namespace gesmi::cli {
namespace {

namespace po = boost::program_options;

constexpr const char* kSimulateUsage =
    "gesmi simulate --preset redermor --seed S -o MISSION.h5 [--errors uniform|worst-case|at-samples|drifting|corners|"
    "bias-noise [--bias-share F] [--drift none|ramp|flip]] "
    "[--duration T] [--rate HZ] [--mines K] [--missed P] [--unassociated P] [--outliers N] [--surface S [--wave-height H] "
    "[--wave-period T] [--surface-dvl]] [--bursts N [--burst-jerk J]] [--config bounds.yaml] [--skip-existing]";

int run_simulate(std::span<const std::string> args) {
  po::options_description options("simulate options");
  options.add_options()
      ("preset", po::value<std::string>()->default_value("redermor"), "mission preset (redermor)")
      ("seed", po::value<std::string>()->required(), "random seed (integer >= 0)")
      ("output,o", po::value<std::string>()->required(), "mission file to write (HDF5)")
      ("errors", po::value<std::string>()->default_value("uniform"),
       "uniform, worst-case (a bias at 99 % of each bound), at-samples (at the ends of the bounds, against the motion: "
       "boxes hold at the sample instants only), or drifting (each sensor's error 0.99 x bound x sin(2 pi t / T + phase), T drawn "
       "in [600, 2400] s and the phase from the seed: inside the bounds, but not a constant bias), or corners (at 99.9 % "
       "of each bound, on the side of the truth's curvature: the truth on its box's corner where the step model is weakest), or "
       "bias-noise (heading, DVL, barometer, altitude and mark range: a bias at --bias-share of each bound, DVL and "
       "barometer split into a scale and an offset with their own signs, plus noise within the rest)")
      ("bias-share", po::value<std::string>(), "bias-noise: the bias's share of each bound, in [0, 1] (default 0.9)")
      ("drift", po::value<std::string>(),
       "bias-noise: none (constant biases, the default), ramp (each bias goes linearly to its opposite by the end) or flip "
       "(each bias turns to its opposite at the middle of the mission)")
      ("duration", po::value<std::string>()->default_value("5999.4"), "mission length (s)")
      ("rate", po::value<std::string>()->default_value("10"), "sampling rate (Hz)")
      ("mines", po::value<std::string>()->default_value("6"), "number of mines (0..64)")
      ("missed", po::value<std::string>()->default_value("0"), "probability that a detection is missed")
      ("unassociated", po::value<std::string>()->default_value("0"), "probability that a mark has no mine number")
      ("outliers", po::value<std::string>()->default_value("0"), "number of corrupted marks (every mark when there are fewer)")
      ("surface", po::value<std::string>()->default_value("0"),
       "seconds at the surface before the dive and after surfacing, with GPS fixes at 1 Hz (0: submerged throughout)")
      ("wave-height", po::value<std::string>()->default_value("0"), "height of the waves at the surface (m): heave and sway")
      ("wave-period", po::value<std::string>()->default_value("6"), "period of the waves (s)")
      ("surface-dvl", "the DVL keeps bottom lock at the surface (else it has no reading there)")
      ("bursts", po::value<std::string>()->default_value("0"), "number of 1 s vertical jerk bursts while submerged")
      ("burst-jerk", po::value<std::string>()->default_value("10"), "the bursts' peak jerk (m/s³)")
      ("config", po::value<std::string>(), "sensor bounds (YAML) the errors are drawn from, stored with the mission");
  add_json_option(options);
  add_skip_existing(options);
  po::variables_map v;
  if (!parse_options(args, options, {}, v, kSimulateUsage)) return kExitOk;
  if (v["preset"].as<std::string>() != "redermor")
    throw UsageError("--preset: unknown preset " + io::quoted_input(v["preset"].as<std::string>()) + " (available: redermor)");
  SimulationOptions o;
  const long long seed = parse_integer("--seed", v["seed"].as<std::string>());
  if (seed < 0) throw UsageError("--seed: must be >= 0");
  o.seed = static_cast<std::uint64_t>(seed);
  const std::string errors = v["errors"].as<std::string>();
  if (!parse_simulated_errors(errors, o.errors))
    throw UsageError("--errors: expected " + simulated_errors_names() + ", got " + io::quoted_input(errors));
  for (const char* name : {"bias-share", "drift"})
    if (v.count(name) && o.errors != SimulatedErrors::bias_noise)
      throw UsageError(std::string("--") + name + ": goes with --errors bias-noise");
  if (v.count("bias-share")) o.bias_share = parse_double("--bias-share", v["bias-share"].as<std::string>());
  if (v.count("drift") && !parse_bias_drift(v["drift"].as<std::string>(), o.drift))
    throw UsageError("--drift: expected none, ramp or flip, got " + io::quoted_input(v["drift"].as<std::string>()));
  o.duration = parse_double("--duration", v["duration"].as<std::string>());
  o.rate = parse_double("--rate", v["rate"].as<std::string>());
  o.mines = parse_int("--mines", v["mines"].as<std::string>());
  o.missed = parse_double("--missed", v["missed"].as<std::string>());
  o.unassociated = parse_double("--unassociated", v["unassociated"].as<std::string>());
  o.outliers = parse_int("--outliers", v["outliers"].as<std::string>());
  o.surface = parse_double("--surface", v["surface"].as<std::string>());
  o.wave_height = parse_double("--wave-height", v["wave-height"].as<std::string>());
  o.wave_period = parse_double("--wave-period", v["wave-period"].as<std::string>());
  o.surface_dvl = v.count("surface-dvl") > 0;
  o.bursts = parse_int("--bursts", v["bursts"].as<std::string>());
  o.burst_jerk = parse_double("--burst-jerk", v["burst-jerk"].as<std::string>());
  // Each reason starts with the option it is about ("missed must be ...").
  if (const std::string why = o.validate(); !why.empty()) throw UsageError("--" + why);
  const std::string output = v["output"].as<std::string>();
  io::OutputSet outputs(input_files(v, {"config"}));
  outputs.check(output);
  if (skipped_as_existing(v, "simulate", {output})) return kExitOk;

  Progress progress("gesmi simulate:");  // on a terminal, for long runs only (progress.h)
  progress.update(-1.0, "simulating " + std::to_string(static_cast<long long>(o.duration * o.rate)) + " samples");
  SensorModel model;
  if (v.count("config")) io::merge_sensor_model_yaml(v["config"].as<std::string>(), model);
  Mission mission = simulate_mission(o, model);
  mission.origin = {48.212920614, -4.458227931};  // the reference start fix
  io::set_geodetic_gps(mission);
  progress.update(-1.0, "writing " + output);
  io::write_mission(mission, output);
  outputs.commit();
  progress.finish();
  // The marks corrupted: --outliers of them, or every mark when there are fewer.
  const auto outliers = static_cast<std::size_t>(
      std::count(mission.truth_marks_outlier.begin(), mission.truth_marks_outlier.end(), 1));
  CommandReport report("simulate", v);
  if (report.enabled()) {
    report.inputs(v, {"config"});
    report.output(output);
    report["mission"] = io::mission_json(mission);
    report["simulation"] = {{"seed", o.seed}, {"errors", errors}, {"missed_marks", mission.truth_missed_marks.size() / 3},
                            {"outliers", outliers}};
    if (o.errors == SimulatedErrors::bias_noise) {
      report["simulation"]["bias_share"] = o.bias_share;
      report["simulation"]["drift"] = bias_drift_name(o.drift);
    }
  } else {
    std::printf("wrote %s: %zu samples over %.1f s, %d mines, %zu marks (%zu missed, %zu outliers)\n", output.c_str(),
                mission.size(), mission.time.back(), mission.mine_count, mission.mark_count(),
                mission.truth_missed_marks.size() / 3, outliers);
  }
  return report.finish(kExitOk);
}

const bool simulate_registered =
    register_command({"simulate", "simulate a reference-like mission with ground truth", run_simulate});

}  // namespace
}  // namespace gesmi::cli
