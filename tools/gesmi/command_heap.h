// The process's memory policy for the gesmi command (not the library: a program that
// links gesmi keeps its own).
#pragma once

namespace gesmi::cli {

// Blocks up to 32 MiB from the heap, one arena for every thread, no trimming before
// exit, and blocks too big for the heap in huge pages (huge_page_blocks.h): freed
// memory is reused, not faulted in again (docs/architecture.md, "Memory"). The heap
// itself stays in small pages (docs/performance.md, "The heap back in small pages").
// Never fails.
void use_command_heap();

}  // namespace gesmi::cli
