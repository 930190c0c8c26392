// The heap in transparent huge pages, for the gesmi command where small pages' faults
// are costly (command_heap.h chooses).
#pragma once

namespace gesmi::cli {

// Grows the heap by a 256 MiB reserve (address space only) starting on a huge-page
// boundary and marks it for transparent huge pages (MADV_HUGEPAGE): later blocks are
// carved from it. Call after the allocator's settings (command_heap.cpp), before any
// thread starts (it changes M_MMAP_MAX for a moment, and takes the heap's start from
// the one arena's size). Returns
// whether the heap was marked: not under ASan, nor where glibc perturbs blocks, nor
// where the program break cannot grow.
bool mark_heap_for_huge_pages();

}  // namespace gesmi::cli
