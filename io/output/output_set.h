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
  /// An output folder: checked, and created if missing. A missing folder is staged
  /// unless `in_place`: it is created as "<folder>.tmp-<pid>" (temporary_names.h), the
  /// files named in `folder` are written there, and commit() renames it to `folder` once
  /// they are in it, so a folder under its final name is always complete. A folder
  /// created in place (for files that name each other by path) is removed again on
  /// failure if still empty.
  void prepare_folder(const std::string& folder, bool in_place = false);
  /// Where the file `path` is written until commit: in its folder's staging folder when
  /// that folder is staged by this set or an enclosing one, else `path` itself.
  std::string staged_path(const std::string& path) const;
  /// Whether `folder` is staged by this set or an enclosing one.
  bool stages(const std::string& folder) const { return staging_of(folder) != nullptr; }
  /// A file that belongs with this set (a sibling such as RESULT.mines.csv): when the
  /// set commits without having written it, a copy left by an earlier run is removed,
  /// so a new result never sits beside stale siblings.
  void owns(const std::string& path);
  /// Renames every file into place, then every staged folder; FormatError when one
  /// cannot be (the new files already renamed are then removed again).
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
    std::string temp, staged, final;  // staged: where commit() renames it (staged_path)
    int slot;
  };
  std::vector<std::string> inputs_;
  std::vector<Pending> pending_;
  std::vector<std::string> owned_, written_, nested_written_;
  std::vector<std::pair<std::string, int>> created_folders_;
  struct Staged {
    std::string staging, final;
    int slot;
  };
  std::vector<Staged> staged_folders_;
  void rename_staged_folders(const std::vector<std::string>& renamed);
  const Staged* staging_of(const std::string& folder) const;
  OutputSet* outer_ = nullptr;
  bool committed_ = false;
};

/// Creates `folder` (and its parents) for a writer, unless the open set stages it
/// (OutputSet::prepare_folder): a writer called outside a command makes its own folder.
/// FormatError naming the folder when it cannot be created.
void create_output_folder(const std::string& folder);

}  // namespace gesmi::io
