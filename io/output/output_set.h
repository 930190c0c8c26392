#pragma once
// The files one command writes, committed as one set. While an OutputSet is open,
// every AtomicOutput of the process hands its finished temporary file to it instead
// of renaming it; commit() renames them all. A set destroyed without commit (an
// error, an exception) removes every temporary it holds, the files that sets opened
// inside it committed, and the folders it created, so on any failure none of the
// new files is left.
//
//   io::OutputSet outputs({mission_path});      // the command's inputs
//   outputs.check(result_path);                 // before any work
//   io::write_result(result, result_path);      // AtomicOutput inside
//   outputs.commit();                           // now result_path exists
//
// check() refuses an output that is one of the inputs (the same file, whatever the
// path says) or an existing non-regular file (a device, a pipe, a folder), so a
// command can neither overwrite what it reads nor replace /dev/null.

#include <string>
#include <utility>
#include <vector>

namespace gesmi::io {

class OutputSet {
 public:
  explicit OutputSet(std::vector<std::string> inputs = {});
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;
  ~OutputSet();

  /// Refuses `path` as an output (FormatError naming it): an input, an existing
  /// non-regular file, a folder that does not exist or cannot be written.
  void check(const std::string& path) const;
  /// Refuses `folder` as an output folder (FormatError naming it): a file, a folder that
  /// cannot be written, or a missing folder whose parent does not exist or cannot be
  /// written. A trailing separator ("out/") names the same folder.
  static void check_folder(const std::string& folder);
  /// An output folder: checked, created if missing (removed again on failure if still
  /// empty).
  void prepare_folder(const std::string& folder);
  /// A file that belongs with this set (a sibling such as RESULT.mines.csv): when the
  /// set commits without having written it, a copy left by an earlier run is removed,
  /// so a new result never sits beside stale siblings.
  void owns(const std::string& path);
  /// Renames every file into place; FormatError when one cannot be (the new files
  /// already renamed are then removed again).
  void commit();
  /// The final paths committed, in the order they were written.
  const std::vector<std::string>& written() const { return written_; }

  /// The innermost open set, or nullptr (for AtomicOutput).
  static OutputSet* active();
  /// The inputs of every open set, innermost first, each once: the files the
  /// outputs being written were made from (their provenance, io/files/provenance.h).
  static std::vector<std::string> open_inputs();
  /// Takes a finished temporary file (AtomicOutput::commit while this set is open).
  void adopt(std::string temp_path, std::string final_path, int slot);

 private:
  struct Pending {
    std::string temp, final;
    int slot;
  };
  std::vector<std::string> inputs_;
  std::vector<Pending> pending_;
  std::vector<std::string> owned_, written_, nested_written_;
  std::vector<std::pair<std::string, int>> created_folders_;
  OutputSet* outer_ = nullptr;
  bool committed_ = false;
};

}  // namespace gesmi::io
