// gesmi kalman: the Kalman smoother baseline on a mission (seed 001, section VI).

#include <chrono>
#include <cmath>
#include <cstdio>
#include <utility>

#include "io/output/output_set.h"
#include "io/output/atomic_output.h"
#include "io/files/kalman_result.h"
#include "io/files/mission_file.h"
#include "tools/gesmi/input_files.h"
#include "tools/gesmi/cli_args.h"
#include "tools/gesmi/progress.h"
#include "tools/gesmi/solve_arguments.h"
#include "tools/gesmi/skip_existing.h"
#include "io/text/csv_number.h"
#include "tools/gesmi/command_report.h"
#include "tools/gesmi/kalman_report.h"
#include "io/report/report_json.h"
#include "io/text/message_text.h"

namespace gesmi::cli {
namespace {

namespace po = boost::program_options;
using Clock = std::chrono::steady_clock;

void add_kalman_options(po::options_description& options) {
  options.add_options()
      ("mission", po::value<std::string>()->required(), "mission file (HDF5)")
      ("output,o", po::value<std::string>()->required(), "result file to write (HDF5)")
      ("config", po::value<std::string>(), "sensor bounds (YAML) overriding the mission's")
      ("noise-factor", po::value<std::string>()->default_value("1"), "variance = factor x bound^2 / 3")
      ("max-iterations", po::value<std::string>()->default_value("20"),
       "cap on the linearisations of the range measurements (1 to 100)")
      ("tolerance", po::value<std::string>()->default_value("0.001"),
       "converged when a linearisation moves no position or mine coordinate more (m)")
      ("stall-fraction", po::value<std::string>()->default_value("0.01"),
       "also stop when the steps stop shrinking though none exceeds this fraction of its coordinate's standard "
       "deviation: the smoother's rounding floor, about 1e-13 m (0: never)")
      ("biases", po::bool_switch(), "also estimate constant sensor biases (heading; DVL scale and offset per axis; depth scale and offset)")
      ("start", po::value<std::string>()->default_value(kalman_start_name(KalmanOptions{}.start)),
       "where the linearisations start: coarse (the same problem solved first on a chain of every 64th sample and "
       "the fixes' and marks' samples; without --biases) or dead-reckoning");
  add_json_option(options, true);
  add_skip_existing(options);
}

// The smoother's options as given; UsageError naming the option when one is not usable.
KalmanOptions kalman_options_given(const po::variables_map& v) {
  KalmanOptions o;
  o.noise_factor = parse_double("--noise-factor", v["noise-factor"].as<std::string>());
  o.max_iterations = parse_int("--max-iterations", v["max-iterations"].as<std::string>());
  o.tolerance = parse_double("--tolerance", v["tolerance"].as<std::string>());
  o.stall_fraction = parse_double("--stall-fraction", v["stall-fraction"].as<std::string>());
  o.biases = v["biases"].as<bool>();
  const auto chosen_start = kalman_start_from_name(v["start"].as<std::string>());
  if (!chosen_start)
    throw UsageError("--start: expected coarse or dead-reckoning, got " + io::quoted_input(v["start"].as<std::string>()));
  o.start = *chosen_start;
  if (const std::string why = o.validate(); !why.empty()) throw UsageError("--" + why);
  return o;
}

// On stderr: a note when the linearisations stopped at the rounding floor, a warning
// when they reached the cap unconverged.
void warn_unless_converged(const KalmanResult& k, double tolerance) {
  if (k.stalled)
    std::fprintf(stderr,
                 "gesmi kalman: note: stopped after %d linearisations at the smoother's rounding floor: the steps "
                 "stopped shrinking (the largest %s m, more than the tolerance %s m, but no coordinate moved more "
                 "than %s of its standard deviation); --stall-fraction 0 goes on to the cap\n",
                 k.iterations, io::format_number(k.last_step).c_str(), io::format_number(tolerance).c_str(),
                 io::format_number(k.last_step_sigmas).c_str());
  else if (!k.converged)
    std::fprintf(stderr,
                 "gesmi kalman: warning: not converged after %d linearisations (the last moved a coordinate by %s m, more "
                 "than the tolerance %s m): raise --max-iterations (up to 100), or "
                 "--tolerance if a coarser estimate will do\n",
                 k.iterations, io::format_number(k.last_step).c_str(), io::format_number(tolerance).c_str());
}

// The report's "kalman" fields.
void add_kalman_fields(CommandReport& report, const io::KalmanFile& file, std::size_t steps, int mines) {
  const Containment& c = file.containment;
  const KalmanOptions& o = file.options;
  report["kalman"] = {{"steps", steps},
                      {"mines", mines},
                      {"containment_3sigma_horizontal", io::number_json(c.horizontal)},
                      {"containment_3sigma_vertical", io::number_json(c.vertical)},
                      {"containment_mines", io::number_json(c.mines)},
                      {"containment_mines_plane", io::number_json(c.mines_plane)},
                      {"iterations", file.result.iterations},
                      {"start", kalman_start_name(o.start)},
                      {"coarse_iterations", file.result.coarse_iterations},
                      {"last_step_m", io::number_json(file.result.last_step)},
                      {"last_step_sigmas", io::number_json(file.result.last_step_sigmas)},
                      {"converged", file.result.converged},
                      {"stalled", file.result.stalled},
                      {"tolerance_m", o.tolerance},
                      {"stall_fraction", o.stall_fraction},
                      {"biases", o.biases}};
  add_kalman_checks(report["kalman"], file.result);
}

// The summary on stdout, without --json.
void print_summary(const io::KalmanFile& file, std::size_t steps, const std::string& output) {
  const KalmanResult& k = file.result;
  const Containment& c = file.containment;
  const std::string coarse =
      k.coarse_iterations > 0 ? " (started from a coarse chain solved in " + std::to_string(k.coarse_iterations) + ")" : "";
  std::printf("kalman smoother: %zu steps in %.1f ms, %s after %d linearisation%s%s (last step %.2g m), written to %s",
              steps, file.timings_ms.at("smooth"),
              k.converged ? "converged" : k.stalled ? "stopped at the rounding floor" : "NOT converged", k.iterations,
              k.iterations == 1 ? "" : "s", coarse.c_str(), k.last_step, output.c_str());
  if (!std::isnan(c.horizontal))
    std::printf("; truth within 3 sigma: horizontal %.1f %%, vertical %.1f %% of steps; inside the 99.73 %% region: "
                "%.0f %% of mines (3-D), %.0f %% (plane)",
                100.0 * c.horizontal, 100.0 * c.vertical, 100.0 * c.mines, 100.0 * c.mines_plane);
  std::printf("\n");
  print_kalman_checks(file.result);
}

int run_kalman(std::span<const std::string> args) {
  po::options_description options("kalman options");
  add_kalman_options(options);
  po::positional_options_description positional;
  positional.add("mission", 1);
  po::variables_map v;
  if (!parse_options(args, options, positional, v, "gesmi kalman MISSION.h5 -o KALMAN.h5 [--noise-factor F] [--max-iterations N] [--tolerance T] [--stall-fraction F] [--biases] [--start coarse|dead-reckoning] [--json] [--skip-existing]"))
    return kExitOk;
  const KalmanOptions o = kalman_options_given(v);
  const std::string output = v["output"].as<std::string>();
  const auto file_options = {"mission", "config"};  // the options naming files read
  io::OutputSet outputs(input_files(v, file_options));
  outputs.check(output);
  if (skipped_as_existing(v, "kalman", {output})) return kExitOk;

  io::KalmanFile file;
  Progress progress("gesmi kalman:");  // on a terminal, for long runs only (progress.h)
  progress.update(-1.0, "reading " + v["mission"].as<std::string>());
  auto start = Clock::now();
  // The truth (for the containment figures) is read after the smoothing, from the file
  // kept open, and its positions are not kept: the peak memory is the smoothing's.
  const io::MissionReader mission_file(v["mission"].as<std::string>());
  Mission mission = mission_file.read(io::TruthReading::skip);
  apply_config(v, mission, "kalman");
  file.timings_ms["load"] = elapsed_ms(start);
  start = Clock::now();
  progress.update(-1.0, "smoothing (linearisations until no coordinate moves more than " + io::format_number(o.tolerance) +
                            " m)");
  file.result = kalman_smooth(mission, mission.model, gps_fixes(mission), o);
  file.timings_ms["smooth"] = elapsed_ms(start);
  start = Clock::now();
  // The true positions only count, block by block: not kept (240 MB at 10^7 steps).
  ContainmentCount count(file.result);
  mission_file.read_truth(mission, [&](std::size_t first, std::span<const double> rows) {
    for (std::size_t i = 0; 3 * i < rows.size(); ++i) count.add(first + i, rows[3 * i], rows[3 * i + 1], rows[3 * i + 2]);
  });
  file.timings_ms["load"] += elapsed_ms(start);
  file.containment = count.finish(mission.truth_mines);
  const std::size_t steps = mission.size();
  file.time = std::move(mission.time);  // (no second copy: 80 MB at 10^7 steps)
  file.epoch = mission.epoch;
  file.origin = mission.origin;
  file.model = mission.model;
  file.options = o;
  start = Clock::now();
  progress.update(-1.0, "writing " + output);
  io::write_kalman_result(file, output);
  outputs.commit();
  file.timings_ms["write"] = elapsed_ms(start);
  progress.finish();
  warn_unless_converged(file.result, o.tolerance);
  CommandReport report("kalman", v);
  if (report.enabled()) {
    report.inputs(v, file_options);
    report.output(output);
    report.timings(file.timings_ms);
    add_kalman_fields(report, file, steps, mission.mine_count);
  } else {
    print_summary(file, steps, output);
  }
  return report.finish(kExitOk);
}

const bool kalman_registered =
    register_command({"kalman", "Kalman smoother baseline (EKF + RTS) on a mission", run_kalman});

}  // namespace
}  // namespace gesmi::cli
