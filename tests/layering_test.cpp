// The layering of docs/architecture.md, checked on the sources: solver/ does no
// file or terminal I/O and includes nothing from io/, tools/, HDF5 or yaml-cpp.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/support/paths.h"

namespace {

TEST(Layering, SolverIncludesNoIoAndNoFileLibraries) {
  const char* forbidden[] = {"<iostream>", "<fstream>", "<cstdio>", "<stdio.h>", "hdf5", "yaml-cpp",
                             "\"io/", "\"tools/", "GeographicLib", "cairo", "printf(", "std::cout", "std::cerr"};
  int files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(gesmi::test::source_dir() + "/solver")) {
    if (!entry.is_regular_file()) continue;
    const auto ext = entry.path().extension();
    if (ext != ".h" && ext != ".cpp") continue;
    ++files;
    std::ifstream in(entry.path());
    std::stringstream text;
    text << in.rdbuf();
    for (const char* word : forbidden)
      EXPECT_EQ(text.str().find(word), std::string::npos) << entry.path() << " contains " << word;
  }
  EXPECT_GT(files, 5);
}

}  // namespace
