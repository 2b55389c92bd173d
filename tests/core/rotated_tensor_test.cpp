// A body tensor turned to the world on components (core/math.hpp rotatedTensor) against
// Eigen's `r * t * r.transpose()`, which it stands for: the same bits over random rotations and
// tensors (inertias from 1e-9 to 1e3 kg m^2 and their inverses, general matrices of either
// sign); and what turning a tensor must keep: a quarter turn about z swaps the x and y
// moments (to the rounding of cos(pi/2)), a turned tensor stays symmetric, and its trace and
// its Frobenius norm are the rotation's invariants. Eigen's order is that of this build's
// two-wide vectors (SSE2); a build with wider ones may order the sums otherwise, and the
// first test would say so.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "core/math.hpp"

namespace tribo {
namespace {

class RandomTensors {
 public:
  explicit RandomTensors(unsigned seed) : rng_(seed) {}
  double magnitude() {
    return std::pow(10.0, std::uniform_real_distribution<double>(-9.0, 3.0)(rng_));
  }
  Mat3 rotation() {
    std::normal_distribution<double> g;
    return Quat(g(rng_), g(rng_), g(rng_), g(rng_)).normalized().toRotationMatrix();
  }
  // A symmetric positive definite inertia: principal moments turned by a random rotation.
  Mat3 inertia() {
    const Mat3 axes = rotation();
    const Vec3 moments(magnitude(), magnitude(), magnitude());
    return axes * moments.asDiagonal() * axes.transpose();
  }
  Mat3 general() {
    Mat3 m;
    for (int i = 0; i < 9; ++i)
      m(i) = std::bernoulli_distribution(0.5)(rng_) ? magnitude() : -magnitude();
    return m;
  }

 private:
  std::mt19937 rng_;
};

// Eigen's product, evaluated into a matrix as the engine's code did.
Mat3 eigenProduct(const Mat3& r, const Mat3& t) { return r * t * r.transpose(); }

TEST(RotatedTensor, SameBitsAsEigensProduct) {
  RandomTensors random(20261130);
  int differing = 0;
  for (int n = 0; n < 20000; ++n) {
    const Mat3 r = random.rotation();
    const Mat3 t = n % 3 == 0   ? random.general()
                   : n % 3 == 1 ? random.inertia()
                                : Mat3(random.inertia().inverse());
    const Mat3 mine = rotatedTensor(r, t), eigen = eigenProduct(r, t);
    for (int i = 0; i < 9; ++i)
      if (std::memcmp(&mine(i), &eigen(i), sizeof(double)) != 0) ++differing;
  }
  EXPECT_EQ(differing, 0) << "coefficients not bit-identical to r * t * r^T";
}

TEST(RotatedTensor, QuarterTurnAboutZSwapsTheMoments) {
  const Mat3 r = Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ()).toRotationMatrix();
  const Mat3 t = Vec3(2.0, 5.0, 7.0).asDiagonal();
  const Mat3 w = rotatedTensor(r, t);
  // cos(pi/2) is 6e-17, not 0: the off-diagonal terms are of that order of the moments.
  EXPECT_NEAR(w(0, 0), 5.0, 1e-15);
  EXPECT_NEAR(w(1, 1), 2.0, 1e-15);
  EXPECT_EQ(w(2, 2), 7.0);
  EXPECT_NEAR(w(0, 1), 0.0, 1e-15);
  EXPECT_NEAR(w(1, 0), 0.0, 1e-15);
}

TEST(RotatedTensor, KeepsTheInvariants) {
  RandomTensors random(7);
  for (int n = 0; n < 2000; ++n) {
    const Mat3 r = random.rotation(), t = random.inertia();
    const Mat3 w = rotatedTensor(r, t);
    const double scale = t.norm();  // the largest moment, to within a factor sqrt(3)
    EXPECT_NEAR(w.trace(), t.trace(), 1e-14 * scale);
    EXPECT_NEAR(w.norm(), scale, 1e-14 * scale);
    EXPECT_NEAR((w - w.transpose()).norm(), 0.0, 1e-14 * scale);
  }
}

}  // namespace
}  // namespace tribo
