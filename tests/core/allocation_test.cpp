// The warm step does not allocate (docs: DESIGN.md, "Workspace"). Every shipped scene
// (scenes/*.yaml and scenes/experiments/*.yaml, listed when the test runs, so a new scene
// is covered without editing this file) is loaded, stepped 20 times to let its buffers grow
// to their working size, then stepped 50 times more while this binary's replaced allocation
// functions count:
//   - global operator new / new[], all variants (plain, nothrow, aligned, aligned nothrow);
//   - in builds without AddressSanitizer also malloc, calloc, realloc and the aligned
//     allocators (glibc's __libc_* underneath), which catches Eigen's dynamic matrices and
//     C libraries; under ASan (which owns malloc) only operator new is counted.
// Counting is thread-local (only this test's thread) and pauses while FCL runs: the
// collision detector brackets every call into FCL with a test hook
// (CollisionDetector::setFclScopeHook), so FCL's own allocations (libccd's GJK/EPA, its
// box/box manifold) are told apart precisely and reported, not failed, while Tribo code it
// calls back (the broadphase pair callback) is counted.
// Integrators (checked on three scenes): semi_implicit_euler, rk4 and dopri5 (ARKODE) must
// not allocate at all. bdf is excluded from the malloc count only, by name: CVODE's
// difference-quotient Jacobian (cvLsDenseDQJac) calls N_VCloneEmpty at every Jacobian setup,
// i.e. malloc inside SUNDIALS every few steps (found with backtraces: all 249 in the three
// scenes' counted steps came from there); operator new, which SUNDIALS (C) never calls,
// must still stay at zero.
#include <gtest/gtest.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include "contact/collision_detector.hpp"
#include "core/simulator.hpp"
#include "io/scene_loader.hpp"

#if defined(__SANITIZE_ADDRESS__)
#define TRIBO_COUNT_MALLOC 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define TRIBO_COUNT_MALLOC 0
#endif
#endif
#ifndef TRIBO_COUNT_MALLOC
#define TRIBO_COUNT_MALLOC 1
#endif

namespace {

struct Counts {
  long news = 0;     // operator new calls outside FCL
  long mallocs = 0;  // malloc-family calls outside FCL (0 when not counted)
  long in_fcl = 0;   // either, inside FCL
};

thread_local bool counting = false;
thread_local int fcl_depth = 0;
thread_local Counts counts;

void noteNew() {
  if (!counting) return;
  if (fcl_depth > 0)
    ++counts.in_fcl;
  else
    ++counts.news;
}

[[maybe_unused]] void noteMalloc() {
  if (!counting) return;
  if (fcl_depth > 0)
    ++counts.in_fcl;
  else
    ++counts.mallocs;
}

void fclHook(bool inside) { fcl_depth += inside ? 1 : -1; }

}  // namespace

#if TRIBO_COUNT_MALLOC
extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void* __libc_memalign(std::size_t, std::size_t);

void* malloc(std::size_t n) {
  noteMalloc();
  return __libc_malloc(n);
}
void* calloc(std::size_t count, std::size_t n) {
  noteMalloc();
  return __libc_calloc(count, n);
}
void* realloc(void* p, std::size_t n) {
  noteMalloc();
  return __libc_realloc(p, n);
}
void* aligned_alloc(std::size_t alignment, std::size_t n) {
  noteMalloc();
  return __libc_memalign(alignment, n);
}
void* memalign(std::size_t alignment, std::size_t n) {
  noteMalloc();
  return __libc_memalign(alignment, n);
}
int posix_memalign(void** out, std::size_t alignment, std::size_t n) {
  noteMalloc();
  void* p = __libc_memalign(alignment, n);
  if (p == nullptr) return ENOMEM;
  *out = p;
  return 0;
}
}

namespace {
void* rawAlloc(std::size_t n) { return __libc_malloc(n == 0 ? 1 : n); }
void* rawAligned(std::size_t alignment, std::size_t n) {
  return __libc_memalign(alignment, n == 0 ? 1 : n);
}
}  // namespace
#else
namespace {
void* rawAlloc(std::size_t n) { return std::malloc(n == 0 ? 1 : n); }
void* rawAligned(std::size_t alignment, std::size_t n) {
  const std::size_t rounded = (std::max<std::size_t>(n, 1) + alignment - 1) / alignment * alignment;
  return std::aligned_alloc(alignment, rounded);
}
}  // namespace
#endif

