// Inputs that are not regular files are refused before they are opened: a pipe would
// block the reader, a device would never end (through the command: bad_input_test.cpp).
#include "io/input_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <cstring>
#include <fstream>

#include "io/format_error.h"
#include "tests/support/run_command.h"

namespace gesmi::io {
namespace {

std::string open_error(const std::string& path) {
  try {
    require_regular_file(path);
  } catch (const FormatError& e) {
    return e.what();
  }
  return "";
}

TEST(InputFile, OnlyRegularFilesPass) {
  const std::string folder = test::temp_folder("input-file");
  const std::string file = folder + "/f.csv", pipe = folder + "/pipe", socket_path = folder + "/s";
  std::ofstream(file) << "time\n";
  ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
  const int s = ::socket(AF_UNIX, SOCK_STREAM, 0);
  ASSERT_GE(s, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  std::strncpy(address.sun_path, socket_path.c_str(), sizeof address.sun_path - 1);
  ASSERT_EQ(::bind(s, reinterpret_cast<const sockaddr*>(&address), sizeof address), 0);

  EXPECT_EQ(open_error(file), "");
  EXPECT_EQ(open_error(folder + "/missing.csv"), folder + "/missing.csv: cannot open the file (does it exist?)");
  EXPECT_EQ(open_error(folder), folder + ": is a folder, not a file");
  const std::string stream = ", not a file: gesmi reads its inputs from files (save the stream to one and give that)";
  EXPECT_EQ(open_error(pipe), pipe + ": is a pipe" + stream);
  EXPECT_EQ(open_error("/dev/zero"), "/dev/zero: is a device" + stream);
  EXPECT_EQ(open_error(socket_path), socket_path + ": is a socket" + stream);
  ::close(s);
}

}  // namespace
}  // namespace gesmi::io
