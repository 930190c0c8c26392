#include "io/exports/solve_outputs.h"

#include <filesystem>

#include "io/plot/plot_envelope.h"
#include "io/exports/result_exports.h"
#include "solver/network/mission_network.h"

namespace gesmi::io {

std::vector<std::string> solve_output_siblings(const std::string& result_path) {
  std::filesystem::path p(result_path);
  if (p.extension() == ".h5") p.replace_extension();
  const std::string base = p.string();
  return {base + ".mines.csv", base + ".geojson", base + ".envelope.png"};
}

std::vector<std::string> asked_solve_outputs(const std::string& result_path, const SolveSiblings& asked) {
  const std::vector<std::string> siblings = solve_output_siblings(result_path);
  std::vector<std::string> paths{result_path};
  if (asked.mines_csv) paths.push_back(siblings[0]);
  if (asked.geojson) paths.push_back(siblings[1]);
  if (asked.envelope_png) paths.push_back(siblings[2]);
  return paths;
}

std::vector<std::string> write_solve_outputs(const SolveResult& result, const Mission& mission,
                                             const std::string& result_path, const std::string& mission_name,
                                             const SolveSiblings& asked) {
  const MissionSolution& s = result.solution;
  const std::vector<std::string> siblings = solve_output_siblings(result_path);
  write_result(result, result_path);
  if (asked.mines_csv) write_mines_csv(result, siblings[0]);
  if (asked.geojson) write_geojson(result, &mission, siblings[1]);
  if (asked.envelope_png) {
    EnvelopePicture picture;
    picture.domains = &s.domains;
    picture.mission = &mission;
    for (const PositionFix& fix : gps_fixes(mission)) picture.fix_boxes.push_back(fix.box);
    picture.title = "gesmi envelope: " + mission_name + (s.report.consistent ? "" : " (INCONSISTENT)");
    write_envelope_png(picture, siblings[2]);
  }
  return asked_solve_outputs(result_path, asked);
}

}  // namespace gesmi::io
