#pragma once
// Sines and cosines of many angles at once, from glibc's vector math library (libmvec):
// four angles a call where the processor has AVX2, two otherwise. The sensor kernel
// takes one sine and one cosine of each of the three angle readings of every sample;
// glibc's scalar sin and cos were 1.9 ms of a cold solve's 180,000 pairs here, libmvec's
// 0.3 ms (docs/performance.md, "Sines and cosines from libmvec").
//
// libmvec's functions are not those of libm: glibc states that they "were tested (via
// reasonable random sampling) to pass 4-ulp maximum relative error criterion on their
// domains in round-to-nearest computation mode" (sourceware.org/glibc/wiki/libmvec).
// Callers widen each value y by kVectorLibmRelative |y| + kVectorLibmAbsolute: 64 ulp,
// sixteen times that criterion, because it was found by sampling, not proven.
// tests/oracle/vector_sin_cos_oracle_test.cpp checks the margin against MPFR.

#include <cstddef>

namespace gesmi {

/// |y - sin x| and |y - cos x| of a result y of sin_cos_many are at most
/// kVectorLibmRelative |y| + kVectorLibmAbsolute (for |x| below kVectorLibmLargest).
inline constexpr double kVectorLibmRelative = 0x1p-46;
inline constexpr double kVectorLibmAbsolute = 0x1p-1060;
/// The angles (rad) the margin is checked for: far beyond any angle reading.
inline constexpr double kVectorLibmLargest = 1e6;

/// sine[i] = sin(angle[i]) and cosine[i] = cos(angle[i]) for i < n, in the caller's
/// rounding mode, which must be round-to-nearest (libmvec's tested mode).
void sin_cos_many(const double* angle, std::size_t n, double* sine, double* cosine);

}  // namespace gesmi
