// Why: fresh memory costs a page fault per page the first time it is touched, and glibc
// by default gives blocks of 128 kB and more their own mapping, unmapped when freed, so
// each such block is faulted in again after every free (its threshold then rises to the
// size of a freed block, up to 32 MiB, but only after that first round); its worker
// threads get arenas of their own, and it returns the heap's top to the kernel past
// 128 kB free (the threshold rises there too). The command's arrays are freed and
// allocated again all along a solve, so here blocks up to 32 MiB come from the heap and
// stay there for reuse. Which page size the heap is cheaper in depends on the host: on a
// virtual machine that gives its free 2 MiB blocks back to the host (free page
// reporting), a huge page is fresh host memory every time, and small pages cost less
// after a pause; where the guest's page tables are shadowed, a small page's fault costs
// ten times more and huge pages cost less in every case measured (docs/performance.md).

#include "tools/gesmi/command_heap.h"

#include <malloc.h>

#include "tools/gesmi/huge_page_blocks.h"
#include "tools/gesmi/huge_page_heap.h"
#include "tools/gesmi/page_fault_cost.h"

namespace gesmi::cli {

HeapPages use_command_heap(HeapPages pages) {
  use_huge_page_blocks();  // the blocks too large for the heap
#if defined(__SANITIZE_ADDRESS__)
  (void)pages;
  return HeapPages::small;  // ASan's allocator ignores glibc's settings and has no heap to mark
#else
  mallopt(M_MMAP_THRESHOLD, static_cast<int>(kHugePageBlock));
  mallopt(M_ARENA_MAX, 1);        // worker threads allocate from the same heap
  mallopt(M_TRIM_THRESHOLD, -1);  // never trimmed (mallopt(3))
  // (NaN, not measured, compares false: small pages)
  if (pages == HeapPages::by_fault_cost)
    pages = small_page_fault_microseconds() >= kCostlySmallFault ? HeapPages::huge : HeapPages::small;
  if (pages == HeapPages::huge && !mark_heap_for_huge_pages()) pages = HeapPages::small;
  return pages;
#endif
}

}  // namespace gesmi::cli
