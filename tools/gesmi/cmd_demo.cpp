// gesmi demo: the README's main job on the embedded demo.
// For now the academic example of seed 001 in its three published cases; the
// simulated reference mission replaces it once the mission solver lands.

#include <cstdio>

#include "solver/network/paper2d.h"
#include "tools/gesmi/command.h"

namespace gesmi::cli {
namespace {

void print_row(const char* name, const Interval& a, const Interval& b) {
  std::printf("  %-3s [%9.3f, %9.3f] x [%9.3f, %9.3f]\n", name, a.lo(), a.hi(), b.lo(), b.hi());
}

int run_demo(std::span<const std::string> args) {
  if (!args.empty()) throw UsageError("demo takes no arguments");
  const Paper2dDeltas cases[] = {{0, 0, kInf}, {1, 0, kInf}, {1, 1, kInf}};
  std::printf("seed 001 academic example: x(k+1) = x(k) + v(k), z(k) = ||x(k) - m||\n");
  for (const Paper2dDeltas& d : cases) {
    const Paper2dResult r = solve_paper2d(paper2d_prior(d));
    std::printf("\ndelta_v = %g, delta_z = %g, delta_x = %g: %d sweeps\n", d.v, d.z, d.x, r.report.sweeps);
    print_row("m", r.domains.m[0], r.domains.m[1]);
    for (std::size_t k = 1; k <= 4; ++k) {
      const std::string name = "x" + std::to_string(k);
      print_row(name.c_str(), r.domains.x[k][0], r.domains.x[k][1]);
    }
  }
  return kExitOk;
}

const bool registered = register_command({"demo", "run the embedded demo", run_demo});

}  // namespace
}  // namespace gesmi::cli
