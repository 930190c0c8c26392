// The process's memory policy for the gesmi command (not the library: a program that
// links gesmi keeps its own).
#pragma once

namespace gesmi::cli {

enum class HeapPages {
  small,          // 4 KiB pages
  huge,           // marked for transparent huge pages (huge_page_heap.h)
  by_fault_cost,  // huge where a small page's fault costs kCostlySmallFault or more
};

/// A small page's fault at or above this (CPU µs, page_fault_cost.h) puts the heap in
/// huge pages. Between the two hosts measured: about 1 µs where huge pages cost more
/// after a pause, about 10 µs where they cost less in every case measured
/// (docs/performance.md, "The heap's page size from the cost of a fault").
inline constexpr double kCostlySmallFault = 4.0;

// Blocks up to 32 MiB from the heap, one arena for every thread, no trimming before
// exit, and blocks too big for the heap in huge pages (huge_page_blocks.h): freed
// memory is reused, not faulted in again (docs/architecture.md, "Memory"). The heap
// itself in the pages asked for; by_fault_cost measures a small page's fault first
// (16 faults). Call before any thread starts. Returns the heap's pages: small where
// huge ones were asked for but could not be had. Never fails.
HeapPages use_command_heap(HeapPages pages = HeapPages::by_fault_cost);

}  // namespace gesmi::cli
