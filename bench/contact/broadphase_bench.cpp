// The broadphase alone, on the same world boxes in the same process: Tribo's hashed grid
// (contact/broadphase.hpp) at three cell scales against FCL's dynamic AABB tree (the
// broadphase Tribo used before; update and collide each call, as a step does). Scenes:
// resting box grids of side x side (0.2 m boxes at a 0.25 m pitch, as scenes/box_grid20.yaml)
// and a loose pile of spheres (radius 5-15 mm, at a 30 % volume fraction of their boxes), each
// resting (boxes creep by 0.1 um a call: the grid keeps its buckets) and moving (by a tenth of
// a box a call: the grid rebuilds them); the grid at cell scales 1, 2 and 0.5 (_cell2,
// _cell0_5); BM_BroadphaseMovesOnly is what the moves alone cost (subtract it). Counters:
// pairs per call and seconds per box.
// Names: BM_Broadphase/<scene>_<motion>[_cell<scale>]/<side or count>,
// BM_BroadphaseFcl/<scene>_<motion>/<side or count>.
#include <benchmark/benchmark.h>
#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/shape/box.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "contact/broadphase.hpp"

namespace {

using tribo::contact::Aabb;

std::vector<Aabb> boxGrid(int side) {
  std::vector<Aabb> boxes;
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      Aabb b;
      b.lo = Eigen::Vector3d(0.25 * i - 0.087, 0.25 * j - 0.113, -1e-4);  // at rest, 0.1 mm deep
      b.hi = b.lo + Eigen::Vector3d::Constant(0.2);
      boxes.push_back(b);
    }
  return boxes;
}

std::vector<Aabb> spherePile(int n) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> r(0.005, 0.015);
  // A cube holding the spheres' boxes (mean volume about (2 cm)^3) at a 30 % volume fraction.
  const double side = std::cbrt(n * 8e-6 / 0.3);
  std::uniform_real_distribution<double> at(0.0, side);
  std::vector<Aabb> boxes;
  for (int k = 0; k < n; ++k) {
    const double radius = r(rng);
    const Eigen::Vector3d c(at(rng), at(rng), at(rng));
    boxes.push_back({c - Eigen::Vector3d::Constant(radius), c + Eigen::Vector3d::Constant(radius)});
  }
  return boxes;
}

std::vector<Aabb> sceneBoxes(int kind, int size) {
  return kind == 0 ? boxGrid(size) : spherePile(size);
}

// Resting: every box moves by up to 0.1 um a call (a resting scene's creep). Moving: by up
// to a tenth of a box (2 cm on the grid, 1-3 mm in the pile), so boxes change cells every
// call and the grid rebuilds its buckets.
void move(std::vector<Aabb>& boxes, std::mt19937& rng, bool moving) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (Aabb& b : boxes) {
    const double reach = moving ? 0.1 * (b.hi - b.lo).maxCoeff() : 1e-7;
    const Eigen::Vector3d m = reach * Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
    b.lo += m;
    b.hi += m;
  }
}

