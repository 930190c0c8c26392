#include "tools/gesmi/cli_args.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <vector>

#include "io/text/message_text.h"

namespace po = boost::program_options;

namespace gesmi::cli {

double parse_double(std::string_view option, const std::string& text) {
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(begin, &end);
  if (text.empty() || end != begin + text.size() || std::isnan(value) || (errno == ERANGE && std::isfinite(value) && value != 0.0))
    throw UsageError(std::string(option) + ": expected a number, got " + io::quoted_input(text));
  if (errno == ERANGE && !std::isfinite(value) && text.find_first_of("iI") == std::string::npos)
    throw UsageError(std::string(option) + ": number out of range: " + io::quoted_input(text));
  return value;
}

double parse_non_negative(std::string_view option, const std::string& text) {
  const double value = parse_double(option, text);
  if (value < 0.0) throw UsageError(std::string(option) + ": must not be negative, got " + io::quoted_input(text));
  return value;
}

long long parse_integer(std::string_view option, const std::string& text) {
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const long long value = std::strtoll(begin, &end, 10);
  if (text.empty() || end != begin + text.size() || errno == ERANGE)
    throw UsageError(std::string(option) + ": expected an integer, got " + io::quoted_input(text));
  return value;
}

int parse_int(std::string_view option, const std::string& text) {
  const long long value = parse_integer(option, text);
  return static_cast<int>(std::clamp<long long>(value, std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
}

bool parse_options(std::span<const std::string> args, const po::options_description& options,
                   const po::positional_options_description& positional, po::variables_map& values,
                   std::string_view usage) {
  po::options_description all = options;
  all.add_options()("help,h", "show this help");
  const std::vector<std::string> argv(args.begin(), args.end());
  try {
    po::store(po::command_line_parser(argv).options(all).positional(positional).run(), values);
    if (values.count("help")) {
      std::cout << "usage: " << usage << "\n\n" << all << "\n";
      return false;
    }
    po::notify(values);
  } catch (const po::too_many_positional_options_error&) {
    throw UsageError("too many arguments; usage: " + std::string(usage));
  } catch (const po::error& e) {
    throw UsageError(e.what());
  }
  return true;
}

}  // namespace gesmi::cli
