#include "io/output/temporary_names.h"

#include <signal.h>
#include <unistd.h>

#include <cerrno>

namespace gesmi::io {
namespace {

namespace fs = std::filesystem;

constexpr const char* kTempMark = ".tmp-";

// Whether `name` is "<base>.tmp-<pid>" (with `base` when it is not empty) of a process
// that no longer runs.
bool dead_temporary(const std::string& name, const std::string& base) {
  const std::size_t mark = name.rfind(kTempMark);
  if (mark == std::string::npos || mark == 0) return false;
  if (!base.empty() && name.compare(0, mark, base) != 0) return false;
  if (!base.empty() && mark != base.size()) return false;
  const std::string digits = name.substr(mark + std::char_traits<char>::length(kTempMark));
  if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) return false;
  const pid_t pid = static_cast<pid_t>(std::stol(digits));
  return pid != ::getpid() && ::kill(pid, 0) != 0 && errno == ESRCH;
}

}  // namespace

std::string temporary_name(const std::string& final_path) {
  return final_path + kTempMark + std::to_string(::getpid());
}

void remove_dead_temporaries(const fs::path& folder, const std::string& name) {
  std::error_code ec;
  const fs::path where = folder.empty() ? fs::path(".") : folder;
  for (fs::directory_iterator it(where, ec), end; !ec && it != end; it.increment(ec)) {
    if (!dead_temporary(it->path().filename().string(), name)) continue;
    std::error_code ignored;
    fs::remove_all(it->path(), ignored);
  }
}

}  // namespace gesmi::io
