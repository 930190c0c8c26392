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
#include <cstring>

#include "tools/gesmi/huge_page_blocks.h"

extern "C" char end;  // the end of the program's data (the linker's symbol, end(3))

namespace gesmi::cli {
namespace {

constexpr std::size_t kHeapReserve = std::size_t{256} << 20;
constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
constexpr int kDefaultMmapMax = 65536;  // mallopt(3)

}  // namespace

namespace {

// Whether glibc fills blocks on malloc and free (MALLOC_PERTURB_, glibc.malloc.perturb):
// the reserve's block would then be written whole, in small pages, at every start.
bool malloc_perturbs() {
  const char* perturb = std::getenv("MALLOC_PERTURB_");
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  return (perturb != nullptr && std::atoi(perturb) != 0) ||
         (tunables != nullptr && std::strstr(tunables, "glibc.malloc.perturb") != nullptr);
}

}  // namespace

void use_huge_page_heap() {
  use_huge_page_blocks();  // the blocks too large for the heap
#if defined(__SANITIZE_ADDRESS__)
  return;  // ASan's allocator has no program break to grow (and would poison the reserve's block)
#endif
  // Blocks up to 32 MiB come from the heap (not a fresh mmap each, which faults again
  // after every free), and the heap is never given back before exit.
  mallopt(M_MMAP_THRESHOLD, static_cast<int>(kHugePageBlock));
  mallopt(M_ARENA_MAX, 1);  // worker threads allocate from the same heap
  mallopt(M_TRIM_THRESHOLD, static_cast<int>(2 * kHeapReserve));
  // The heap's current start: blocks freed before this call are reused first, so the
  // mark covers them too (never below the program's own data, `end`).
  const auto page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
  const auto first_break = reinterpret_cast<std::uintptr_t>(sbrk(0)) - mallinfo2().arena;
  const std::uintptr_t start = (std::max(first_break, reinterpret_cast<std::uintptr_t>(&end)) + page - 1) & ~(page - 1);
  // The kernel gives a huge page only to a whole aligned 2 MiB of a marked range that
  // nothing has touched yet; so the heap grows without touching any:
  // - its new top starts one page below a 2 MiB boundary: the gap up to there is taken
  //   by sbrk here (glibc counts it as another's and frees its old top into its bins),
  //   so the top's header is written below the boundary and the heap's first, most used,
  //   huge page starts clean (it took about 400 small-page faults, measured);
  // - it grows by one block of the reserve's size (address space only), from the heap,
  //   not mapped apart, so the free top's header is left at the far end.
  const auto break_now = reinterpret_cast<std::uintptr_t>(sbrk(0));
  const std::uintptr_t top = ((break_now + page + kHugePage - 1) & ~(kHugePage - 1)) - page;
  if (malloc_perturbs()) return;  // (the heap stays in small pages)
  if (top > break_now) sbrk(static_cast<intptr_t>(top - break_now));  // (refused: as before)
  mallopt(M_MMAP_MAX, 0);
  void* probe = std::malloc(kHeapReserve);
  // (glibc's default: a value set through MALLOC_MMAP_MAX_ cannot be read back)
  mallopt(M_MMAP_MAX, kDefaultMmapMax);
  const auto after = reinterpret_cast<std::uintptr_t>(sbrk(0));
  std::free(probe);
  // Too little heap to mark: brk refused (glibc then maps the block apart, and the heap
  // goes on in small pages), or the reserve refused (strict overcommit, a data limit).
  if (probe == nullptr || after <= start + kHugePage) return;
  madvise(reinterpret_cast<void*>(start), after - start, MADV_HUGEPAGE);
}

}  // namespace gesmi::cli
