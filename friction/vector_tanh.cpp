#include "friction/vector_tanh.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

#if defined(TRIBO_HAVE_LIBMVEC) && defined(__x86_64__) && defined(__GLIBC__)
#include <immintrin.h>
#define TRIBO_VECTOR_TANH 1
// glibc's vector variants of tanh (libmvec, glibc >= 2.35), in the x86-64 vector ABI's names:
// 'b' two doubles in an SSE register, 'd' four in an AVX2 register.
extern "C" __m128d _ZGVbN2v_tanh(__m128d);
extern "C" __attribute__((target("avx2"))) __m256d _ZGVdN4v_tanh(__m256d);
#endif

namespace tribo::friction {
namespace {

using TanhKernel = void (*)(const double*, double*, std::size_t);

void tanhOne(const double* x, double* y, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) y[i] = std::tanh(x[i]);
}

#ifdef TRIBO_VECTOR_TANH

// n values from x to y (which may be x); a partial group goes through a padded copy (zeros
// beside it), so every value goes through the same lane arithmetic.
void tanhTwo(const double* x, double* y, std::size_t n) {
  std::size_t i = 0;
  for (; i + 2 <= n; i += 2) _mm_storeu_pd(y + i, _ZGVbN2v_tanh(_mm_loadu_pd(x + i)));
  if (i < n) {
    alignas(16) double in[2] = {x[i], 0.0}, out[2];
    _mm_store_pd(out, _ZGVbN2v_tanh(_mm_load_pd(in)));
    y[i] = out[0];
  }
}

__attribute__((target("avx2"))) void tanhFour(const double* x, double* y, std::size_t n) {
  std::size_t i = 0;
  for (; i + 4 <= n; i += 4) _mm256_storeu_pd(y + i, _ZGVdN4v_tanh(_mm256_loadu_pd(x + i)));
  if (i < n) {
    alignas(32) double in[4] = {0.0, 0.0, 0.0, 0.0}, out[4];
    std::copy(x + i, x + n, in);
    _mm256_store_pd(out, _ZGVdN4v_tanh(_mm256_load_pd(in)));
    std::copy(out, out + (n - i), y + i);
  }
}

int chosenWidth() {
  static const int width = __builtin_cpu_supports("avx2") ? 4 : 2;
  return width;
}

#else

int chosenWidth() { return 1; }

#endif

TanhKernel kernelOfWidth(int width) {
  if (width > chosenWidth() || (width != 1 && width != 2 && width != 4))
    throw std::invalid_argument("tanh of width " + std::to_string(width) +
                                " is not run here (widest: " + std::to_string(chosenWidth()) + ")");
#ifdef TRIBO_VECTOR_TANH
  if (width == 4) return tanhFour;
  if (width == 2) return tanhTwo;
#endif
  return tanhOne;
}

TanhKernel chosenKernel() {
  static const TanhKernel kernel = kernelOfWidth(chosenWidth());
  return kernel;
}

}  // namespace

void tanhEach(std::span<const double> x, std::span<double> y) {
  chosenKernel()(x.data(), y.data(), std::min(x.size(), y.size()));
}

double tanhOf(double x) {
  double y;
  chosenKernel()(&x, &y, 1);
  return y;
}

int tanhWidth() { return chosenWidth(); }

void tanhEachOfWidth(int width, std::span<const double> x, std::span<double> y) {
  kernelOfWidth(width)(x.data(), y.data(), std::min(x.size(), y.size()));
}

}  // namespace tribo::friction