// The boxes' moves alone: what every other case spends before its broadphase.
void BM_BroadphaseMovesOnly(benchmark::State& st, int kind, bool moving) {
  std::vector<Aabb> boxes = sceneBoxes(kind, static_cast<int>(st.range(0)));
  std::mt19937 rng(2);
  for (auto _ : st) {
    move(boxes, rng, moving);
    benchmark::DoNotOptimize(boxes.data());
  }
  st.counters["per_box"] = benchmark::Counter(
      static_cast<double>(boxes.size()),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_Broadphase(benchmark::State& st, int kind, bool moving, double cell_scale) {
  std::vector<Aabb> boxes = sceneBoxes(kind, static_cast<int>(st.range(0)));
  std::vector<int> members(boxes.size());
  for (std::size_t g = 0; g < members.size(); ++g) members[g] = static_cast<int>(g);
  tribo::contact::GridBroadphase grid(cell_scale);
  std::vector<std::pair<int, int>> pairs;
  std::mt19937 rng(2);
  for (auto _ : st) {
    move(boxes, rng, moving);
    grid.overlappingPairs(boxes, members, pairs);
    benchmark::DoNotOptimize(pairs.data());
  }
  st.counters["pairs"] = static_cast<double>(pairs.size());
  st.counters["per_box"] = benchmark::Counter(
      static_cast<double>(boxes.size()),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_BroadphaseFcl(benchmark::State& st, int kind, bool moving) {
  std::vector<Aabb> boxes = sceneBoxes(kind, static_cast<int>(st.range(0)));
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects;
  std::vector<fcl::CollisionObjectd*> raw;
  for (const Aabb& b : boxes) {
    objects.push_back(
        std::make_unique<fcl::CollisionObjectd>(std::make_shared<fcl::Boxd>(b.hi - b.lo)));
    raw.push_back(objects.back().get());
  }
  fcl::DynamicAABBTreeCollisionManagerd manager;
  manager.registerObjects(raw);
  manager.setup();
  std::mt19937 rng(2);
  long pairs = 0;
  for (auto _ : st) {
    move(boxes, rng, moving);
    for (std::size_t g = 0; g < boxes.size(); ++g) {
      Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
      t.translation() = 0.5 * (boxes[g].lo + boxes[g].hi);
      objects[g]->setTransform(t);
      objects[g]->computeAABB();
    }
    pairs = 0;
    manager.update();
    manager.collide(&pairs, [](fcl::CollisionObjectd*, fcl::CollisionObjectd*, void* d) {
      ++*static_cast<long*>(d);
      return false;
    });
  }
  st.counters["pairs"] = static_cast<double>(pairs);
  st.counters["per_box"] = benchmark::Counter(
      static_cast<double>(boxes.size()),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

BENCHMARK_CAPTURE(BM_BroadphaseMovesOnly, grid_resting, 0, false)
    ->Arg(20)
    ->Arg(70)
    ->Arg(142)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_BroadphaseMovesOnly, pile_moving, 1, true)
    ->Arg(200)
    ->Arg(4000)
    ->Arg(32000)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Broadphase, grid_resting, 0, false, 1.0)
    ->Arg(20)
    ->Arg(70)
    ->Arg(142)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Broadphase, grid_resting_cell2, 0, false, 2.0)
    ->Arg(20)
    ->Arg(70)
    ->Arg(142)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Broadphase, grid_resting_cell0_5, 0, false, 0.5)
    ->Arg(20)
    ->Arg(70)
    ->Arg(142)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_BroadphaseFcl, grid_resting, 0, false)
    ->Arg(20)
    ->Arg(70)
    ->Arg(142)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Broadphase, grid_moving, 0, true, 1.0)
    ->Arg(20)
    ->Arg(70)
    ->Arg(142)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Broadphase, grid_moving_cell2, 0, true, 2.0)
    ->Arg(20)
    ->Arg(70)
    ->Arg(142)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Broadphase, grid_moving_cell0_5, 0, true, 0.5)
    ->Arg(20)
    ->Arg(70)
    ->Arg(142)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_BroadphaseFcl, grid_moving, 0, true)
    ->Arg(20)
    ->Arg(70)
    ->Arg(142)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Broadphase, pile_resting, 1, false, 1.0)
    ->Arg(200)
    ->Arg(4000)
    ->Arg(32000)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Broadphase, pile_resting_cell2, 1, false, 2.0)
    ->Arg(200)
    ->Arg(4000)
    ->Arg(32000)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Broadphase, pile_resting_cell0_5, 1, false, 0.5)
    ->Arg(200)
    ->Arg(4000)
    ->Arg(32000)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_BroadphaseFcl, pile_resting, 1, false)
    ->Arg(200)
    ->Arg(4000)
    ->Arg(32000)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Broadphase, pile_moving, 1, true, 1.0)
    ->Arg(200)
    ->Arg(4000)
    ->Arg(32000)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Broadphase, pile_moving_cell2, 1, true, 2.0)
    ->Arg(200)
    ->Arg(4000)
    ->Arg(32000)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Broadphase, pile_moving_cell0_5, 1, true, 0.5)
    ->Arg(200)
    ->Arg(4000)
    ->Arg(32000)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_BroadphaseFcl, pile_moving, 1, true)
    ->Arg(200)
    ->Arg(4000)
    ->Arg(32000)
    ->Unit(benchmark::kMicrosecond);

}  // namespace