// The replaced global allocation functions: count, then allocate with the C allocator (the
// matching deletes free with std::free, which takes glibc's memory from both).
// GCC sees std::free applied to what operator new returned once it inlines them and warns
// (-Wmismatched-new-delete); here the pairing is by design, every new above is malloc.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
void* operator new(std::size_t n) {
  noteNew();
  if (void* p = rawAlloc(n)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) { return operator new(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  noteNew();
  return rawAlloc(n);
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
  noteNew();
  return rawAlloc(n);
}
void* operator new(std::size_t n, std::align_val_t al) {
  noteNew();
  if (void* p = rawAligned(static_cast<std::size_t>(al), n)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n, std::align_val_t al) { return operator new(n, al); }
void* operator new(std::size_t n, std::align_val_t al, const std::nothrow_t&) noexcept {
  noteNew();
  return rawAligned(static_cast<std::size_t>(al), n);
}
void* operator new[](std::size_t n, std::align_val_t al, const std::nothrow_t&) noexcept {
  noteNew();
  return rawAligned(static_cast<std::size_t>(al), n);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }

namespace tribo {
namespace {

constexpr int kWarmSteps = 20;
constexpr int kCountedSteps = 50;

// Allocations made by `f` on this thread.
template <typename F>
Counts countDuring(F&& f) {
  counts = {};
  counting = true;
  f();
  counting = false;
  return counts;
}

class Allocation : public ::testing::Test {
 protected:
  void SetUp() override { contact::CollisionDetector::setFclScopeHook(&fclHook); }
  void TearDown() override { contact::CollisionDetector::setFclScopeHook(nullptr); }
};

std::vector<std::filesystem::path> shippedScenes() {
  std::vector<std::filesystem::path> files;
  for (const char* dir : {"/scenes", "/scenes/experiments"})
    for (const auto& e : std::filesystem::directory_iterator(std::string(TRIBO_SOURCE_DIR) + dir))
      if (e.is_regular_file() && e.path().extension() == ".yaml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

// Steps `model` kWarmSteps times, then counts the allocations of kCountedSteps more; `what`
// names the run in failures.
Counts warmStepAllocations(std::shared_ptr<const Model> model, const std::string& what) {
  Simulator sim(std::move(model));
  for (int i = 0; i < kWarmSteps; ++i) {
    const StepStatus s = sim.step();
    if (!s.ok) ADD_FAILURE() << what << ": warm-up step failed: " << s.message;
  }
  bool ok = true;
  const Counts c = countDuring([&] {
    for (int i = 0; i < kCountedSteps && ok; ++i) ok = sim.step().ok;
  });
  EXPECT_TRUE(ok) << what << ": a counted step failed";
  return c;
}

// `sundials_jacobian_mallocs`: malloc-family calls are CVODE's own (see the header).
void expectNone(const Counts& c, const std::string& what, bool sundials_jacobian_mallocs = false) {
  EXPECT_EQ(c.news, 0) << what << ": operator new called " << c.news << " times in "
                       << kCountedSteps << " warm steps";
  if (sundials_jacobian_mallocs) {
    if (c.mallocs > 0)
      std::cout << "[ note     ] " << what << ": " << c.mallocs
                << " mallocs inside CVODE's difference-quotient Jacobian (excluded)\n";
  } else {
    EXPECT_EQ(c.mallocs, 0) << what << ": malloc-family called " << c.mallocs << " times in "
                            << kCountedSteps << " warm steps";
  }
  if (c.in_fcl > 0)
    std::cout << "[ note     ] " << what << ": " << c.in_fcl
              << " allocations inside FCL (not Tribo's; excluded)\n";
}

TEST_F(Allocation, TheCounterSeesNewAndMallocAndPausesInsideFcl) {
  // Direct calls: a new-expression paired with its delete may be elided by the compiler.
  Counts c = countDuring([] { ::operator delete(::operator new(8)); });
  EXPECT_EQ(c.news, 1);
  c = countDuring([] {
    ::operator delete[](::operator new[](24, std::align_val_t{64}), std::align_val_t{64});
  });
  EXPECT_EQ(c.news, 1);
  c = countDuring([] { ::operator delete(::operator new(8, std::nothrow), std::nothrow); });
  EXPECT_EQ(c.news, 1);
  c = countDuring([] {
    std::vector<int> v(100);
    fclHook(true);
    std::vector<int> w(100);
    fclHook(false);
  });
  EXPECT_EQ(c.news, 1);
  EXPECT_EQ(c.in_fcl, 1);
#if TRIBO_COUNT_MALLOC
  c = countDuring([] { std::free(std::malloc(16)); });
  EXPECT_EQ(c.mallocs, 1);
#endif
}

TEST_F(Allocation, WarmStepsOfEveryShippedSceneDoNotAllocate) {
  const auto files = shippedScenes();
  ASSERT_FALSE(files.empty());
  bool robots = false;
  for (const auto& file : files) {
    const std::string name = file.filename().string();
    robots = robots || name == "urdf_robots.yaml";
    const io::Scene scene = io::loadScene(file.string());
    expectNone(warmStepAllocations(scene.model, name), name);
  }
  EXPECT_TRUE(robots) << "scenes/urdf_robots.yaml (URDF robots) not found";
}

// Every integrator, on scenes with a belt's moving surface, several boxes on a belt, and
// URDF robots with joints and a sliding block.
TEST_F(Allocation, WarmStepsOfEveryIntegratorDoNotAllocate) {
  for (const char* file : {"belt.yaml", "boxes_on_belt.yaml", "urdf_robots.yaml"}) {
    const io::Scene scene = io::loadScene(std::string(TRIBO_SOURCE_DIR) + "/scenes/" + file);
    for (IntegratorType type : {IntegratorType::kSemiImplicitEuler, IntegratorType::kRk4,
                                IntegratorType::kDopri5, IntegratorType::kBdf}) {
      auto model = std::make_shared<Model>(*scene.model);
      model->options.integrator = type;
      const std::string what = std::string(file) + " with " + integratorName(type);
      expectNone(warmStepAllocations(model, what), what, type == IntegratorType::kBdf);
    }
  }
}

// Both factorizations of J M^-1 J^T (core/multiplier_matrix.hpp), on mechanisms.
TEST_F(Allocation, WarmStepsOfDenseAndSparseConstraintSolvesDoNotAllocate) {
  for (const char* file : {"andrews_squeezer.yaml", "slider_crank.yaml", "urdf_robots.yaml",
                           "belt_joint_friction.yaml"}) {
    const io::Scene scene = io::loadScene(std::string(TRIBO_SOURCE_DIR) + "/scenes/" + file);
    for (ConstraintSolverKind kind :
         {ConstraintSolverKind::kDense, ConstraintSolverKind::kSparse}) {
      auto model = std::make_shared<Model>(*scene.model);
      model->options.constraints.solver = kind;
      const std::string what =
          std::string(file) + (kind == ConstraintSolverKind::kDense ? " dense" : " sparse");
      expectNone(warmStepAllocations(model, what), what);
    }
  }
}

}  // namespace
}  // namespace tribo
