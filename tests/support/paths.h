#pragma once
// Locations the tests need (never relative to the working directory). CMake passes them
// to paths.cpp alone, so that no other file's compile command names the checkout and a
// compiler cache serves any clone of the project.

#include <string>

namespace gesmi::test {

std::string source_dir();
std::string bin_dir();
std::string itf1788_dir();

}  // namespace gesmi::test
