// The affine displacement of a run of steps (solver/structured/affine_track.h) against an
// independent long double computation: a synthetic mission whose true world velocity is
// linear within each step (so the trapezoid is exact and the jerk bound may be zero),
// read through biases and noises placed at their bounds' corners. The true displacement
// must lie in value + coefficient . z + rest for the true biases z, at every sample.

#include "solver/structured/affine_track.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "solver/network/frame/frame_margins.h"
#include "solver/network/sensors/sensor_boxes.h"
#include "solver/structured/structured_errors.h"

namespace gesmi {
namespace {

struct Synthetic {
  Mission mission;
  std::vector<std::array<long double, 2>> displacement;  // true p_k - p_0, north and east
  std::array<double, kBiasTerms> bias{};
};

long double corner(std::mt19937_64& random, long double bound) { return (random() & 1u ? 0.999L : -0.999L) * bound; }

// A turning, pitching run read with the biases and noises at their corners.
Synthetic synthetic_run(std::uint64_t seed, double share, std::size_t samples) {
  std::mt19937_64 random(seed);
  Synthetic s;
  Mission& m = s.mission;
  m.model.heading = 0.05;  // a wide heading bound: the rotation's higher terms matter
  m.model.max_jerk = 0.0;  // the truth is linear within each step
  const StructuredErrors split = split_by_bias_share(m.model, share);
  for (std::size_t t = 0; t < kBiasTerms; ++t) s.bias[t] = static_cast<double>(corner(random, split.bias_bound[t]));
  std::array<long double, 2> at{0.0L, 0.0L}, previous_w{};
  for (std::size_t k = 0; k < samples; ++k) {
    const long double time = 0.1L * static_cast<long double>(k);
    const long double psi = 0.3L + 0.002L * time * time, theta = 0.05L * sinl(0.1L * time),
                      phi = 0.03L * cosl(0.2L * time);
    const std::array<long double, 3> v = {2.0L + 0.2L * sinl(0.05L * time), 0.1L * cosl(0.07L * time), 0.05L};
    // The true world velocity, Rz(psi) Ry(theta) Rx(phi) v.
    const long double y1 = cosl(phi) * v[1] - sinl(phi) * v[2], z1 = sinl(phi) * v[1] + cosl(phi) * v[2];
    const long double x2 = cosl(theta) * v[0] + sinl(theta) * z1;
    const std::array<long double, 2> w = {cosl(psi) * x2 - sinl(psi) * y1, sinl(psi) * x2 + cosl(psi) * y1};
    if (k > 0)
      for (std::size_t i = 0; i < 2; ++i) at[i] += 0.05L * (previous_w[i] + w[i]);
    s.displacement.push_back(at);
    previous_w = w;
    m.time.push_back(static_cast<double>(time));
    m.heading.push_back(static_cast<double>(psi + s.bias[kHeadingBias] + corner(random, split.noise.heading)));
    m.pitch.push_back(static_cast<double>(theta + corner(random, m.model.pitch)));
    m.roll.push_back(static_cast<double>(phi + corner(random, m.model.roll)));
    std::array<std::vector<double>*, 3> dvl = {&m.vx, &m.vy, &m.vz};
    for (std::size_t a = 0; a < 3; ++a) {
      const long double read_without_noise = v[a] * (1.0L + s.bias[kScaleBias + a]) + s.bias[kOffsetBias + a];
      const long double noise =
          (1.0L - share) * (m.model.dvl_relative * fabsl(read_without_noise) + m.model.dvl_absolute);
      dvl[a]->push_back(static_cast<double>(read_without_noise + corner(random, noise)));
    }
    m.depth.push_back(10.0);
    m.altitude.push_back(20.0);
  }
  return s;
}

TEST(AffineTrack, TheTrueDisplacementIsInsideTheFormAtTheTrueBiases) {
  for (const double share : {1.0, 0.7, 0.0})
    for (const std::uint64_t seed : {1u, 2u, 3u}) {
      SCOPED_TRACE("share " + std::to_string(share) + ", seed " + std::to_string(seed));
      const Synthetic s = synthetic_run(seed, share, 1501);
      const Mission& m = s.mission;
      const StructuredErrors split = split_by_bias_share(m.model, share);
      const FrameMargins frame = zone_frame(m);
      const StepRegimes submerged;
      const SensorBoxes noise(m, split.noise, frame), whole(m, m.model, frame, &submerged);
      StepSums sums(m, noise, whole);
      double widest_rest = 0.0;
      for (std::size_t k = 0; k + 1 < m.size(); ++k) {
        sums.add_step(k);
        const AffineDisplacement d = sums.form(split.bias_bound);
        for (std::size_t i = 0; i < 2; ++i) {
          long double affine = d.value[i];
          for (std::size_t t = 0; t < kBiasTerms; ++t)
            affine += static_cast<long double>(d.coefficient[i][t]) * s.bias[t];
          const long double miss = s.displacement[k + 1][i] - affine, slack = 1e-12L;
          ASSERT_GE(miss, static_cast<long double>(d.rest[i].lo()) - slack) << "step " << k << " axis " << i;
          ASSERT_LE(miss, static_cast<long double>(d.rest[i].hi()) + slack) << "step " << k << " axis " << i;
          widest_rest = std::max(widest_rest, d.rest[i].width());
        }
      }
      std::printf("share %.1f seed %d: widest rest %.3f m over 150 s\n", share, static_cast<int>(seed), widest_rest);
    }
}

}  // namespace
}  // namespace gesmi
