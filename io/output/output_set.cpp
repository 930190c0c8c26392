#include "io/output/output_set.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "io/output/atomic_output.h"
#include "io/format_error.h"
#include "io/output/interrupt_cleanup.h"
#include "io/output/temporary_names.h"

namespace gesmi::io {
namespace {

namespace fs = std::filesystem;

OutputSet*& innermost() {
  static OutputSet* set = nullptr;
  return set;
}

bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec;
  return fs::exists(a, ec) && fs::exists(b, ec) && fs::equivalent(a, b, ec) && !ec;
}

}  // namespace

OutputSet::OutputSet(std::vector<std::string> inputs) : inputs_(std::move(inputs)), outer_(innermost()) {
  innermost() = this;
}

OutputSet::~OutputSet() {
  innermost() = outer_;
  if (committed_) return;
  for (const Pending& p : pending_) {
    std::remove(p.temp.c_str());
    untrack_temporary(p.slot);
  }
  for (const std::string& path : nested_written_) std::remove(path.c_str());
  for (auto it = created_folders_.rbegin(); it != created_folders_.rend(); ++it) {
    ::rmdir(it->first.c_str());  // only if still empty
    untrack_temporary(it->second);
  }
  for (const Staged& s : staged_folders_) {
    std::error_code ignored;
    fs::remove_all(s.staging, ignored);  // wholly this run's
    untrack_temporary(s.slot);
  }
}

OutputSet* OutputSet::active() { return innermost(); }

std::vector<std::string> OutputSet::open_inputs() {
  std::vector<std::string> inputs;
  for (const OutputSet* set = innermost(); set; set = set->outer_)
    for (const std::string& path : set->inputs_)
      if (std::find(inputs.begin(), inputs.end(), path) == inputs.end()) inputs.push_back(path);
  return inputs;
}

void OutputSet::check(const std::string& path) const {
  check_writable_target(path);
  for (const std::string& input : inputs_)
    if (!input.empty() && same_file(path, input))
      throw FormatError(path + ": is also an input of this command (" + input + "); write to another file");
}

namespace {

// The folder's path without trailing separators ("out/" and "out" are one folder; "/"
// stays). Nothing else is rewritten: "a/.." means what the file system says it means.
fs::path folder_path(const std::string& folder) {
  std::string name = folder;
  while (name.size() > 1 && name.back() == '/') name.pop_back();
  return fs::path(name);
}

}  // namespace

void OutputSet::check_folder(const std::string& folder) {
  std::error_code ec;
  if (folder.empty()) throw FormatError("output folder: empty name");
  const fs::path path = folder_path(folder);
  if (fs::exists(fs::symlink_status(path, ec))) {
    if (!fs::is_directory(path, ec)) throw FormatError(folder + ": exists and is not a folder");
    if (::access(path.c_str(), W_OK) != 0) throw FormatError(folder + ": folder is not writable");
    return;
  }
  const fs::path parent = path.has_parent_path() ? path.parent_path() : fs::path(".");
  if (!fs::is_directory(parent, ec)) throw FormatError(folder + ": parent folder " + parent.string() + " does not exist");
  if (::access(parent.c_str(), W_OK) != 0) throw FormatError(folder + ": parent folder " + parent.string() + " is not writable");
}

void OutputSet::prepare_folder(const std::string& folder, bool in_place) {
  check_folder(folder);
  const fs::path path = folder_path(folder);
  std::error_code ec;
  if (fs::is_directory(path, ec)) return;
  if (in_place) {
    if (!fs::create_directory(path, ec) || ec) throw FormatError(folder + ": cannot create the folder: " + ec.message());
    created_folders_.emplace_back(path.string(), track_temporary(path.string(), true));
    return;
  }
  remove_dead_temporaries(path.parent_path(), path.filename().string());
  const std::string staging = temporary_name(path.string());
  if (!fs::create_directory(staging, ec) || ec) throw FormatError(folder + ": cannot create the folder: " + ec.message());
  staged_folders_.push_back({staging, path.lexically_normal().string(), track_temporary(staging, true)});
}

const OutputSet::Staged* OutputSet::staging_of(const std::string& folder) const {
  const std::string wanted = folder_path(folder).lexically_normal().string();
  for (const OutputSet* set = this; set; set = set->outer_)
    for (const Staged& s : set->staged_folders_)
      if (s.final == wanted) return &s;
  return nullptr;
}

std::string OutputSet::staged_path(const std::string& path) const {
  const fs::path target(path);
  const Staged* s = staging_of(target.parent_path().string());
  return s ? (fs::path(s->staging) / target.filename()).string() : path;
}

void create_output_folder(const std::string& folder) {
  if (const OutputSet* set = OutputSet::active(); set && set->stages(folder)) return;
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec) throw FormatError(folder + ": cannot create the folder: " + ec.message());
}

void OutputSet::owns(const std::string& path) { owned_.push_back(path); }

void OutputSet::adopt(std::string temp_path, std::string final_path, int slot) {
  std::string staged = staged_path(final_path);
  pending_.push_back({std::move(temp_path), std::move(staged), std::move(final_path), slot});
}

void OutputSet::commit() {
  // Fault injection for the test suite: hold the complete temporaries for a while, so
  // that a test can interrupt the command at the worst moment.
  if (const char* pause = std::getenv("GESMI_TEST_PAUSE_BEFORE_COMMIT"); pause && !pending_.empty())
    ::usleep(static_cast<useconds_t>(std::clamp(std::atof(pause), 0.0, 10.0) * 1e6));
  std::vector<std::string> renamed;  // where each file now is (in a staging folder or in place)
  for (std::size_t i = 0; i < pending_.size(); ++i) {
    const Pending& p = pending_[i];
    if (std::rename(p.temp.c_str(), p.staged.c_str()) != 0) {
      const std::string why = std::strerror(errno);
      for (const std::string& done : renamed) std::remove(done.c_str());
      pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(i));
      throw FormatError(p.final + ": cannot write: " + why);
    }
    untrack_temporary(p.slot);
    renamed.push_back(p.staged);
    written_.push_back(p.final);
  }
  pending_.clear();
  rename_staged_folders(renamed);
  for (const std::string& path : owned_) {
    const bool rewritten = std::any_of(written_.begin(), written_.end(), [&](const std::string& w) { return w == path; });
    std::error_code ec;
    if (!rewritten && fs::is_regular_file(fs::symlink_status(path, ec))) fs::remove(path, ec);
  }
  for (const auto& [folder, slot] : created_folders_) untrack_temporary(slot);
  created_folders_.clear();
  if (outer_) outer_->nested_written_.insert(outer_->nested_written_.end(), written_.begin(), written_.end());
  committed_ = true;
}

// Each staged folder under its final name; on failure the files `renamed` into place and
// the folders renamed already are removed again.
void OutputSet::rename_staged_folders(const std::vector<std::string>& renamed) {
  for (std::size_t i = 0; i < staged_folders_.size(); ++i) {
    const Staged& s = staged_folders_[i];
    // (onto an empty folder that appeared meanwhile too; never onto files)
    if (std::rename(s.staging.c_str(), s.final.c_str()) != 0) {
      const std::string why = std::strerror(errno);
      for (const std::string& done : renamed) std::remove(done.c_str());
      written_.clear();
      std::error_code ignored;
      for (std::size_t j = 0; j < i; ++j) fs::remove_all(staged_folders_[j].final, ignored);
      throw FormatError(s.final + ": cannot write the folder: " + why);
    }
  }
  for (const Staged& s : staged_folders_) untrack_temporary(s.slot);
  staged_folders_.clear();
}

}  // namespace gesmi::io
