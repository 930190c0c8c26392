// The process's memory policy for the gesmi command (not the library: a program that
// links gesmi keeps its own).
#pragma once

namespace gesmi::cli {

// Ask the kernel for transparent huge pages on the first 256 MiB of the heap and keep
// freed memory for reuse (docs/performance.md, "Page faults"). A no-op where the kernel
// refuses; never fails.
void use_huge_page_heap();

}  // namespace gesmi::cli
