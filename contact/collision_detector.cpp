#include "contact/collision_detector.hpp"

#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/capsule.h>
#include <fcl/geometry/shape/cone.h>
#include <fcl/geometry/shape/convex.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/halfspace.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/collision.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

#include "contact/parallel_range.hpp"
#include "contact/polyhedron_contacts.hpp"

namespace tribo::contact {

namespace {

enum class PairKind {
  kHalfSpaceBox,    // the hot belt pair, straight to its corner manifold
  kHalfSpaceShape,  // A half-space, B anything: closed form
  kShapeHalfSpace,  // the same, normal flipped
  kSphereSphere,
  kBoxSphere,
  kSphereBox,
  kPolyhedra,  // FCL's EPA point grown into a face manifold (polyhedron_contacts.hpp)
  kFcl
};

std::shared_ptr<fcl::CollisionGeometryd> makeFclGeometry(const Shape& shape) {
  switch (shape.type) {
    case ShapeType::kBox:
      return std::make_shared<fcl::Boxd>(2.0 * shape.half_extents);
    case ShapeType::kSphere:
      return std::make_shared<fcl::Sphered>(shape.radius);
    case ShapeType::kCylinder:
      return std::make_shared<fcl::Cylinderd>(shape.radius, 2.0 * shape.half_length);
    case ShapeType::kCapsule:
      return std::make_shared<fcl::Capsuled>(shape.radius, 2.0 * shape.half_length);
    case ShapeType::kCone:
      return std::make_shared<fcl::Coned>(shape.radius, 2.0 * shape.half_length);
    case ShapeType::kHalfSpace:
      return std::make_shared<fcl::Halfspaced>(Eigen::Vector3d::UnitZ(), 0.0);
    case ShapeType::kConvexMesh: {
      auto vertices = std::make_shared<std::vector<Eigen::Vector3d>>(shape.mesh->vertices);
      auto faces = std::make_shared<std::vector<int>>();
      for (const auto& t : shape.mesh->triangles)
        faces->insert(faces->end(), {3, t[0], t[1], t[2]});
      return std::make_shared<fcl::Convexd>(vertices,
                                            static_cast<int>(shape.mesh->triangles.size()), faces);
    }
    case ShapeType::kTriangleMesh: {
      auto model = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
      std::vector<fcl::Triangle> triangles;
      for (const auto& t : shape.mesh->triangles)
        triangles.emplace_back(static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[1]),
                               static_cast<std::size_t>(t[2]));
      model->beginModel();
      model->addSubModel(shape.mesh->vertices, triangles);
      model->endModel();
      model->computeLocalAABB();
      return model;
    }
  }
  throw std::invalid_argument("unsupported shape");
}

// FCL's own world AABB of a rotated object is the bounding sphere's box, which makes
// resting neighbours overlap; this one is the tight box from the shape's support function
// (for meshes with many vertices FCL's is kept: the support costs a pass over them).
class TrackedObject : public fcl::CollisionObjectd {
 public:
  using fcl::CollisionObjectd::CollisionObjectd;
  void updateAabb(const Shape& shape, const Eigen::Isometry3d& pose) {
    if (shape.mesh && shape.mesh->vertices.size() > 64) {
      computeAABB();
      return;
    }
    const Eigen::Matrix3d& r = pose.linear();
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector3d axis = r.row(i).transpose();  // world axis i in the shape frame
      aabb.max_[i] = pose.translation()[i] + shape.support(axis);
      aabb.min_[i] = pose.translation()[i] - shape.support(-axis);
    }
  }
};

std::atomic<CollisionDetector::FclScopeHook> fcl_scope_hook{nullptr};

// Brackets calls into FCL: their wall time when `seconds` is given, and the test hook.
class FclScope {
 public:
  explicit FclScope(double* seconds)
      : seconds_(seconds), hook_(fcl_scope_hook.load(std::memory_order_relaxed)) {
    if (seconds_ != nullptr) start_ = std::chrono::steady_clock::now();
    if (hook_ != nullptr) hook_(true);
  }
  ~FclScope() {
    if (hook_ != nullptr) hook_(false);
    if (seconds_ != nullptr)
      *seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  FclScope(const FclScope&) = delete;
  FclScope& operator=(const FclScope&) = delete;

 private:
  double* seconds_;
  CollisionDetector::FclScopeHook hook_;
  std::chrono::steady_clock::time_point start_{};
};

// Tribo code called back from inside FCL: outside the hook's bracket while it runs.
class FclCallback {
 public:
  FclCallback() : hook_(fcl_scope_hook.load(std::memory_order_relaxed)) {
    if (hook_ != nullptr) hook_(false);
  }
  ~FclCallback() {
    if (hook_ != nullptr) hook_(true);
  }
  FclCallback(const FclCallback&) = delete;
  FclCallback& operator=(const FclCallback&) = delete;

