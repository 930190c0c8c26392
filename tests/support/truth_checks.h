#pragma once
// Checks of enclosures against a simulated mission's truth, shared by the tests.

#include <gtest/gtest.h>

#include "solver/mission/mission.h"
#include "solver/network/tube_domains.h"

namespace gesmi::test {

/// Every true position inside the tube and every true mine inside its box; the
/// failure names the first samples and mines outside.
::testing::AssertionResult truth_inside(const Mission& mission, const TubeDomains& domains);

}  // namespace gesmi::test
