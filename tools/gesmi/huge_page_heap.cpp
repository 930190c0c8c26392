// Why: a cold solve touches about 30 MB of fresh memory. In 4 KiB pages that took 5,100
// page faults, a third of the process's CPU on a virtual machine; with the heap in 2 MiB
// transparent huge pages, about 1,000 (most of them the program's own pages). Kernels
// set to "madvise" (Debian's default) give huge pages only to ranges marked
// MADV_HUGEPAGE, and glibc marks its heap only when told so by an environment variable
// (glibc.malloc.hugetlb), read before main. So the heap is grown once here, untouched,
// and marked; later allocations are carved from it.

#include "tools/gesmi/huge_page_heap.h"

#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>

#include "tools/gesmi/huge_page_blocks.h"

extern "C" char end;  // the end of the program's data (the linker's symbol, end(3))

namespace gesmi::cli {
namespace {

constexpr std::size_t kHeapReserve = std::size_t{256} << 20;
constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
constexpr int kDefaultTopPad = 128 << 10;  // mallopt(3)

}  // namespace

void use_huge_page_heap() {
  use_huge_page_blocks();  // the blocks too large for the heap
  // Blocks up to 32 MiB come from the heap (not a fresh mmap each, which faults again
  // after every free), and the heap is never given back before exit.
  mallopt(M_MMAP_THRESHOLD, static_cast<int>(kHugePageBlock));
  mallopt(M_ARENA_MAX, 1);  // worker threads allocate from the same heap
  mallopt(M_TRIM_THRESHOLD, static_cast<int>(2 * kHeapReserve));
  // The next growth of the heap reserves kHeapReserve beyond what it needs (address
  // space only: nothing is touched).
  mallopt(M_TOP_PAD, static_cast<int>(kHeapReserve));
  // The heap's current start: blocks freed before this call are reused first, so the
  // mark covers them too (never below the program's own data, `end`).
  const auto page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
  const auto first_break = reinterpret_cast<std::uintptr_t>(sbrk(0)) - mallinfo2().arena;
  const std::uintptr_t start = (std::max(first_break, reinterpret_cast<std::uintptr_t>(&end)) + page - 1) & ~(page - 1);
  void* probe = std::malloc(kHugePage);  // larger than the initial heap's free top
  const auto after = reinterpret_cast<std::uintptr_t>(sbrk(0));
  std::free(probe);
  mallopt(M_TOP_PAD, kDefaultTopPad);
  if (probe == nullptr || after <= start + kHugePage) return;  // too little heap to mark (ASan, or brk refused)
  madvise(reinterpret_cast<void*>(start), after - start, MADV_HUGEPAGE);
}

}  // namespace gesmi::cli
