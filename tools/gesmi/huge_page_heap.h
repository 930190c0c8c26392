// The process's memory policy for the gesmi command (not the library: a program that
// links gesmi keeps its own).
#pragma once

namespace gesmi::cli {

// Ask the kernel for transparent huge pages on the first 256 MiB of the heap and on
// blocks too big for it (huge_page_blocks.h), and keep freed memory for reuse
// (docs/performance.md, "Huge pages for the command's heap"). Where the kernel refuses
// the marks, only the allocator settings remain; never fails.
void use_huge_page_heap();

}  // namespace gesmi::cli
