#pragma once
// The one exception type of io/: bad input, named precisely.

#include <stdexcept>
#include <string>

namespace gesmi::io {

/// A file that cannot be read or is not valid. what() is one line naming the file,
/// the dataset or line, the field and the reason, e.g.
/// "mission.h5: /nav/time: row 17: time does not increase (4.2 after 4.3)".
class FormatError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace gesmi::io
