// tanh over arrays of doubles, several values an instruction, for the laws whose coefficient
// is a tanh of the slip speed (coulomb's tanh regularization, friction/coulomb_law.hpp):
//
//   tanhEach(x, y)   y[i] = tanh(x[i]) for every i (x and y may be the same array)
//   tanhOf(x)        the same function at one value: the same bits as tanhEach gives at x
//
// On x86-64 with glibc it is glibc's vector math library (libmvec, _ZGVdN4v_tanh: four values
// a call with AVX2, else _ZGVbN2v_tanh: two), chosen once a process from the CPU; elsewhere
// std::tanh. A lane's result does not depend on its neighbours or its position, so a batch of
// points and the points one by one agree bit for bit, on any thread count.
// Accuracy: at most 2.2 ulp from a long-double tanh, measured over 1e-12 <= |x| <= 300 (std::tanh
// of glibc: 2.1 ulp); tests/friction/vector_tanh_test.cpp holds it to 3 ulp and to the exact
// special values (+-0, +-1 at +-inf, NaN). The four- and two-value variants differ in the last
// bit on about 3 values in 10 000, so a run's bits may differ between CPUs with and without
// AVX2 (not between runs, paths or thread counts on one machine).
// Why: std::tanh was 110 instructions a contact point of the sphere pile's friction stage.
// Not here: any other function (stribeck's tanh is still std::tanh: its exp is a point's
// larger cost).
#pragma once

#include <span>

namespace tribo::friction {

void tanhEach(std::span<const double> x, std::span<double> y);
double tanhOf(double x);

// For tests: the values a call of the chosen variant (tanhWidth()) and of every narrower one
// this build and CPU run (tanhEachOfWidth: 4, 2, or 1 = std::tanh).
int tanhWidth();
void tanhEachOfWidth(int width, std::span<const double> x, std::span<double> y);

}  // namespace tribo::friction
