// Why: kernels set to "madvise" (Debian's default) give huge pages only to ranges marked
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

extern "C" char end;  // the end of the program's data (the linker's symbol, end(3))

namespace gesmi::cli {
namespace {

constexpr std::size_t kHeapReserve = std::size_t{256} << 20;
constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
constexpr int kDefaultMmapMax = 65536;  // mallopt(3)

// Whether glibc fills blocks on malloc and free (MALLOC_PERTURB_, glibc.malloc.perturb):
// the reserve's block would then be written whole, in small pages, at every start.
[[maybe_unused]] bool malloc_perturbs() {  // (unused under ASan)
  const char* perturb = std::getenv("MALLOC_PERTURB_");
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  return (perturb != nullptr && std::atoi(perturb) != 0) ||
         (tunables != nullptr && std::strstr(tunables, "glibc.malloc.perturb") != nullptr);
}

}  // namespace

bool mark_heap_for_huge_pages() {
#if defined(__SANITIZE_ADDRESS__)
  return false;  // ASan's allocator has no program break to grow (and would poison the reserve's block)
#else
  if (malloc_perturbs()) return false;
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
  if (top > break_now) sbrk(static_cast<intptr_t>(top - break_now));  // (refused: as before)
  mallopt(M_MMAP_MAX, 0);
  void* probe = std::malloc(kHeapReserve);
  // (glibc's default: a value set through MALLOC_MMAP_MAX_ cannot be read back)
  mallopt(M_MMAP_MAX, kDefaultMmapMax);
  const auto after = reinterpret_cast<std::uintptr_t>(sbrk(0));
  const auto reserve = reinterpret_cast<std::uintptr_t>(probe);
  std::free(probe);
  // Too little heap to mark: brk refused (glibc then maps the block apart, and the heap
  // goes on in small pages), or the reserve refused (strict overcommit, a data limit).
  if (reserve == 0 || after <= start + kHugePage) return false;
  // The reserve mapped apart (the break could not grow past another mapping): the heap
  // goes on elsewhere, in small pages.
  if (reserve < start || reserve + kHeapReserve > after) return false;
  return madvise(reinterpret_cast<void*>(start), after - start, MADV_HUGEPAGE) == 0;
#endif
}

}  // namespace gesmi::cli
