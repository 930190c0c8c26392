#pragma once
// Work over the steps of a mission split into contiguous chunks, one per core: each
// chunk writes only its own steps, so the result does not depend on the split.

#include <sched.h>

#include <algorithm>
#include <cstddef>
#include <thread>
#include <vector>

namespace gesmi {

/// Fewer steps than this per chunk are not worth a thread.
inline constexpr std::size_t kMinStepsPerChunk = 20000;

/// The cores this process may run on: its CPU affinity (what Slurm's --cpus-per-task or
/// taskset grant), not every core of the machine; read once.
inline std::size_t usable_cores() {
  static const std::size_t cores = [] {
    cpu_set_t set;
    CPU_ZERO(&set);
    if (::sched_getaffinity(0, sizeof(set), &set) == 0 && CPU_COUNT(&set) > 0) return static_cast<std::size_t>(CPU_COUNT(&set));
    return static_cast<std::size_t>(std::max(1u, std::thread::hardware_concurrency()));
  }();
  return cores;
}

/// The number of chunks for `count` steps: one per usable core, but none smaller than
/// `min_per_chunk` steps (a thread costs more than a few thousand steps of work).
inline std::size_t step_chunk_count(std::size_t count, std::size_t min_per_chunk = kMinStepsPerChunk) {
  return std::clamp<std::size_t>(count / min_per_chunk, 1, usable_cores());
}

/// Runs body(chunk, first, last) over [0, count) in `chunks` contiguous chunks, the
/// first on the calling thread; returns when all are done.
template <class Body>
void for_step_chunks(std::size_t count, std::size_t chunks, Body body) {
  std::vector<std::jthread> workers;
  for (std::size_t c = 1; c < chunks; ++c) workers.emplace_back(body, c, count * c / chunks, count * (c + 1) / chunks);
  body(std::size_t{0}, std::size_t{0}, count / chunks);
}

}  // namespace gesmi
