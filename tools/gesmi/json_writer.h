#pragma once
// Minimal JSON text output for the commands' --json and --stats modes: numbers
// with 17 significant digits (round-trip exact), infinite bounds as "inf"/"-inf".

#include <string>
#include <string_view>

#include "solver/interval/interval.h"

namespace gesmi::cli {

std::string json_number(double x);
std::string json_string(std::string_view s);
/// [lo, hi] pair; an empty interval is written as null.
std::string json_interval(const Interval& x);

}  // namespace gesmi::cli
