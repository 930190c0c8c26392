#pragma once
// The files a command reads, as named by its options: an io::OutputSet refuses to
// write over any of them.

#include <boost/program_options.hpp>
#include <initializer_list>
#include <string>
#include <vector>

namespace gesmi::cli {

/// The values of those of `options` that were given.
inline std::vector<std::string> input_files(const boost::program_options::variables_map& v,
                                            std::initializer_list<const char*> options) {
  std::vector<std::string> files;
  for (const char* name : options)
    if (v.count(name)) files.push_back(v[name].as<std::string>());
  return files;
}

}  // namespace gesmi::cli
