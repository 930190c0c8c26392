#pragma once
// Work over the steps of a mission split into contiguous chunks, one per core: each
// chunk writes only its own steps, so the result does not depend on the split.

#include <algorithm>
#include <cstddef>
#include <thread>
#include <vector>

namespace gesmi {

/// Fewer steps than this per chunk are not worth a thread.
inline constexpr std::size_t kMinStepsPerChunk = 20000;

/// The number of chunks for `count` steps: one per core, but none smaller than
/// `min_per_chunk` steps (a thread costs more than a few thousand steps of work).
inline std::size_t step_chunk_count(std::size_t count, std::size_t min_per_chunk = kMinStepsPerChunk) {
  return std::clamp<std::size_t>(count / min_per_chunk, 1, std::max(1u, std::thread::hardware_concurrency()));
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
