// The box/half-space corners of the 400-box grid (resting, tilts of 1e-6, 32.7 um deep) as the
// detector forms them once an evaluation: boxHalfSpaceContacts (the column products formed
// once a box, contact/primitive_contacts.cpp) against the plain loop it replaced (each corner
// `box_pose * s`, its depth, a branch). Each iteration runs both over the same boxes,
// alternately, so a change of the machine's load hits both; counters: each one's time a box
// [ns] and their ratio (speedup, > 1: boxHalfSpaceContacts faster).
// Names: BM_BoxHalfSpaceCorners.
#include <benchmark/benchmark.h>

#include <chrono>
#include <random>
#include <vector>

#include "contact/primitive_contacts.hpp"

namespace {

using tribo::contact::ContactPoint;

void plainCorners(const Eigen::Isometry3d& box, const Eigen::Vector3d& half,
                  const Eigen::Isometry3d& plane, int pair, std::vector<ContactPoint>& out) {
  const Eigen::Vector3d n = plane.linear().col(2);
  const double offset = n.dot(plane.translation());
  for (int k = 0; k < 8; ++k) {
    const Eigen::Vector3d s((k & 1) ? half.x() : -half.x(), (k & 2) ? half.y() : -half.y(),
                            (k & 4) ? half.z() : -half.z());
    const Eigen::Vector3d corner = box * s;
    const double depth = offset - n.dot(corner);
    if (depth <= 0.0) continue;
    ContactPoint& cp = out.emplace_back();
    cp.pair = pair;
    cp.feature = k;
    cp.position = corner + 0.5 * depth * n;
    cp.normal = n;
    cp.depth = depth;
  }
}

void BM_BoxHalfSpaceCorners(benchmark::State& st) {
  constexpr int kBoxes = 400;
  const Eigen::Vector3d half(0.1, 0.1, 0.1);
  const Eigen::Isometry3d plane = Eigen::Isometry3d::Identity();
  std::vector<Eigen::Isometry3d> boxes(kBoxes, Eigen::Isometry3d::Identity());
  std::mt19937 rng(400);
  std::normal_distribution<double> g;
  for (int b = 0; b < kBoxes; ++b) {
    boxes[b].linear() =
        Eigen::Quaterniond(1.0, 1e-6 * g(rng), 1e-6 * g(rng), 1e-6 * g(rng)).normalized().matrix();
    boxes[b].translation() = Eigen::Vector3d(0.25 * (b / 20), 0.25 * (b % 20), 0.1 - 32.7e-6);
  }
  std::vector<ContactPoint> out;
  out.reserve(8 * kBoxes);
  double seconds[2] = {0, 0};
  long turns = 0;
  std::size_t points = 0;
  for (auto _ : st) {
    for (int k = 0; k < 2; ++k) {
      out.clear();
      const auto t0 = std::chrono::steady_clock::now();
      for (int b = 0; b < kBoxes; ++b) {
        if (k == 0)
          plainCorners(boxes[b], half, plane, b, out);
        else
          tribo::contact::boxHalfSpaceContacts(boxes[b], half, plane, b, out);
      }
      benchmark::DoNotOptimize(out.data());
      benchmark::ClobberMemory();
      seconds[k] += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    points = out.size();
    ++turns;
  }
  const double boxes_run = static_cast<double>(turns) * kBoxes;
  st.counters["plain_ns_per_box"] = 1e9 * seconds[0] / boxes_run;
  st.counters["columns_ns_per_box"] = 1e9 * seconds[1] / boxes_run;
  st.counters["speedup"] = seconds[0] / seconds[1];
  st.counters["points"] = static_cast<double>(points);
}

}  // namespace

BENCHMARK(BM_BoxHalfSpaceCorners)->Unit(benchmark::kMicrosecond);
