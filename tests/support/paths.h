#pragma once
// Locations the tests need, passed by CMake as compile definitions (never relative
// to the working directory).

#include <string>

namespace gesmi::test {

inline std::string source_dir() { return GESMI_SOURCE_DIR; }
inline std::string bin_dir() { return GESMI_BIN_DIR; }
inline std::string itf1788_dir() { return GESMI_ITF1788_DIR; }

}  // namespace gesmi::test
