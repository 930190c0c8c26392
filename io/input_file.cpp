#include "io/input_file.h"

#include <sys/stat.h>

#include "io/format_error.h"

namespace gesmi::io {

void require_regular_file(const std::string& path) {
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0) throw FormatError(path + ": cannot open the file (does it exist?)");
  if (S_ISREG(status.st_mode)) return;
  const char* what = S_ISDIR(status.st_mode)                               ? "a folder"
                     : S_ISFIFO(status.st_mode)                            ? "a pipe"
                     : S_ISCHR(status.st_mode) || S_ISBLK(status.st_mode) ? "a device"
                     : S_ISSOCK(status.st_mode)                            ? "a socket"
                                                                           : "not a regular file";
  const bool stream = S_ISFIFO(status.st_mode) || S_ISCHR(status.st_mode) || S_ISSOCK(status.st_mode);
  throw FormatError(path + ": is " + what + ", not a file" +
                    (stream ? ": gesmi reads its inputs from files (save the stream to one and give that)" : ""));
}

}  // namespace gesmi::io
