#include "io/output/atomic_output.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "io/format_error.h"
#include "io/output/interrupt_cleanup.h"
#include "io/output/output_set.h"
#include "io/output/temporary_names.h"

namespace gesmi::io {

namespace fs = std::filesystem;

AtomicOutput::AtomicOutput(std::string final_path) : final_path_(std::move(final_path)) {
  // Beside the target, or in its folder's staging folder (OutputSet::prepare_folder).
  const OutputSet* set = OutputSet::active();
  const fs::path where(set ? set->staged_path(final_path_) : final_path_);
  temp_path_ = temporary_name(where.string());
  remove_dead_temporaries(where.parent_path(), where.filename().string());
  slot_ = track_temporary(temp_path_);
}

AtomicOutput::~AtomicOutput() {
  if (committed_) return;
  std::remove(temp_path_.c_str());
  untrack_temporary(slot_);
}

void AtomicOutput::commit() {
  // Fault injection for the test suite (tests/tools/output_safety_test.cpp): a target
  // whose path contains $GESMI_TEST_FAIL_WRITE fails as a full disk would.
  if (const char* failing = std::getenv("GESMI_TEST_FAIL_WRITE"); failing && *failing && final_path_.find(failing) != std::string::npos)
    throw FormatError(final_path_ + ": cannot write (disk full?) [injected by GESMI_TEST_FAIL_WRITE]");
  if (OutputSet* set = OutputSet::active()) {
    set->adopt(temp_path_, final_path_, slot_);  // the set renames, or removes, it
    committed_ = true;
    return;
  }
  if (std::rename(temp_path_.c_str(), final_path_.c_str()) != 0)
    throw FormatError(final_path_ + ": cannot write: " + std::strerror(errno));
  untrack_temporary(slot_);
  committed_ = true;
}

void write_text_file(const std::string& path, const std::string& text) {
  AtomicOutput out(path);
  {
    std::ofstream file(out.temp_path(), std::ios::binary);
    if (!file) throw FormatError(path + ": cannot create the file: " + std::strerror(errno));
    file << text;
    file.flush();
    if (!file) throw FormatError(path + ": cannot write (disk full?)");
  }
  out.commit();
}

void check_writable_target(const std::string& path) {
  const fs::path target(path);
  if (path.empty()) throw FormatError("output path is empty");
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) throw FormatError(path + ": folder " + folder.string() + " does not exist");
  if (::access(folder.c_str(), W_OK) != 0) throw FormatError(path + ": folder " + folder.string() + " is not writable");
  const fs::file_status status = fs::symlink_status(target, ec);
  if (fs::is_directory(fs::status(target, ec))) throw FormatError(path + ": is a folder, expected a file name");
  if (fs::exists(status) && !fs::is_regular_file(status) && !fs::is_symlink(status))
    throw FormatError(path + ": exists and is not a regular file (a device or a pipe); choose a file name");
  if (fs::is_symlink(status) && fs::exists(fs::status(target, ec)) && !fs::is_regular_file(fs::status(target, ec)))
    throw FormatError(path + ": is a link to something that is not a regular file; choose a file name");
}

}  // namespace gesmi::io
