#include "solver/model/vector_sin_cos.h"

#include <immintrin.h>

// libmvec's entry points, named by the x86_64 vector function ABI: `b` two lanes of
// SSE2 (every x86_64 processor), `d` four lanes of AVX2; `N` unmasked, `v` a vector
// argument. glibc resolves each to its best variant for the processor at load.
extern "C" {
__m128d _ZGVbN2v_sin(__m128d);
__m128d _ZGVbN2v_cos(__m128d);
__attribute__((target("avx2"))) __m256d _ZGVdN4v_sin(__m256d);
__attribute__((target("avx2"))) __m256d _ZGVdN4v_cos(__m256d);
}

namespace gesmi {
namespace {

__attribute__((target("avx2"))) std::size_t four_at_a_time(const double* angle, std::size_t n, double* sine,
                                                          double* cosine) {
  std::size_t i = 0;
  for (; i + 4 <= n; i += 4) {
    const __m256d x = _mm256_loadu_pd(angle + i);
    _mm256_storeu_pd(sine + i, _ZGVdN4v_sin(x));
    _mm256_storeu_pd(cosine + i, _ZGVdN4v_cos(x));
  }
  return i;
}

std::size_t two_at_a_time(const double* angle, std::size_t from, std::size_t n, double* sine, double* cosine) {
  std::size_t i = from;
  for (; i + 2 <= n; i += 2) {
    const __m128d x = _mm_loadu_pd(angle + i);
    _mm_storeu_pd(sine + i, _ZGVbN2v_sin(x));
    _mm_storeu_pd(cosine + i, _ZGVbN2v_cos(x));
  }
  return i;
}

}  // namespace

void sin_cos_many(const double* angle, std::size_t n, double* sine, double* cosine) {
  static const bool avx2 = __builtin_cpu_supports("avx2");
  std::size_t done = avx2 ? four_at_a_time(angle, n, sine, cosine) : 0;
  done = two_at_a_time(angle, done, n, sine, cosine);
  if (done < n) {  // the last odd one through the same two-lane function (one code path)
    const double last[2] = {angle[done], 0.0};
    double s[2], c[2];
    two_at_a_time(last, 0, 2, s, c);
    sine[done] = s[0];
    cosine[done] = c[0];
  }
}

}  // namespace gesmi
