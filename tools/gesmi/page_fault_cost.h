// What a page fault in small pages costs this process, measured at start-up: the
// command's heap policy reads it to choose the heap's page size (command_heap.h).
#pragma once

namespace gesmi::cli {

/// CPU microseconds of a first write to a fresh 4 KiB page (the fault, the kernel's
/// zeroing and, on a virtual machine, the host's part), the smaller of two rounds of 8
/// pages: 16 faults, about 0.4 ms of CPU in all where one costs 10 µs (the mappings'
/// set-up and removal included). NaN where it cannot be measured (no mapping, no clock).
double small_page_fault_microseconds();

/// This thread's CPU time (user and system) in µs; NaN where the clock is missing.
double thread_cpu_microseconds();

}  // namespace gesmi::cli
