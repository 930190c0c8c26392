#pragma once
// --skip-existing, for batch reruns of a campaign (docs/batch.md): a command whose
// outputs all exist already does nothing. gesmi commits its outputs together under
// their final names only when complete (io/output/output_set.h), so an existing
// output is a whole one; whether it is up to date with its inputs is the caller's
// business, as with MB-System's tools.

#include <boost/program_options.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace gesmi::cli {

/// Adds --skip-existing to a command's options.
void add_skip_existing(boost::program_options::options_description& options);

/// True, after saying so on stdout, when --skip-existing was given and every one of
/// `outputs` is an existing file: the command then stops with exit code 0 and writes
/// nothing. Called once the options are parsed and the outputs checked, so that what
/// would be an error (exit 2) stays one.
bool skipped_as_existing(const boost::program_options::variables_map& values, std::string_view command,
                         const std::vector<std::string>& outputs);

}  // namespace gesmi::cli
