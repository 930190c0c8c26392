#pragma once
// Command-line helpers shared by the subcommands: strict number parsing and
// Boost.Program_options parsing that turns every failure into a one-line UsageError.

#include <boost/program_options.hpp>
#include <span>
#include <string>
#include <string_view>

#include "tools/gesmi/command.h"

namespace gesmi::cli {

/// Parses a whole string as a double ("inf" accepted); throws UsageError naming the option.
double parse_double(std::string_view option, const std::string& text);
/// Parses a non-negative double ("inf" accepted).
double parse_non_negative(std::string_view option, const std::string& text);
/// Parses a whole string as an integer.
long long parse_integer(std::string_view option, const std::string& text);
/// The same, clamped to int's range: for options whose validate() bounds them well within
/// it, and then names the option with its bounds.
int parse_int(std::string_view option, const std::string& text);

/// Parses args against options (and positional names, in order). Unknown options,
/// missing values and extra arguments become UsageError. Returns false when --help
/// was asked for (the help text is printed).
bool parse_options(std::span<const std::string> args, const boost::program_options::options_description& options,
                   const boost::program_options::positional_options_description& positional,
                   boost::program_options::variables_map& values, std::string_view usage);

}  // namespace gesmi::cli