 private:
  CollisionDetector::FclScopeHook hook_;
};

std::uint64_t pairKey(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
}

}  // namespace

struct CollisionDetector::Impl {
  std::vector<Shape> shapes;
  std::vector<std::pair<int, int>> pairs;
  std::vector<PairKind> kinds;
  CollisionOptions options;
  bool any_fcl_pair = false;
  std::vector<std::unique_ptr<TrackedObject>> objects;
  std::unordered_map<std::uint64_t, int> pair_index;  // geometry pair -> pair
  fcl::DynamicAABBTreeCollisionManagerd manager;
  fcl::CollisionRequestd request;  // shared by the threads: FCL only reads it
  std::vector<int> candidates;
  std::vector<int> all_pairs;         // 0, 1, ..., pairs - 1: the list without the broadphase
  std::vector<int> unbounded_pairs;   // pairs with a half-space: never culled
  std::vector<Polyhedron> polyhedra;  // by geometry, for kPolyhedra pairs (else empty)
  bool timing = false;
  double fcl_seconds = 0.0;
  int threads = 1;
  // What one thread of the narrowphase writes to: its points, FCL's answer, the clipping
  // buffers and its FCL time (summed into fcl_seconds after the loop).
  struct Lane {
    std::vector<ContactPoint> points;
    fcl::CollisionResultd result;
    ClipScratch clip_scratch;
    double fcl_seconds = 0.0;
  };
  std::vector<Lane> lanes{1};  // lane 0 serves the one-thread path (its `points` unused)

  // The narrowphase of every pair in `list`, appended to `out` in list order. Split across
  // `threads` when the list is long enough: thread t takes the t-th contiguous run of the
  // list into its lane, then each lane is copied to its place in `out`.
  void narrowphaseAll(std::span<const int> list, std::span<const Eigen::Isometry3d> poses,
                      std::vector<ContactPoint>& out) {
    constexpr std::size_t kPairsPerThread = 128;
    const int team = threadsFor(list.size(), threads, kPairsPerThread);
    if (team <= 1) {
      for (int p : list) narrowphase(p, poses, out, lanes[0]);
      if (timing) fcl_seconds += std::exchange(lanes[0].fcl_seconds, 0.0);
      return;
    }
    if (lanes.size() < static_cast<std::size_t>(team)) lanes.resize(static_cast<std::size_t>(team));
    const std::size_t base = out.size();
#pragma omp parallel num_threads(team)
    {
      const auto t = static_cast<std::size_t>(omp_get_thread_num());
      const auto n = static_cast<std::size_t>(omp_get_num_threads());
      Lane& lane = lanes[t];
      lane.points.clear();
      for (std::size_t i = list.size() * t / n; i < list.size() * (t + 1) / n; ++i)
        narrowphase(list[i], poses, lane.points, lane);
#pragma omp barrier
#pragma omp single
      {
        std::size_t total = base;
        for (std::size_t k = 0; k < n; ++k) total += lanes[k].points.size();
        out.resize(total);
      }  // implicit barrier: `out` has its size before any lane is copied
      std::size_t offset = base;
      for (std::size_t k = 0; k < t; ++k) offset += lanes[k].points.size();
      std::copy(lane.points.begin(), lane.points.end(),
                out.begin() + static_cast<std::ptrdiff_t>(offset));
    }
    for (Lane& lane : lanes)
      if (timing) fcl_seconds += std::exchange(lane.fcl_seconds, 0.0);
  }

