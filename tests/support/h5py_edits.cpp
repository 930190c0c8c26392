#include "tests/support/h5py_edits.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/support/run_command.h"

namespace gesmi::test {

std::vector<std::string> h5py_edited_copies(const std::string& source, const std::vector<std::string>& edits) {
  const std::string folder = temp_folder("h5py-edits");
  std::vector<std::string> copies;
  // Each edit becomes the body of a function of its own, so that its names stay its own.
  std::ostringstream script;
  script << "import h5py, numpy as np, sys\n";
  for (std::size_t i = 0; i < edits.size(); ++i) {
    copies.push_back(folder + "/edited-" + std::to_string(i) + ".h5");
    std::filesystem::copy_file(source, copies.back());
    script << "def edit_" << i << "(f):\n";
    std::istringstream lines(edits[i]);
    for (std::string line; std::getline(lines, line);) script << "    " << line << "\n";
    script << "    pass\n";
  }
  script << "for i, path in enumerate(sys.argv[1:]):\n"
            "    with h5py.File(path, 'r+') as f:\n"
            "        globals()['edit_%d' % i](f)\n";
  const std::string script_path = folder + "/edit.py";
  std::ofstream(script_path) << script.str();
  std::string command = "/usr/bin/python3 " + script_path;
  for (const std::string& copy : copies) command += " " + copy;
  EXPECT_EQ(std::system(command.c_str()), 0) << script.str();
  return copies;
}

std::string h5py_edited_copy(const std::string& source, const std::string& edit) {
  return h5py_edited_copies(source, {edit}).front();
}

}  // namespace gesmi::test
