// What fresh memory costs on this machine (docs/performance.md, "The heap back in small
// pages"): a new anonymous mapping of the given MiB, in small pages or marked for
// transparent huge pages, written once a page, then unmapped. CPU time per MiB, the
// kernel's work included (page faults, zeroing and, on a virtual machine, the host
// backing the memory). A pause before each mapping, outside the timing, lets memory
// freed by the last one go back to the host as it does between a user's commands
// (free page reporting); without it, each mapping gets the pages the last one freed.
//
//   gesmi-bench --benchmark_filter=BM_FreshMemory
//
// BM_SmallPageFault: the gesmi command's own probe (page_fault_cost.h), the figure its
// heap's page size is chosen by (command_heap.h), and which that is on this machine.
//
// Arguments of BM_FreshMemory: MiB, huge pages (0 or 1), pause before each mapping (ms). The pauses add
// about 72 s to a whole gesmi-bench run; a huge-page row is skipped when the kernel's
// transparent huge pages are off.

#include <benchmark/benchmark.h>

#include <sys/mman.h>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>
#include <thread>

#include "tools/gesmi/command_heap.h"
#include "tools/gesmi/page_fault_cost.h"

namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;
constexpr std::size_t kSmallPage = 4096;

// Whether madvise(MADV_HUGEPAGE) can give huge pages ("always" or "madvise" selected).
bool huge_pages_available() {
  std::ifstream setting("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string line;
  return std::getline(setting, line) && line.find("[never]") == std::string::npos;
}

void BM_FreshMemory(benchmark::State& state) {
  const auto bytes = static_cast<std::size_t>(state.range(0)) << 20;
  const bool huge = state.range(1) != 0;
  if (huge && !huge_pages_available()) {
    state.SkipWithError("transparent huge pages are off on this kernel (never)");
    return;
  }
  const auto pause = std::chrono::milliseconds(state.range(2));
  double touching_ms = 0.0;  // this thread's CPU time in the writes (the faults are charged to it)
  for (auto _ : state) {
    state.PauseTiming();
    std::this_thread::sleep_for(pause);
    // Over-mapped by a huge page, so that the range written starts on one.
    void* raw = mmap(nullptr, bytes + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (raw == MAP_FAILED) {
      state.SkipWithError("mmap refused the mapping");
      break;
    }
    auto* start = reinterpret_cast<unsigned char*>((reinterpret_cast<std::uintptr_t>(raw) + kHugePage - 1) &
                                                   ~(std::uintptr_t{kHugePage} - 1));
    madvise(start, bytes, huge ? MADV_HUGEPAGE : MADV_NOHUGEPAGE);
    state.ResumeTiming();
    const double before = gesmi::cli::thread_cpu_microseconds();
    for (std::size_t offset = 0; offset < bytes; offset += kSmallPage) start[offset] = 1;
    benchmark::DoNotOptimize(start[bytes / 2]);
    touching_ms += (gesmi::cli::thread_cpu_microseconds() - before) / 1e3;
    state.PauseTiming();
    munmap(raw, bytes + kHugePage);
    state.ResumeTiming();
  }
  state.counters["cpu_ms_per_MiB"] =
      touching_ms / (static_cast<double>(state.iterations()) * static_cast<double>(state.range(0)));
}

BENCHMARK(BM_FreshMemory)
    ->ArgNames({"MiB", "huge", "pause_ms"})
    ->Args({16, 0, 0})
    ->Args({16, 1, 0})
    ->Args({16, 0, 3000})
    ->Args({16, 1, 3000})
    ->Args({256, 0, 3000})
    ->Args({256, 1, 3000})
    ->Iterations(6)
    ->Unit(benchmark::kMillisecond);

void BM_SmallPageFault(benchmark::State& state) {
  double microseconds = 0.0;
  for (auto _ : state) microseconds += gesmi::cli::small_page_fault_microseconds();
  const double per_fault = microseconds / static_cast<double>(state.iterations());
  state.counters["us_per_fault"] = per_fault;
  state.SetLabel(per_fault >= gesmi::cli::kCostlySmallFault ? "the command's heap: huge pages"
                                                            : "the command's heap: small pages");
}
BENCHMARK(BM_SmallPageFault)->Iterations(20)->Unit(benchmark::kMicrosecond);

}  // namespace