  void narrowphase(int p, std::span<const Eigen::Isometry3d> poses, std::vector<ContactPoint>& out,
                   Lane& lane) {
    const auto [a, b] = pairs[p];
    const int max_points = options.max_points_per_pair;
    switch (kinds[p]) {
      case PairKind::kHalfSpaceBox:
        boxHalfSpaceContacts(poses[b], shapes[b].half_extents, poses[a], p, out);
        return;
      case PairKind::kHalfSpaceShape:
        halfSpaceContacts(shapes[b], poses[b], poses[a], p, max_points, out);
        return;
      case PairKind::kShapeHalfSpace: {
        const auto first = out.size();
        halfSpaceContacts(shapes[a], poses[a], poses[b], p, max_points, out);
        for (auto i = first; i < out.size(); ++i) out[i].normal = -out[i].normal;
        return;
      }
      case PairKind::kSphereSphere:
        sphereSphereContact(poses[a].translation(), shapes[a].radius, poses[b].translation(),
                            shapes[b].radius, p, out);
        return;
      case PairKind::kBoxSphere:
        boxSphereContact(poses[a], shapes[a].half_extents, poses[b].translation(), shapes[b].radius,
                         p, out);
        return;
      case PairKind::kSphereBox: {
        const auto first = out.size();
        boxSphereContact(poses[b], shapes[b].half_extents, poses[a].translation(), shapes[a].radius,
                         p, out);
        for (auto i = first; i < out.size(); ++i) out[i].normal = -out[i].normal;
        return;
      }
      case PairKind::kPolyhedra:
      case PairKind::kFcl:
        break;
    }
    // FCL 0.7 answers shape/mesh with the normal reversed (and misses some sphere/triangle
    // contacts) but mesh/shape correctly: ask with the mesh first and turn the normal back.
    // Its sphere/triangle test also reports the depth with a negative sign: for mesh pairs
    // the magnitude is used.
    const bool swap =
        shapes[b].type == ShapeType::kTriangleMesh && shapes[a].type != ShapeType::kTriangleMesh;
    const bool mesh =
        shapes[a].type == ShapeType::kTriangleMesh || shapes[b].type == ShapeType::kTriangleMesh;
    fcl::CollisionResultd& result = lane.result;
    {
      const FclScope scope(timing ? &lane.fcl_seconds : nullptr);
      result.clear();
      if (swap)
        fcl::collide(objects[b].get(), objects[a].get(), request, result);
      else
        fcl::collide(objects[a].get(), objects[b].get(), request, result);
    }
    const auto first = out.size();
    for (std::size_t i = 0; i < result.numContacts(); ++i) {
      const auto& c = result.getContact(i);
      const double depth = mesh ? std::abs(c.penetration_depth) : c.penetration_depth;
      if (!(depth > 0.0)) continue;  // touching, or FCL gave no depth
      ContactPoint cp;
      cp.pair = p;
      cp.position = c.pos;
      // FCL: from o1 to o2, so from A into B unless swapped.
      cp.normal = swap ? Eigen::Vector3d(-c.normal.normalized()) : c.normal.normalized();
      cp.depth = depth;
      out.push_back(cp);
    }
    if (kinds[p] == PairKind::kPolyhedra && out.size() > first) {
      // EPA's deepest point gives the normal and depth; a face contact becomes its manifold.
      const ContactPoint epa = *std::max_element(
          out.begin() + static_cast<std::ptrdiff_t>(first), out.end(),
          [](const ContactPoint& x, const ContactPoint& y) { return x.depth < y.depth; });
      out.resize(first);
      if (polyhedronContacts(polyhedra[a], poses[a], polyhedra[b], poses[b], epa.normal, epa.depth,
                             p, max_points, lane.clip_scratch, out) == 0)
        out.push_back(epa);
    }
  }
};

CollisionDetector::CollisionDetector(std::vector<Shape> shapes,
                                     std::vector<std::pair<int, int>> pairs,
                                     CollisionOptions options)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.shapes = std::move(shapes);
  m.pairs = std::move(pairs);
  m.options = options;
  const int n = static_cast<int>(m.shapes.size());
  for (int g = 0; g < n; ++g) {
    try {
      m.shapes[g].validate();
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("geometry " + std::to_string(g) + ": " + e.what());
    }
  }
  for (std::size_t p = 0; p < m.pairs.size(); ++p) {
    const auto [a, b] = m.pairs[p];
    if (a < 0 || b < 0 || a >= n || b >= n || a == b)
      throw std::invalid_argument("contact pair " + std::to_string(p) +
                                  ": geometry index out of range or pair with itself");
    const auto ta = m.shapes[a].type, tb = m.shapes[b].type;
    if (ta == ShapeType::kHalfSpace && tb == ShapeType::kHalfSpace)
      throw std::invalid_argument("contact pair " + std::to_string(p) +
                                  ": two half-spaces cannot be in contact");
    PairKind kind = PairKind::kFcl;
    const bool box_plane = (ta == ShapeType::kBox && tb == ShapeType::kHalfSpace) ||
                           (tb == ShapeType::kBox && ta == ShapeType::kHalfSpace);
    const bool closed =
        box_plane ? options.closed_form_box_halfspace : options.closed_form_primitives;
    if (closed) {
      if (ta == ShapeType::kHalfSpace)
        kind = tb == ShapeType::kBox ? PairKind::kHalfSpaceBox : PairKind::kHalfSpaceShape;
      if (tb == ShapeType::kHalfSpace) kind = PairKind::kShapeHalfSpace;
      if (ta == ShapeType::kSphere && tb == ShapeType::kSphere) kind = PairKind::kSphereSphere;
      if (ta == ShapeType::kBox && tb == ShapeType::kSphere) kind = PairKind::kBoxSphere;
      if (ta == ShapeType::kSphere && tb == ShapeType::kBox) kind = PairKind::kSphereBox;
    }
    // Convex meshes with boxes or each other (box/box keeps FCL's own manifold).
    if (kind == PairKind::kFcl && options.polyhedron_manifold && isPolyhedron(m.shapes[a]) &&
        isPolyhedron(m.shapes[b]) && !(ta == ShapeType::kBox && tb == ShapeType::kBox))
      kind = PairKind::kPolyhedra;
    m.kinds.push_back(kind);
    m.any_fcl_pair = m.any_fcl_pair || kind == PairKind::kFcl || kind == PairKind::kPolyhedra;
    m.pair_index[pairKey(a, b)] = static_cast<int>(p);
  }
  // FCL objects only where FCL is asked something: an FCL pair, or the broadphase.
  std::vector<bool> needed(n, options.broadphase);
  m.polyhedra.resize(n);
  for (std::size_t p = 0; p < m.pairs.size(); ++p) {
    const auto [a, b] = m.pairs[p];
    if (m.kinds[p] == PairKind::kFcl || m.kinds[p] == PairKind::kPolyhedra)
      needed[a] = needed[b] = true;
    if (m.kinds[p] != PairKind::kPolyhedra) continue;
    for (int g : {a, b})
      if (m.polyhedra[g].faces.empty()) m.polyhedra[g] = makePolyhedron(m.shapes[g]);
  }
  for (int g = 0; g < n; ++g) {
    m.objects.push_back(needed[g] ? std::make_unique<TrackedObject>(makeFclGeometry(m.shapes[g]))
                                  : nullptr);
    if (m.objects.back())
      m.objects.back()->setUserData(reinterpret_cast<void*>(static_cast<std::intptr_t>(g)));
  }
  m.request = fcl::CollisionRequestd(static_cast<std::size_t>(options.max_points_per_pair), true);
  if (options.broadphase) {
    std::vector<fcl::CollisionObjectd*> raw;
    for (int g = 0; g < n; ++g)
      if (m.shapes[g].type != ShapeType::kHalfSpace) raw.push_back(m.objects[g].get());
    for (std::size_t p = 0; p < m.pairs.size(); ++p) {
      const auto [a, b] = m.pairs[p];
      if (m.shapes[a].type == ShapeType::kHalfSpace || m.shapes[b].type == ShapeType::kHalfSpace)
        m.unbounded_pairs.push_back(static_cast<int>(p));
    }
    m.manager.registerObjects(raw);
    m.manager.setup();
  }
}

