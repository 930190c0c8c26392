#pragma once
#include <string_view>

namespace gesmi::io {

/// gesmi's version, as set in the top-level CMakeLists.txt.
std::string_view version();

}  // namespace gesmi::io
