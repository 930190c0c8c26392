#pragma once
// Names of the sonar side in files and on the command line.

#include <string>
#include <string_view>

#include "solver/mission/sensor_model.h"

namespace gesmi::io {

std::string_view sonar_side_name(SonarSide side);
/// "starboard", "port" or "both"; FormatError "<context>: ..." otherwise.
SonarSide parse_sonar_side(const std::string& text, const std::string& context);

}  // namespace gesmi::io