CollisionDetector::~CollisionDetector() = default;
CollisionDetector::CollisionDetector(CollisionDetector&&) noexcept = default;
CollisionDetector& CollisionDetector::operator=(CollisionDetector&&) noexcept = default;

const std::vector<std::pair<int, int>>& CollisionDetector::pairs() const { return impl_->pairs; }

void CollisionDetector::setTiming(bool timing) { impl_->timing = timing; }
void CollisionDetector::setThreads(int threads) { impl_->threads = std::max(1, threads); }
double CollisionDetector::fclSeconds() const { return impl_->fcl_seconds; }
void CollisionDetector::setFclScopeHook(FclScopeHook hook) {
  fcl_scope_hook.store(hook, std::memory_order_relaxed);
}

void CollisionDetector::detect(std::span<const Eigen::Isometry3d> poses,
                               std::vector<ContactPoint>& out) {
  Impl& m = *impl_;
  out.clear();
  if (m.any_fcl_pair || m.options.broadphase) {
    for (std::size_t g = 0; g < m.objects.size(); ++g) {
      if (!m.objects[g]) continue;
      m.objects[g]->setTransform(poses[g]);
      if (m.options.broadphase && m.shapes[g].type != ShapeType::kHalfSpace)
        m.objects[g]->updateAabb(m.shapes[g], poses[g]);
    }
  }
  if (!m.options.broadphase) {
    m.all_pairs.resize(m.pairs.size());
    std::iota(m.all_pairs.begin(), m.all_pairs.end(), 0);
    m.narrowphaseAll(m.all_pairs, poses, out);
    return;
  }
  m.candidates.assign(m.unbounded_pairs.begin(), m.unbounded_pairs.end());
  {
    const FclScope scope(m.timing ? &m.fcl_seconds : nullptr);
    m.manager.update();
    m.manager.collide(&m, [](fcl::CollisionObjectd* o1, fcl::CollisionObjectd* o2, void* d) {
      const FclCallback ours;
      auto* self = static_cast<Impl*>(d);
      const int a = static_cast<int>(reinterpret_cast<std::intptr_t>(o1->getUserData()));
      const int b = static_cast<int>(reinterpret_cast<std::intptr_t>(o2->getUserData()));
      const auto it = self->pair_index.find(pairKey(a, b));
      if (it != self->pair_index.end()) self->candidates.push_back(it->second);
      return false;  // keep going
    });
  }
  std::sort(m.candidates.begin(), m.candidates.end());  // deterministic order
  m.narrowphaseAll(m.candidates, poses, out);
}

}  // namespace tribo::contact
