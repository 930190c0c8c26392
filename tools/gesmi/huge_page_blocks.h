// Large C++ blocks (arrays of 10^7-step missions) in their own huge-page mappings.
#pragma once

#include <cstddef>

namespace gesmi::cli {

/// From now on, `operator new` serves blocks of at least kHugePageBlock bytes from their
/// own mapping marked for transparent huge pages (glibc would map them in 4 KiB pages);
/// smaller blocks still come from malloc. Under ASan, which owns operator new, nothing
/// changes.
void use_huge_page_blocks();

inline constexpr std::size_t kHugePageBlock = std::size_t{32} << 20;  // glibc's largest heap block

}  // namespace gesmi::cli
