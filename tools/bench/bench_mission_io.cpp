// Mission data: loading a 60,000-sample mission (target <= 20 ms), the
// peak memory of loading a 10^7-sample mission (target: at most two copies of the
// data), and simulating 6e4 / 1e6 / 1e7 samples (target: seconds). Also reading a
// 60,000-step result as a warm rerun reads it.
//
// Peak memory is read from /proc/self/status: VmHWM is reset through
// /proc/self/clear_refs ("5") just before the read, so the counter
// peak_over_data = (VmHWM - VmRSS before) / bytes of the mission's arrays counts the
// copies of the data that were alive at once (1.0 = the arrays themselves).
// The 10^7 file (about 1 GB) is written to $TMPDIR (or /tmp) and removed at exit.

#include <benchmark/benchmark.h>

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/geodesy.h"
#include "io/files/mission_file.h"
#include "io/files/result_file.h"
#include "solver/sim/simulator.h"
#include "solver/solve/solve_mission.h"

namespace {

namespace fs = std::filesystem;
using namespace gesmi;

// Reads "VmRSS" or "VmHWM" from /proc/self/status, in bytes.
double status_bytes(const std::string& key) {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(key + ":", 0) == 0) return std::stod(line.substr(key.size() + 1)) * 1024.0;
  return 0.0;
}

void reset_peak() { std::ofstream("/proc/self/clear_refs") << "5"; }

std::size_t mission_bytes(const Mission& m) {
  std::size_t doubles = 0;
  for (const std::vector<double>* v : {&m.time, &m.roll, &m.pitch, &m.heading, &m.vx, &m.vy, &m.vz, &m.altitude,
                                       &m.depth, &m.truth_x, &m.truth_y, &m.truth_z})
    doubles += v->size();
  return doubles * sizeof(double);
}

// A simulated mission of `duration` s at 10 Hz (seed 1, with the reference origin).
Mission simulated(double duration) {
  SimulationOptions o;
  o.seed = 1;
  o.duration = duration;
  Mission m = simulate_mission(o);
  m.origin = {48.212920614, -4.458227931};
  io::set_geodetic_gps(m);
  return m;
}

// A file under $TMPDIR (or /tmp), `stem`-PID.h5, written once by `write(path)` and
// removed when the object goes.
class TemporaryFile {
 public:
  template <class Write>
  TemporaryFile(const std::string& stem, Write&& write) {
    const char* tmp = std::getenv("TMPDIR");
    path_ = (fs::path(tmp ? tmp : "/tmp") / (stem + "-" + std::to_string(::getpid()) + ".h5")).string();
    write(path_);
  }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  ~TemporaryFile() { fs::remove(path_); }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// The simulated mission of `duration` s in a temporary file.
TemporaryFile mission_file(double duration) {
  return TemporaryFile("gesmi-bench-" + std::to_string(static_cast<long>(duration)),
                       [&](const std::string& path) { io::write_mission(simulated(duration), path); });
}

void BM_ReadMission60k(benchmark::State& state) {
  static const TemporaryFile file = mission_file(5999.4);
  std::size_t samples = 0;
  for (auto _ : state) {
    const Mission m = io::read_mission(file.path());
    samples = m.size();
    benchmark::DoNotOptimize(m.time.data());
  }
  state.counters["samples"] = static_cast<double>(samples);
  state.counters["file_MB"] = static_cast<double>(fs::file_size(file.path())) / 1e6;
}

// The result of a cold solve of the reference-like mission in a temporary file.
TemporaryFile result_file() {
  return TemporaryFile("gesmi-bench-result", [](const std::string& path) {
    const Mission m = simulated(5999.4);
    io::SolveResult r;
    r.solution = solve_mission(m);
    io::record_inputs(r, m);
    io::write_result(r, path);
  });
}

// A warm rerun's reading of the earlier result (every part, its digests checked). glibc
// gives each iteration's arrays back to the kernel, so on a host where a small page's
// fault is costly (BM_SmallPageFault) the faults dominate: 23 ms here against 4-6 ms
// with the heap kept as the gesmi command keeps it (GLIBC_TUNABLES=
// glibc.malloc.mmap_threshold=1073741824:glibc.malloc.trim_threshold=4294967295).
void BM_ReadResult60k(benchmark::State& state) {
  static const TemporaryFile file = result_file();
  std::size_t steps = 0;
  for (auto _ : state) {
    const io::SolveResult r = io::read_result(file.path());
    steps = r.solution.domains.size();
    benchmark::DoNotOptimize(r.solution.domains.px.data());
  }
  state.counters["steps"] = static_cast<double>(steps);
}

void BM_ReadMission10M(benchmark::State& state) {
  static const TemporaryFile file = mission_file(999999.9);  // 10^7 samples
  for (auto _ : state) {
    state.PauseTiming();
    reset_peak();
    const double before = status_bytes("VmRSS");
    state.ResumeTiming();
    const Mission m = io::read_mission(file.path());
    state.PauseTiming();
    const double peak = status_bytes("VmHWM");
    const double data = static_cast<double>(mission_bytes(m));
    state.counters["samples"] = static_cast<double>(m.size());
    state.counters["data_MB"] = data / 1e6;
    state.counters["peak_increase_MB"] = (peak - before) / 1e6;
    state.counters["peak_over_data"] = (peak - before) / data;
    state.ResumeTiming();
  }
}

// In-process simulate + write, as `gesmi simulate --duration T` does.
void BM_SimulateAndWrite(benchmark::State& state) {
  const double duration = static_cast<double>(state.range(0)) / 10.0 - 0.1;
  const std::string path = fs::temp_directory_path() / ("gesmi-bench-sim-" + std::to_string(::getpid()) + ".h5");
  double simulate_ms = 0.0;
  for (auto _ : state) {
    SimulationOptions o;
    o.seed = 1;
    o.duration = duration;
    const auto start = std::chrono::steady_clock::now();
    Mission m = simulate_mission(o);
    simulate_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    m.origin = {48.212920614, -4.458227931};
    io::set_geodetic_gps(m);
    io::write_mission(m, path);
  }
  fs::remove(path);
  state.counters["samples"] = static_cast<double>(state.range(0));
  state.counters["simulate_ms"] = simulate_ms;
}

BENCHMARK(BM_ReadMission60k)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadResult60k)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadMission10M)->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK(BM_SimulateAndWrite)->Arg(60000)->Arg(1000000)->Arg(10000000)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
