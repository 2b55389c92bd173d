// friction/vector_tanh.hpp against an independent tanh: glibc's long-double tanhl (64-bit
// mantissa, rounded to double only for the ulp's size) over |x| from 1e-300 to 1e3 log-uniform
// and both signs, within the header's 3 ulp, for the chosen width and every narrower one this
// CPU runs; the special values exactly; oddness; and the
// batch and the single value bit for bit at every position of arrays of 1 to 9 and 256 values,
// in place or not (the tail of a batch goes through a padded copy).
#include "friction/vector_tanh.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <random>
#include <span>
#include <stdexcept>
#include <vector>

#include "support/same_bits.hpp"

namespace tribo::friction {
namespace {

// |a - ref| in units of the last place of the double nearest ref.
double ulpsFrom(double a, long double ref) {
  const double r = std::fabs(static_cast<double>(ref));
  const double ulp = std::nextafter(r, std::numeric_limits<double>::infinity()) - r;
  return static_cast<double>(std::fabs(static_cast<long double>(a) - ref) / ulp);
}

std::vector<double> logUniformValues(std::size_t n, double lo_exp, double hi_exp, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> exponent(lo_exp, hi_exp);
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = (i % 2 ? -1.0 : 1.0) * std::pow(10.0, exponent(rng));
  return x;
}

// The widths this build and CPU run: the chosen one and every narrower one.
std::vector<int> widths() {
  std::vector<int> w;
  for (int width : {1, 2, 4})
    if (width <= tanhWidth()) w.push_back(width);
  return w;
}

TEST(VectorTanh, EveryWidthWithinThreeUlpOfALongDoubleTanhFromTinyToSaturated) {
  // Where friction laws ask (slip over v_eps: 1e-12 to 1e5) and beyond, both signs; 1001
  // values a batch, so that each width's tail is used too.
  for (int width : widths()) {
    for (const auto& [lo, hi] : {std::pair{-300.0, -12.0}, {-12.0, 0.0}, {0.0, 3.0}}) {
      const std::vector<double> x = logUniformValues(300300, lo, hi, 11);
      std::vector<double> y(x.size());
      for (std::size_t i = 0; i < x.size(); i += 1001)
        tanhEachOfWidth(width, std::span(x).subspan(i, 1001), std::span(y).subspan(i, 1001));
      double worst = 0.0, worst_x = 0.0;
      for (std::size_t i = 0; i < x.size(); ++i) {
        const double u = ulpsFrom(y[i], tanhl(static_cast<long double>(x[i])));
        if (u > worst) worst = u, worst_x = x[i];
      }
      EXPECT_LE(worst, 3.0) << "width " << width << " at x = " << worst_x << " (range 1e" << lo
                            << " to 1e" << hi << ")";
    }
  }
}

TEST(VectorTanh, AWidthThisCpuDoesNotRunIsRefused) {
  std::vector<double> x{0.5}, y(1);
  EXPECT_THROW(tanhEachOfWidth(3, x, y), std::invalid_argument);
  EXPECT_THROW(tanhEachOfWidth(2 * tanhWidth(), x, y), std::invalid_argument);
}

TEST(VectorTanh, SpecialValuesExactly) {
  const double inf = std::numeric_limits<double>::infinity();
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_TRUE(test::sameBits(tanhOf(0.0), 0.0));
  EXPECT_TRUE(test::sameBits(tanhOf(-0.0), -0.0));
  EXPECT_EQ(tanhOf(inf), 1.0);
  EXPECT_EQ(tanhOf(-inf), -1.0);
  EXPECT_EQ(tanhOf(1e300), 1.0);
  EXPECT_EQ(tanhOf(-1e300), -1.0);
  EXPECT_EQ(tanhOf(40.0), 1.0);  // 1 - tanh(40) = 2 exp(-80) ~ 4e-35, far below half an ulp of 1
  EXPECT_TRUE(std::isnan(tanhOf(std::numeric_limits<double>::quiet_NaN())));
  // tanh(x) = x - x^3/3 + ...: x itself below 1e-8 (x^2/3 under half an ulp).
  EXPECT_EQ(tanhOf(1e-10), 1e-10);
  EXPECT_EQ(tanhOf(-3e-200), -3e-200);
  EXPECT_EQ(tanhOf(std::numeric_limits<double>::min()), std::numeric_limits<double>::min());
  // A subnormal is itself or, on a thread that flushes subnormals to zero, zero.
  const double t = tanhOf(tiny);
  EXPECT_TRUE(t == tiny || t == 0.0) << t;
}

TEST(VectorTanh, EveryWidthOddBitForBit) {
  const std::vector<double> x = logUniformValues(100000, -20.0, 2.0, 5);
  std::vector<double> minus(x.size()), y(x.size()), y_minus(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) minus[i] = -x[i];
  for (int width : widths()) {
    tanhEachOfWidth(width, x, y);
    tanhEachOfWidth(width, minus, y_minus);
    for (std::size_t i = 0; i < x.size(); ++i)
      ASSERT_TRUE(test::sameBits(y_minus[i], -y[i])) << "width " << width << " x = " << x[i];
  }
}

TEST(VectorTanh, BatchAndSingleValueAgreeBitForBitAtEveryPosition) {
  const std::vector<double> pool = logUniformValues(256, -14.0, 1.5, 3);
  for (std::size_t n : {1, 2, 3, 4, 5, 6, 7, 8, 9, 256}) {
    for (std::size_t shift = 0; shift < 4 && shift + n <= pool.size(); ++shift) {
      const std::vector<double> x(pool.begin() + static_cast<std::ptrdiff_t>(shift),
                                  pool.begin() + static_cast<std::ptrdiff_t>(shift + n));
      std::vector<double> y(n), in_place = x;
      tanhEach(x, y);
      tanhEach(in_place, in_place);
      for (std::size_t i = 0; i < n; ++i) {
        ASSERT_TRUE(test::sameBits(y[i], tanhOf(x[i]))) << "n " << n << " position " << i;
        ASSERT_TRUE(test::sameBits(in_place[i], y[i])) << "n " << n << " position " << i;
      }
    }
  }
}

}  // namespace
}  // namespace tribo::friction
