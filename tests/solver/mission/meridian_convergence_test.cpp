// MeridianConvergence::within (solver/mission/meridian_convergence.h), which bounds
// tan(latitude + a) by the addition formula instead of a tangent per distance, is never
// below meridian_convergence_within(), the bound the solve took before (a tangent per
// distance, in doubles), and is within rounding of that bound's formula, distance /
// (0.99 R) times tan of the largest latitude within it times 1.01, computed here in long
// double with libm's tanl (64-bit significand): not below it by more than 1e-13 (the
// tangent of the capped latitude, near 100, moves 1e4 times its argument's rounding), not
// above it by more than 1e-11 relative. Latitudes from the equator to 89.9°
// (both signs), distances from 0 to 200 km (across the 12.6 km where the formula stops),
// and those that put the largest latitude at and around its cap; and it is
// the same as meridian_convergence_within() where it falls back to it. Without the 2^-40
// for the roundings, 31,613 samples come out below the bound before; without the a^4/3
// of the series, one: the a^5 term matters only near 12.6 km.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "solver/mission/meridian_convergence.h"

namespace gesmi {
namespace {

long double exact_bound(double origin_latitude, double distance) {
  const long double angle = static_cast<long double>(distance) / (0.99L * kWgs84SemiMajorAxis);
  const long double degree = std::numbers::pi_v<long double> / 180.0L;
  const long double cap = std::numbers::pi_v<long double> / 2.0L - 0.01L;
  const long double latitude = std::min(std::fabs(static_cast<long double>(origin_latitude)) * degree + angle, cap);
  return angle * std::tan(latitude) * 1.01L;
}

struct Sample {
  double latitude, distance;
};

std::vector<Sample> samples() {
  std::mt19937_64 rng(0x6d6572696469616eULL);  // "meridian"
  std::uniform_real_distribution<double> latitude(-89.9, 89.9), unit(0.0, 1.0);
  std::vector<Sample> s;
  for (int i = 0; i < 200000; ++i) {
    const double d = i % 4 == 0 ? unit(rng) * 200e3 : std::pow(10.0, -2.0 + 7.3 * unit(rng));  // to 200 km
    s.push_back({latitude(rng), std::min(d, 200e3)});
  }
  // The largest latitude at, just below and just above its cap (89.427°).
  const double cap_degrees = (std::numbers::pi / 2 - 0.01) * 180.0 / std::numbers::pi;
  for (int i = 0; i < 20000; ++i) {
    const double d = unit(rng) * 12.6e3;
    const double reach = d / (0.99 * kWgs84SemiMajorAxis) * 180.0 / std::numbers::pi;
    s.push_back({cap_degrees - reach + (unit(rng) - 0.5) * 1e-6, d});
  }
  for (const double d : {0.0, 1e-300, 1.0, 12.7e3, 12.75e3, 12.8e3, 1e5})
    for (const double lat : {0.0, -0.0, 48.0, -48.0, 89.0, 89.4, 89.5})
      s.push_back({lat, d});
  return s;
}

TEST(MeridianConvergence, NeverBelowTheBoundItStandsFor) {
  int below = 0, below_formula = 0, looser = 0, checked = 0;
  for (const Sample& s : samples()) {
    const MeridianConvergence convergence(s.latitude);
    const long double exact = exact_bound(s.latitude, s.distance);
    const double got = convergence.within(s.distance);
    const double before = meridian_convergence_within(s.latitude, s.distance);
    ++checked;
    if (got < before && below++ < 5)
      ADD_FAILURE() << "latitude " << s.latitude << " distance " << s.distance << ": " << got << " below "
                    << before << " (meridian_convergence_within)";
    // (an underflow to the smallest subnormal, for a distance of 1e-300 m, is above the
    // exact 2.5e-614: the double's 0 would not be)
    if (got < exact * (1.0L - 1e-13L) && !(got > 0.0 && exact < 0x1p-1074L) && below_formula++ < 5)
      ADD_FAILURE() << "latitude " << s.latitude << " distance " << s.distance << ": " << got << " below "
                    << static_cast<double>(exact) << " (the formula in long double)";
    if (got > exact * (1.0L + 1e-11L) && got > std::numeric_limits<double>::denorm_min() && looser++ < 5)
      ADD_FAILURE() << "latitude " << s.latitude << " distance " << s.distance << ": " << static_cast<double>(got)
                    << " more than 1e-11 above " << static_cast<double>(exact);
  }
  EXPECT_EQ(below, 0);
  EXPECT_EQ(below_formula, 0);
  EXPECT_EQ(looser, 0);
  EXPECT_GT(checked, 220000);
}

TEST(MeridianConvergence, FarDistancesAndTheCapAreTheGeneralBound) {
  for (const double lat : {0.0, 48.0, -70.0, 89.5})
    for (const double d : {12.8e3, 1e5, 1e6, std::numeric_limits<double>::infinity()}) {
      const MeridianConvergence convergence(lat);
      EXPECT_EQ(convergence.within(d), meridian_convergence_within(lat, d)) << lat << " " << d;
    }
  EXPECT_TRUE(std::isnan(MeridianConvergence(48.0).within(std::numeric_limits<double>::quiet_NaN())));
  // At the cap the general bound holds the tangent of the largest latitude.
  EXPECT_EQ(MeridianConvergence(89.9).within(10.0), meridian_convergence_within(89.9, 10.0));
}

}  // namespace
}  // namespace gesmi
