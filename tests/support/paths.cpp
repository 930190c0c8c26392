#include "tests/support/paths.h"

namespace gesmi::test {

std::string source_dir() { return GESMI_SOURCE_DIR; }
std::string bin_dir() { return GESMI_BIN_DIR; }
std::string itf1788_dir() { return GESMI_ITF1788_DIR; }

}  // namespace gesmi::test
