// gesmi marks list|add|remove: the operator's edits of the mark table.

#include <cmath>
#include <cstdio>

#include "io/output/output_set.h"
#include "io/output/atomic_output.h"
#include "io/text/message_text.h"
#include "io/files/mark_rules.h"
#include "io/files/mission_file.h"
#include "tools/gesmi/input_files.h"
#include "tools/gesmi/cli_args.h"
#include "tools/gesmi/command_report.h"

namespace gesmi::cli {
namespace {

namespace po = boost::program_options;

nlohmann::json mark_json(const Mission& m, std::size_t j) {
  return {{"row", j},
          {"time", m.mark_time[j]},
          {"mine", m.mark_mine[j] < 0 ? nlohmann::json(nullptr) : nlohmann::json(m.mark_mine[j])},
          {"range", m.mark_range[j]},
          {"side", m.mark_side[j] > 0 ? "starboard" : "port"}};
}

int list_marks(std::span<const std::string> args) {
  po::options_description options("marks list options");
  options.add_options()("mission", po::value<std::string>()->required(), "mission file");
  add_json_option(options);
  po::positional_options_description positional;
  positional.add("mission", 1);
  po::variables_map v;
  if (!parse_options(args, options, positional, v, "gesmi marks list MISSION.h5")) return kExitOk;
  const Mission m = io::read_mission(v["mission"].as<std::string>());
  CommandReport report("marks list", v);
  if (report.enabled()) {
    report.inputs(v, {"mission"});
    nlohmann::json marks = nlohmann::json::array();
    for (std::size_t j = 0; j < m.mark_count(); ++j) marks.push_back(mark_json(m, j));
    report["marks"] = marks;
    report["mines"] = m.mine_count;
    return report.finish(kExitOk);
  }
  std::printf("%5s %10s %5s %9s %10s\n", "index", "time", "mine", "range", "side");
  for (std::size_t j = 0; j < m.mark_count(); ++j) {
    const std::string mine = m.mark_mine[j] < 0 ? "?" : std::to_string(m.mark_mine[j]);
    std::printf("%5zu %10.1f %5s %9.2f %10s\n", j, m.mark_time[j], mine.c_str(), m.mark_range[j],
                m.mark_side[j] > 0 ? "starboard" : "port");
  }
  std::printf("%zu marks, %d mines\n", m.mark_count(), m.mine_count);
  return kExitOk;
}

int add_mark(std::span<const std::string> args) {
  po::options_description options("marks add options");
  options.add_options()
      ("mission", po::value<std::string>()->required(), "mission file")
      ("time", po::value<std::string>()->required(), "detection time (s)")
      ("range", po::value<std::string>()->required(), "measured slant range (m)")
      ("side", po::value<std::string>()->default_value("starboard"), "starboard or port")
      ("mine", po::value<std::string>()->default_value("?"), "mine number, or ? when unknown")
      ("output,o", po::value<std::string>()->required(), "mission file to write");
  add_json_option(options);
  po::positional_options_description positional;
  positional.add("mission", 1);
  po::variables_map v;
  if (!parse_options(args, options, positional, v,
                     "gesmi marks add MISSION.h5 --time T --range R [--side starboard|port] [--mine ID|?] -o OUT.h5"))
    return kExitOk;
  const double time = parse_double("--time", v["time"].as<std::string>());
  const double range = parse_double("--range", v["range"].as<std::string>());
  const std::string side = v["side"].as<std::string>(), mine_text = v["mine"].as<std::string>();
  if (side != "starboard" && side != "port") throw UsageError("--side: expected starboard or port, got " + io::quoted_input(side));
  const std::string output = v["output"].as<std::string>();
  io::OutputSet outputs(input_files(v, {"mission"}));
  outputs.check(output);
  Mission m = io::read_mission(v["mission"].as<std::string>());
  const long long mine = mine_text == "?" ? -1 : parse_integer("--mine", mine_text);
  const int side_sign = side == "starboard" ? 1 : -1;
  // The rules of the mission file and of `gesmi import marks` (io/files/mark_rules.h).
  if (const auto problem = io::check_mark(io::mark_rules(m), time, mine, range, side_sign))
    throw UsageError("--" + std::string(io::mark_field_name(problem->field)) + ": " + problem->reason);
  m.mark_time.push_back(time);
  m.mark_mine.push_back(static_cast<std::int32_t>(mine));
  m.mark_range.push_back(range);
  m.mark_side.push_back(side_sign);
  // An operator's mark on a simulated mission: its truth is unknown (-1 = not a
  // simulated detection), and it is not an injected outlier.
  if (!m.truth_marks_outlier.empty()) m.truth_marks_outlier.push_back(0);
  if (!m.truth_marks_mine.empty()) m.truth_marks_mine.push_back(-1);
  io::write_mission(m, output);
  outputs.commit();
  CommandReport report("marks add", v);
  if (report.enabled()) {
    report.inputs(v, {"mission"});
    report.output(output);
    report["added"] = mark_json(m, m.mark_count() - 1);
    report["marks"] = m.mark_count();
    return report.finish(kExitOk);
  }
  std::printf("added mark %zu (t = %.1f s, mine %s, range %.2f m, %s); %s has %zu marks\n", m.mark_count() - 1, time,
              mine < 0 ? "?" : std::to_string(mine).c_str(), range, side.c_str(), output.c_str(), m.mark_count());
  return kExitOk;
}

int remove_mark(std::span<const std::string> args) {
  po::options_description options("marks remove options");
  options.add_options()("mission", po::value<std::string>()->required(), "mission file")(
      "index", po::value<std::string>()->required(), "row of the mark table")(
      "output,o", po::value<std::string>()->required(), "mission file to write");
  add_json_option(options);
  po::positional_options_description positional;
  positional.add("mission", 1).add("index", 1);
  po::variables_map v;
  if (!parse_options(args, options, positional, v, "gesmi marks remove MISSION.h5 INDEX -o OUT.h5")) return kExitOk;
  const std::string output = v["output"].as<std::string>();
  io::OutputSet outputs(input_files(v, {"mission"}));
  outputs.check(output);
  Mission m = io::read_mission(v["mission"].as<std::string>());
  const long long index = parse_integer("INDEX", v["index"].as<std::string>());
  if (index < 0 || static_cast<std::size_t>(index) >= m.mark_count())
    throw UsageError("INDEX: " + io::quoted_input(v["index"].as<std::string>()) + " is not a row of the mark table (0.." +
                     std::to_string(static_cast<long long>(m.mark_count()) - 1) + ")");
  const auto at = static_cast<std::ptrdiff_t>(index);
  const nlohmann::json removed = mark_json(m, static_cast<std::size_t>(index));
  m.mark_time.erase(m.mark_time.begin() + at);
  m.mark_mine.erase(m.mark_mine.begin() + at);
  m.mark_range.erase(m.mark_range.begin() + at);
  m.mark_side.erase(m.mark_side.begin() + at);
  if (!m.truth_marks_outlier.empty()) m.truth_marks_outlier.erase(m.truth_marks_outlier.begin() + at);
  if (!m.truth_marks_mine.empty()) m.truth_marks_mine.erase(m.truth_marks_mine.begin() + at);
  io::write_mission(m, output);
  outputs.commit();
  CommandReport report("marks remove", v);
  if (report.enabled()) {
    report.inputs(v, {"mission"});
    report.output(output);
    report["removed"] = removed;
    report["marks"] = m.mark_count();
    return report.finish(kExitOk);
  }
  std::printf("removed mark %lld; %s has %zu marks\n", index, output.c_str(), m.mark_count());
  return kExitOk;
}

int run_marks(std::span<const std::string> args) {
  if (args.empty()) throw UsageError("expected list, add or remove (gesmi marks list MISSION.h5)");
  const std::string action = args[0];
  if (action == "list") return list_marks(args.subspan(1));
  if (action == "add") return add_mark(args.subspan(1));
  if (action == "remove") return remove_mark(args.subspan(1));
  if (action == "--help" || action == "-h") {
    std::printf("usage: gesmi marks list|add|remove ... ('gesmi marks add --help')\n");
    return kExitOk;
  }
  throw UsageError("unknown action " + io::quoted_input(action) + ": expected list, add or remove");
}

const bool marks_registered = register_command({"marks", "list, add or remove operator marks", run_marks});

}  // namespace
}  // namespace gesmi::cli
