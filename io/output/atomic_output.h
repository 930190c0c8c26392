#pragma once
// Outputs are written to a temporary name beside the target and renamed into
// place only when complete, so a failed or interrupted run never leaves a
// half-written file under the requested name.
//
//   AtomicOutput out("result.h5");
//   write_everything(out.temp_path());   // any writer that takes a path
//   out.commit();                        // rename; without it the temp file is removed
//
// While an OutputSet is open (output_set.h), commit() hands the file to the set,
// which renames all of a command's files together. The temporary name is
// "<target>.tmp-<pid>" (in the staging folder of a folder the set stages);
// temporaries of processes that no longer run are removed
// when the same target is written again, and an interrupt removes the current
// ones (interrupt_cleanup.h).

#include <string>

namespace gesmi::io {

class AtomicOutput {
 public:
  explicit AtomicOutput(std::string final_path);
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;
  ~AtomicOutput();

  const std::string& temp_path() const { return temp_path_; }
  const std::string& final_path() const { return final_path_; }
  /// Renames the temporary file to the final name (or hands it to the open
  /// OutputSet); throws FormatError on failure.
  void commit();

 private:
  std::string final_path_;
  std::string temp_path_;
  int slot_ = -1;
  bool committed_ = false;
};

/// Writes text to path atomically (temporary file, then rename).
void write_text_file(const std::string& path, const std::string& text);

/// Checks before any work starts that the folder of `path` exists and is writable
/// and that `path` is not an existing folder, device or pipe, so a long run does not
/// fail at the end; throws FormatError naming the path.
void check_writable_target(const std::string& path);

}  // namespace gesmi::io
