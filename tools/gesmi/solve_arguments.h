#pragma once
// The options of `gesmi solve`, and their translation into SolveOptions.

#include <boost/program_options.hpp>

#include "io/exports/solve_outputs.h"
#include "solver/mission/mission.h"
#include "solver/solve/solve_mission.h"

namespace gesmi::cli {

inline constexpr const char* kSolveUsage =
    "gesmi solve MISSION.h5 -o RESULT.h5 [--config bounds.yaml] [--max-sweeps N] [--tolerance T] [--stats] "
    "[--from RESULT.h5] [--max-outliers Q | --minimal-outliers Q] [--trust-gps] [--mines K] [--png] [--geojson] "
    "[--mines-csv] [--skip-existing]";

boost::program_options::options_description solve_options();
/// SolveOptions from the parsed options; UsageError naming the option when one is bad.
SolveOptions parse_solve_options(const boost::program_options::variables_map& v);
/// Which of the result's siblings --png, --geojson and --mines-csv ask for.
io::SolveSiblings parse_solve_siblings(const boost::program_options::variables_map& v);
/// Applies --mines K to the mission (K above every mine number of the mark table).
void apply_mine_count(const boost::program_options::variables_map& v, Mission& mission);

/// --config (solve, kalman): merges the file into the mission's model and prints its
/// notice, if any (the GPS bounds rule), as "gesmi COMMAND: note: ..." on stderr.
void apply_config(const boost::program_options::variables_map& v, Mission& mission, std::string_view command);

}  // namespace gesmi::cli
