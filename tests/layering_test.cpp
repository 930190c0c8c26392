// The layering of docs/architecture.md, checked on the sources: solver/ does no
// file or terminal I/O and includes nothing from io/, tools/, HDF5 or yaml-cpp.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

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

// io/'s folders in layers (io/README.md): a folder includes only from its own layer's
// folders or the layers below, so the folders form no cycle.
TEST(Layering, IoFoldersIncludeOnlyTheLayersBelow) {
  const std::vector<std::vector<std::string>> layers = {
      {"text", "time", "digest", "output"}, {"report", "hdf5"}, {"files", "plot"}, {"imports"}, {"exports", "localization"}};
  const auto layer_of = [&](const std::string& folder) {
    for (std::size_t i = 0; i < layers.size(); ++i)
      for (const std::string& f : layers[i])
        if (f == folder) return static_cast<int>(i);
    return -1;
  };
  const std::string include = "#include \"io/";
  int files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(gesmi::test::source_dir() + "/io")) {
    const std::filesystem::path relative = std::filesystem::relative(entry.path(), gesmi::test::source_dir() + "/io");
    if (!entry.is_regular_file() || std::distance(relative.begin(), relative.end()) < 2) continue;  // (root files)
    const int own = layer_of(relative.begin()->string());
    ASSERT_GE(own, 0) << relative << ": a folder of io/ missing from the layers here and in io/README.md";
    ++files;
    std::ifstream in(entry.path());
    for (std::string line; std::getline(in, line);) {
      if (line.rfind(include, 0) != 0) continue;
      const std::string path = line.substr(include.size());
      const std::size_t slash = path.find('/');
      if (slash == std::string::npos) continue;  // (io/'s root files)
      const std::string folder = path.substr(0, slash);
      const int theirs = layer_of(folder);
      EXPECT_TRUE(theirs >= 0 && theirs <= own) << relative << " includes io/" << folder << "/";
    }
  }
  EXPECT_GT(files, 50);
}

}  // namespace
