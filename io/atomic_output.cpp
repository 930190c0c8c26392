#include "io/atomic_output.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "io/format_error.h"

namespace gesmi::io {

AtomicOutput::AtomicOutput(std::string final_path)
    : final_path_(std::move(final_path)), temp_path_(final_path_ + ".tmp-" + std::to_string(::getpid())) {}

AtomicOutput::~AtomicOutput() {
  if (!committed_) std::remove(temp_path_.c_str());
}

void AtomicOutput::commit() {
  if (std::rename(temp_path_.c_str(), final_path_.c_str()) != 0)
    throw FormatError(final_path_ + ": cannot write: " + std::strerror(errno));
  committed_ = true;
}

void write_text_file(const std::string& path, const std::string& text) {
  AtomicOutput out(path);
  {
    std::ofstream file(out.temp_path(), std::ios::binary);
    file << text;
    file.flush();
    if (!file) throw FormatError(path + ": cannot write: " + std::strerror(errno));
  }
  out.commit();
}

void check_writable_target(const std::string& path) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  if (path.empty()) throw FormatError("output path is empty");
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) throw FormatError(path + ": folder " + folder.string() + " does not exist");
  if (::access(folder.c_str(), W_OK) != 0) throw FormatError(path + ": folder " + folder.string() + " is not writable");
  if (fs::is_directory(target, ec)) throw FormatError(path + ": is a folder, expected a file name");
}

}  // namespace gesmi::io
