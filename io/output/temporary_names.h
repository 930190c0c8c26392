#pragma once
// The names of gesmi's temporaries, "<final name>.tmp-<pid>" beside their target (a file
// being written, or a folder being filled), and the removal of those a process left
// when it was killed by -9 or a power cut: the next run that writes beside them removes
// them, since no signal handler could.

#include <filesystem>
#include <string>

namespace gesmi::io {

/// "<final_path>.tmp-<this process's id>".
std::string temporary_name(const std::string& final_path);

/// Removes, in `folder`, the files and folders named "<name>.tmp-<pid>" whose process no
/// longer runs: every such name, or only those of `name` when it is not empty.
void remove_dead_temporaries(const std::filesystem::path& folder, const std::string& name = {});

}  // namespace gesmi::io
