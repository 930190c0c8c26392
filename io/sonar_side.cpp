#include "io/sonar_side.h"

#include "io/format_error.h"
#include "io/text/message_text.h"

namespace gesmi::io {

std::string_view sonar_side_name(SonarSide side) {
  switch (side) {
    case SonarSide::starboard: return "starboard";
    case SonarSide::port: return "port";
    case SonarSide::both: return "both";
  }
  return "starboard";
}

SonarSide parse_sonar_side(const std::string& text, const std::string& context) {
  if (text == "starboard") return SonarSide::starboard;
  if (text == "port") return SonarSide::port;
  if (text == "both") return SonarSide::both;
  throw FormatError(context + ": expected starboard, port or both, found " + quoted_input(text));
}

}  // namespace gesmi::io
