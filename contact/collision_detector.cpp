#include "contact/collision_detector.hpp"

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
#include <array>
#include <atomic>
#include <cassert>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

#include "contact/box_box_contacts.hpp"
#include "contact/box_round_contacts.hpp"
#include "contact/broadphase.hpp"
#include "contact/cell_list.hpp"
#include "contact/counting_sort.hpp"
#include "contact/parallel_range.hpp"
#include "contact/polyhedron_contacts.hpp"
#include "contact/round_contacts.hpp"

namespace tribo::contact {

namespace {

// The skin list's fat boxes go to the cell list while the largest is at most this times the
// first build's median (contact/cell_list.hpp: its box tests grow as the largest cubed).
constexpr double kCellListSpread = 1.5;

enum class PairKind : std::uint8_t {
  kHalfSpaceBox,    // the hot belt pair, straight to its corner manifold
  kHalfSpaceShape,  // A half-space, B anything: closed form
  kShapeHalfSpace,  // the same, normal flipped
  kSphereSphere,
  kBoxSphere,
  kSphereBox,
  kBoxBox,          // box_box_contacts.hpp, no FCL
  kBoxCapsule,      // box_round_contacts.hpp
  kCapsuleBox,      // the same, normal flipped
  kBoxCylinder,     // box_round_contacts.hpp where exact, else FCL
  kCylinderBox,     // the same, normal flipped
  kSphereCapsule,   // round_contacts.hpp
  kCapsuleSphere,   // the same, normal flipped
  kCapsuleCapsule,  // round_contacts.hpp
  kPolyhedra,       // FCL's EPA point grown into a face manifold (polyhedron_contacts.hpp)
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

// The world box of a shape at `pose`: tight, from the shape's support function along the
// world axes (FCL's own box of a rotated object is the bounding sphere's, which makes resting
// neighbours overlap). A mesh with many vertices: its local box turned (|R| times the half
// extents), since the support costs a pass over the vertices; a box the same way (exactly its
// support along each axis); a sphere its centre +- r.
Aabb worldBox(const Shape& shape, const Eigen::Isometry3d& pose, const Aabb* local) {
  const Eigen::Matrix3d& r = pose.linear();
  Aabb box;
  // A box of local half widths `half` about `centre` (world), turned by r: its half width
  // along world axis i is |row i of r| . half.
  auto turned = [&](const Eigen::Vector3d& centre, const Eigen::Vector3d& half) {
    const Eigen::Vector3d world_half = r.cwiseAbs() * half;
    box.lo = centre - world_half;
    box.hi = centre + world_half;
    return box;
  };
  if (local != nullptr)
    return turned(pose * (0.5 * (local->lo + local->hi)), 0.5 * (local->hi - local->lo));
  if (shape.type == ShapeType::kBox) return turned(pose.translation(), shape.half_extents);
  if (shape.type == ShapeType::kSphere) {  // the same in every frame: no rotation, no norm
    box.lo = pose.translation().array() - shape.radius;
    box.hi = pose.translation().array() + shape.radius;
    return box;
  }
  // Shapes symmetric about their origin have support(-d) == support(d) bit for bit (a norm,
  // a hypot, |d_z|): one call per axis.
  const bool symmetric = shape.type == ShapeType::kCapsule || shape.type == ShapeType::kCylinder;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d axis = r.row(i).transpose();  // world axis i in the shape frame
    const double up = shape.support(axis);
    box.hi[i] = pose.translation()[i] + up;
    box.lo[i] = pose.translation()[i] - (symmetric ? up : shape.support(-axis));
  }
  return box;
}

// Does `outer` contain `inner`? False when a coordinate of either is NaN.
bool contains(const Aabb& outer, const Aabb& inner) {
  return inner.lo.x() >= outer.lo.x() && inner.lo.y() >= outer.lo.y() &&
         inner.lo.z() >= outer.lo.z() && inner.hi.x() <= outer.hi.x() &&
         inner.hi.y() <= outer.hi.y() && inner.hi.z() <= outer.hi.z();
}

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

std::uint64_t pairKey(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
}

}  // namespace

// One pair to look at: its id, geometries A and B, and how. `cull`: a pair of the skin list,
// looked at only while the two geometries' tight world boxes overlap.
struct Candidate {
  int id = -1;
  int a = -1, b = -1;
  PairKind kind = PairKind::kFcl;
  bool cull = false;
};

namespace {

// `list` in increasing pair id, the order that keeps every run's points the same for any
// thread count. Ids are distinct, so any correct sort gives this one order: a long list (the
// skin list of a 32 000-sphere chute holds ~10^5 pairs, rebuilt every few steps) by a
// least-significant-digit radix sort on 11-bit digits, one stable pass a digit the largest id
// has (three for ids up to 2^33), each a counting sort (contact/counting_sort.hpp) through
// `scratch` and `start`; a short one, or one holding a negative id,
// by comparison. The radix passes cost O(n) each where the comparison sort took 5.7 % of the
// chute's one-thread step (docs/performance.md).
void sortById(std::vector<Candidate>& list, std::vector<Candidate>& scratch,
              std::vector<std::uint32_t>& start) {
  constexpr std::size_t kRadixFrom = 1024;
  auto by_id = [](const Candidate& x, const Candidate& y) { return x.id < y.id; };
  int largest = 0;
  bool negative = false;
  for (const Candidate& c : list) {
    largest = std::max(largest, c.id);
    negative = negative || c.id < 0;
  }
  if (list.size() < kRadixFrom || negative) {
    std::sort(list.begin(), list.end(), by_id);
    return;
  }
  constexpr int kBits = 11;
  constexpr std::uint32_t kDigits = 1u << kBits;
  const auto top = static_cast<std::uint32_t>(largest);
  for (int shift = 0; shift < 32 && (top >> shift) != 0; shift += kBits) {
    countingSort(
        list, kDigits,
        [&list, shift](std::size_t e) {
          return (static_cast<std::uint32_t>(list[e].id) >> shift) & (kDigits - 1);
        },
        start, scratch);
    list.swap(scratch);
  }
}

// `pairs` ((g, h), g < h, each once, g below `geometries`) in increasing (g, h): counted into
// runs by g, then each run (a geometry's few neighbours) sorted on h; `start` and `scratch`
// are kept between calls. One counting pass where a sort of the candidates by id took three
// radix passes over records twice the size.
void sortPairsByGeometry(std::vector<std::pair<int, int>>& pairs, std::size_t geometries,
                         std::vector<std::uint32_t>& start,
                         std::vector<std::pair<int, int>>& scratch) {
  countingSort(
      pairs, geometries,
      [&pairs](std::size_t i) { return static_cast<std::size_t>(pairs[i].first); }, start, scratch);
  for (std::size_t g = 0; g < geometries; ++g) {
    auto first = scratch.begin() + start[g], last = scratch.begin() + start[g + 1];
    if (last - first <= 32) {
      for (auto i = first + (first != last); i < last; ++i) {  // insertion on h
        const std::pair<int, int> p = *i;
        auto j = i;
        for (; j > first && (j - 1)->second > p.second; --j) *j = *(j - 1);
        *j = p;
      }
    } else {
      std::sort(first, last);
    }
  }
  pairs.swap(scratch);
}

}  // namespace

struct CollisionDetector::Impl {
  std::vector<Shape> shapes;
  std::vector<Candidate> listed;         // listed pairs, by id (empty with a rule)
  std::unique_ptr<const PairRule> rule;  // pairs on demand (null with a list)
  CollisionOptions options;
  bool any_fcl_pair = false;
  bool narrowphase_reaches_fcl = false;     // some pair may go to fcl::collide
  std::unique_ptr<QueryWatchdog> watchdog;  // null unless watchQueries() started one
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects;  // null where FCL is never asked
  std::unordered_map<std::uint64_t, int> pair_index;            // listed: geometry pair -> pair
  GridBroadphase grid;
  CellList cells;            // the skin list's broadphase while its fat boxes are of about one size
  std::vector<int> bounded;  // geometries in the broadphase (all but half-spaces)
  std::vector<Aabb> boxes;   // world boxes, by geometry (half-spaces' unused)
  std::vector<Aabb> mesh_local;      // local boxes of meshes with many vertices (else empty)
  std::vector<char> has_mesh_local;  // by geometry
  std::vector<std::pair<int, int>> close_pairs;
  std::vector<std::pair<int, int>> close_scratch;  // sortPairsByGeometry's second buffer
  std::vector<std::uint32_t> close_start;          // and its runs
  fcl::CollisionRequestd request;                  // shared by the threads: FCL only reads it
  std::vector<Candidate> candidates;
  std::vector<Candidate> sort_scratch;    // sortById's second buffer
  std::vector<std::uint32_t> sort_start;  // and its digits' counts
  std::vector<Candidate> unbounded;       // pairs with a half-space: never culled
  // The skin list (options.broadphase_skin > 0): every pair whose boxes grown by `margin` on
  // each side (`fat`, by geometry, as of the last build) overlap, with the unbounded pairs,
  // by pair id; rebuilt when some tight box has left its fat box.
  double margin = -1.0;     // [m]; < 0 before the first build
  double fat_median = 0.0;  // [m] the fat boxes' median largest extent at the first build
  std::vector<Aabb> fat;
  std::vector<Candidate> skin_list;
  bool skin_valid = false;
  long skin_builds = 0;
  long cell_list_builds = 0;
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

  // The kind of a pair by its shapes' types and the options, listed once a type pair
  // (listKindsOfTypes, when the options are set) so that a skin list's rebuild, which asks
  // for every candidate, reads a table; classify adds the convex meshes' manifold.
  static constexpr std::size_t kShapeTypes = static_cast<std::size_t>(ShapeType::kTriangleMesh) + 1;
  std::array<PairKind, kShapeTypes * kShapeTypes> kinds_of_types{};
  PairKind kindOfTypes(ShapeType ta, ShapeType tb) const;
  void listKindsOfTypes();
  PairKind classify(int a, int b) const;
  Candidate candidate(int id, int a, int b) const { return {id, a, b, classify(a, b)}; }
  void setUp();
  void candidateFound(int g, int h);
  void buildSkinList();

  // The narrowphase of every pair in `list`, appended to `out` in list order. Split across
  // `threads` when the list is long enough: the list cut into contiguous runs, each into its
  // own lane by whichever thread claims it, then the lanes appended in order.
  void narrowphaseAll(std::span<const Candidate> list, std::span<const Eigen::Isometry3d> poses,
                      std::vector<ContactPoint>& out) {
    constexpr std::size_t kPairsPerThread = 128;
    const int team = threadsFor(list.size(), threads, kPairsPerThread);
    if (team <= 1) {
      for (const Candidate& c : list)
        if (!culled(c)) narrowphaseOf(c, poses, out, lanes[0]);
      if (timing) fcl_seconds += std::exchange(lanes[0].fcl_seconds, 0.0);
      return;
    }
    // Contiguous runs of the list, one lane each, claimed by the threads (contact/work_team.hpp);
    // the lanes are copied to `out` in list order whoever ran them.
    const std::size_t chunks = chunksFor(list.size(), team);
    if (lanes.size() < chunks) lanes.resize(chunks);
    if (watchdog) watchdog->reserveLanes(static_cast<int>(chunks));
    auto run = [&](std::size_t c) {
      Lane& lane = lanes[c];
      lane.points.clear();
      for (std::size_t i = list.size() * c / chunks; i < list.size() * (c + 1) / chunks; ++i)
        if (!culled(list[i])) narrowphaseOf(list[i], poses, lane.points, lane);
    };
    runChunks(chunks, team, run);
    std::size_t total = out.size();
    for (std::size_t c = 0; c < chunks; ++c) total += lanes[c].points.size();
    out.reserve(total);
    for (std::size_t c = 0; c < chunks; ++c)
      out.insert(out.end(), lanes[c].points.begin(), lanes[c].points.end());
    for (Lane& lane : lanes)
      if (timing) fcl_seconds += std::exchange(lane.fcl_seconds, 0.0);
  }

  // A pair of the skin list whose tight boxes do not overlap: what the grid on the tight boxes
  // would not have reported. Tested in the loop over the list, before the call: on a chute
  // most of the list is culled, and the narrowphase's entry and exit cost more than the test.
  bool culled(const Candidate& c) const {
    return c.cull &&
           !overlaps(boxes[static_cast<std::size_t>(c.a)], boxes[static_cast<std::size_t>(c.b)]);
  }

  // The contact points of one pair, appended to `out` (never culled here: the caller tests).
  // A granular scene's pairs (sphere/sphere, and a half-space's with each shape above it) are
  // answered here: their closed forms cost about as much as narrowphase's entry and exit (the
  // dispatch over every kind, its frame), which they then skip. Every other pair: narrowphase.
  void narrowphaseOf(const Candidate& c, std::span<const Eigen::Isometry3d> poses,
                     std::vector<ContactPoint>& out, Lane& lane) {
    const auto a = static_cast<std::size_t>(c.a), b = static_cast<std::size_t>(c.b);
    if (c.kind == PairKind::kSphereSphere) {
      sphereSphereContact(poses[a].translation(), shapes[a].radius, poses[b].translation(),
                          shapes[b].radius, c.id, out);
      return;
    }
    if (c.kind == PairKind::kHalfSpaceShape) {
      halfSpaceContacts(shapes[b], poses[b], poses[a], c.id, options.max_points_per_pair, out);
      return;
    }
    narrowphase(c, poses, out, lane);
  }

  // The dispatch over the other kinds of pair, for narrowphaseOf (the only caller).
  void narrowphase(const Candidate& c, std::span<const Eigen::Isometry3d> poses,
                   std::vector<ContactPoint>& out, Lane& lane) {
    const int a = c.a, b = c.b, p = c.id;
    const int max_points = options.max_points_per_pair;
    switch (c.kind) {
      case PairKind::kHalfSpaceBox:
        boxHalfSpaceContacts(poses[b], shapes[b].half_extents, poses[a], p, out);
        return;
      case PairKind::kHalfSpaceShape:
      case PairKind::kSphereSphere:
        assert(false && "answered by narrowphaseOf before the dispatch");
        return;
      case PairKind::kShapeHalfSpace: {
        const auto first = out.size();
        halfSpaceContacts(shapes[a], poses[a], poses[b], p, max_points, out);
        for (auto i = first; i < out.size(); ++i) out[i].normal = -out[i].normal;
        return;
      }
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
      case PairKind::kBoxBox:
        boxBoxContacts(poses[a], shapes[a].half_extents, poses[b], shapes[b].half_extents, p,
                       max_points, out);
        return;
      case PairKind::kBoxCapsule:
        boxCapsuleContacts(poses[a], shapes[a].half_extents, poses[b], shapes[b].radius,
                           shapes[b].half_length, p, out);
        return;
      case PairKind::kCapsuleBox: {
        const auto first = out.size();
        boxCapsuleContacts(poses[b], shapes[b].half_extents, poses[a], shapes[a].radius,
                           shapes[a].half_length, p, out);
        for (auto i = first; i < out.size(); ++i) out[i].normal = -out[i].normal;
        return;
      }
      case PairKind::kBoxCylinder:
        if (boxCylinderContacts(poses[a], shapes[a].half_extents, poses[b], shapes[b].radius,
                                shapes[b].half_length, p, out) >= 0)
          return;
        break;  // no closed form for this pose: FCL
      case PairKind::kCylinderBox: {
        const auto first = out.size();
        if (boxCylinderContacts(poses[b], shapes[b].half_extents, poses[a], shapes[a].radius,
                                shapes[a].half_length, p, out) < 0)
          break;
        for (auto i = first; i < out.size(); ++i) out[i].normal = -out[i].normal;
        return;
      }
      case PairKind::kSphereCapsule:
        sphereCapsuleContact(poses[a].translation(), shapes[a].radius, poses[b], shapes[b].radius,
                             shapes[b].half_length, p, out);
        return;
      case PairKind::kCapsuleSphere: {
        const auto first = out.size();
        sphereCapsuleContact(poses[b].translation(), shapes[b].radius, poses[a], shapes[a].radius,
                             shapes[a].half_length, p, out);
        for (auto i = first; i < out.size(); ++i) out[i].normal = -out[i].normal;
        return;
      }
      case PairKind::kCapsuleCapsule:
        capsuleCapsuleContacts(poses[a], shapes[a].radius, shapes[a].half_length, poses[b],
                               shapes[b].radius, shapes[b].half_length, p, out);
        return;
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
      const int lane_index = static_cast<int>(&lane - lanes.data());
      if (watchdog) watchdog->begin(lane_index, a, b);
      result.clear();
      if (swap)
        fcl::collide(objects[b].get(), objects[a].get(), request, result);
      else
        fcl::collide(objects[a].get(), objects[b].get(), request, result);
      if (watchdog) watchdog->end(lane_index);
    }
    const auto first = out.size();
    for (std::size_t i = 0; i < result.numContacts(); ++i) {
      const auto& hit = result.getContact(i);
      const double depth = mesh ? std::abs(hit.penetration_depth) : hit.penetration_depth;
      if (!(depth > 0.0)) continue;  // touching, or FCL gave no depth
      ContactPoint cp;
      cp.pair = p;
      cp.position = hit.pos;
      // FCL: from o1 to o2, so from A into B unless swapped.
      cp.normal = swap ? Eigen::Vector3d(-hit.normal.normalized()) : hit.normal.normalized();
      cp.depth = depth;
      out.push_back(cp);
    }
    if (c.kind == PairKind::kPolyhedra && out.size() > first) {
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

PairKind CollisionDetector::Impl::kindOfTypes(ShapeType ta, ShapeType tb) const {
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
    if (ta == ShapeType::kBox && tb == ShapeType::kBox) kind = PairKind::kBoxBox;
    if (ta == ShapeType::kBox && tb == ShapeType::kCapsule) kind = PairKind::kBoxCapsule;
    if (ta == ShapeType::kCapsule && tb == ShapeType::kBox) kind = PairKind::kCapsuleBox;
    if (ta == ShapeType::kBox && tb == ShapeType::kCylinder) kind = PairKind::kBoxCylinder;
    if (ta == ShapeType::kCylinder && tb == ShapeType::kBox) kind = PairKind::kCylinderBox;
    if (ta == ShapeType::kSphere && tb == ShapeType::kCapsule) kind = PairKind::kSphereCapsule;
    if (ta == ShapeType::kCapsule && tb == ShapeType::kSphere) kind = PairKind::kCapsuleSphere;
    if (ta == ShapeType::kCapsule && tb == ShapeType::kCapsule) kind = PairKind::kCapsuleCapsule;
  }
  return kind;
}

void CollisionDetector::Impl::listKindsOfTypes() {
  for (std::size_t i = 0; i < kShapeTypes; ++i)
    for (std::size_t j = 0; j < kShapeTypes; ++j)
      kinds_of_types[i * kShapeTypes + j] =
          kindOfTypes(static_cast<ShapeType>(i), static_cast<ShapeType>(j));
}

PairKind CollisionDetector::Impl::classify(int a, int b) const {
  const auto ta = shapes[a].type, tb = shapes[b].type;
  PairKind kind =
      kinds_of_types[static_cast<std::size_t>(ta) * kShapeTypes + static_cast<std::size_t>(tb)];
  // Convex meshes with boxes or each other (box/box: its closed form, or FCL's manifold).
  if (kind == PairKind::kFcl && options.polyhedron_manifold && isPolyhedron(shapes[a]) &&
      isPolyhedron(shapes[b]) && !(ta == ShapeType::kBox && tb == ShapeType::kBox))
    kind = PairKind::kPolyhedra;
  return kind;
}

// The broadphase reported geometries g and h close: a candidate when they form a pair.
void CollisionDetector::Impl::candidateFound(int g, int h) {
  if (rule) {
    const int id = rule->pairId(g, h);
    if (id < 0) return;
    const auto [a, b] = rule->geometries(id);
    candidates.push_back(candidate(id, a, b));
    return;
  }
  const auto it = pair_index.find(pairKey(g, h));
  if (it != pair_index.end()) candidates.push_back(listed[static_cast<std::size_t>(it->second)]);
}

// The skin list from the current tight boxes: the margin (fixed at the first build), the fat
// boxes, the grid's pairs among them as candidates, and the unbounded pairs, sorted by id.
void CollisionDetector::Impl::buildSkinList() {
  if (margin < 0.0) {
    std::vector<double> extents;
    extents.reserve(bounded.size());
    for (const int g : bounded) {
      const Aabb& b = boxes[static_cast<std::size_t>(g)];
      const double e = (b.hi - b.lo).maxCoeff();
      if (e > 0.0 && std::isfinite(e)) extents.push_back(e);
    }
    double median = 1.0;  // every box a point: 1 m, as the grid's cell
    if (!extents.empty()) {
      const auto middle = extents.begin() + static_cast<std::ptrdiff_t>(extents.size() / 2);
      std::nth_element(extents.begin(), middle, extents.end());
      median = *middle;
    }
    margin = options.broadphase_skin * median;
    fat_median = median + 2.0 * margin;
  }
  const Eigen::Vector3d grow = Eigen::Vector3d::Constant(margin);
  double largest = 0.0;  // the largest fat extent (a NaN one left out: both keep it aside)
  for (const int g : bounded) {
    const Aabb& b = boxes[static_cast<std::size_t>(g)];
    Aabb& f = fat[static_cast<std::size_t>(g)];
    f = {b.lo - grow, b.hi + grow};
    largest = std::max(largest, (f.hi - f.lo).maxCoeff());
  }
  // Fat boxes of about one size (a pile, a chute: the largest within 1.5 times the first
  // median) are paired by the cell list, a third of the grid's box tests there
  // (contact/cell_list.hpp); others by the grid. The same pairs either way.
  if (largest <= kCellListSpread * fat_median) {
    cells.overlappingPairs(fat, bounded, close_pairs);
    ++cell_list_builds;
  } else {
    grid.overlappingPairs(fat, bounded, close_pairs);
  }
  // With a rule (automatic contacts) the ids grow with (g, h) (core/automatic_contacts.hpp:
  // g n + h), so the close pairs sorted by geometry give the candidates in id order, merged
  // with the unbounded pairs (sorted at set-up). Checked, not assumed: a rule whose ids run
  // otherwise has its candidates sorted by id as a listed detector's are.
  if (rule) sortPairsByGeometry(close_pairs, shapes.size(), close_start, close_scratch);
  candidates.clear();
  for (const auto& [g, h] : close_pairs) candidateFound(g, h);
  for (Candidate& c : candidates) c.cull = true;
  auto by_id = [](const Candidate& x, const Candidate& y) { return x.id < y.id; };
  if (rule && std::is_sorted(candidates.begin(), candidates.end(), by_id)) {
    skin_list.resize(candidates.size() + unbounded.size());
    std::merge(candidates.begin(), candidates.end(), unbounded.begin(), unbounded.end(),
               skin_list.begin(), by_id);
  } else {
    candidates.insert(candidates.end(), unbounded.begin(), unbounded.end());
    sortById(candidates, sort_scratch, sort_start);
    skin_list.assign(candidates.begin(), candidates.end());
  }
  skin_valid = true;
  ++skin_builds;
}

// FCL objects, polyhedra and the broadphase, once the pairs (listed or by rule) are known.
void CollisionDetector::Impl::setUp() {
  const int n = static_cast<int>(shapes.size());
  for (int g = 0; g < n; ++g) {
    try {
      shapes[g].validate();
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("geometry " + std::to_string(g) + ": " + e.what());
    }
  }
  // FCL objects only where FCL's narrowphase is asked something: a listed FCL pair, or with
  // a rule a shape type that meets another with no closed form (polyhedra are made for every
  // convex shape).
  std::vector<bool> needed(n, false);
  // Sized by geometry on the first polyhedron made: left empty, as `mesh_local` is, when a
  // scene needs none (the two were 104 bytes a geometry of a large scene of boxes).
  auto make_polyhedron = [&](int g) {
    if (polyhedra.empty()) polyhedra.resize(static_cast<std::size_t>(n));
    polyhedra[static_cast<std::size_t>(g)] = makePolyhedron(shapes[g]);
  };
  // Cylinder/box falls back to FCL for the poses it has no closed form for.
  auto fcl_kind = [](PairKind k) {
    return k == PairKind::kFcl || k == PairKind::kPolyhedra || k == PairKind::kBoxCylinder ||
           k == PairKind::kCylinderBox;
  };
  for (const Candidate& c : listed) {
    if (fcl_kind(c.kind)) needed[c.a] = needed[c.b] = true;
    any_fcl_pair = any_fcl_pair || fcl_kind(c.kind);
    if (c.kind != PairKind::kPolyhedra) continue;
    for (int g : {c.a, c.b})
      if (polyhedra.empty() || polyhedra[g].faces.empty()) make_polyhedron(g);
  }
  if (rule && options.polyhedron_manifold) {
    // Any two polyhedra may meet, except two boxes: boxes need theirs only beside a mesh.
    bool any_mesh = false;
    for (int g = 0; g < n; ++g)
      any_mesh = any_mesh || (isPolyhedron(shapes[g]) && shapes[g].type != ShapeType::kBox);
    for (int g = 0; g < n; ++g)
      if (isPolyhedron(shapes[g]) && (any_mesh || shapes[g].type != ShapeType::kBox))
        make_polyhedron(g);
  }
  narrowphase_reaches_fcl = any_fcl_pair;
  if (rule) {
    // Any two geometries may be asked: some pair reaches FCL when two of the present shape
    // types (a type with itself when it occurs twice) have no closed form.
    constexpr auto kTypes = static_cast<std::size_t>(ShapeType::kTriangleMesh) + 1;
    std::vector<int> first_of(kTypes, -1), second_of(kTypes, -1);
    for (int g = 0; g < n; ++g) {
      auto& slot = first_of[static_cast<std::size_t>(shapes[g].type)];
      if (slot < 0)
        slot = g;
      else if (second_of[static_cast<std::size_t>(shapes[g].type)] < 0)
        second_of[static_cast<std::size_t>(shapes[g].type)] = g;
    }
    std::vector<bool> type_reaches_fcl(kTypes, false);
    for (std::size_t s = 0; s < first_of.size(); ++s)
      for (std::size_t t = s; t < first_of.size(); ++t) {
        const int a = first_of[s], b = s == t ? second_of[t] : first_of[t];
        if (a < 0 || b < 0) continue;
        if (shapes[a].type == ShapeType::kHalfSpace && shapes[b].type == ShapeType::kHalfSpace)
          continue;
        if (fcl_kind(classify(a, b)) || fcl_kind(classify(b, a)))
          type_reaches_fcl[s] = type_reaches_fcl[t] = true;
      }
    for (int g = 0; g < n; ++g)
      if (type_reaches_fcl[static_cast<std::size_t>(shapes[g].type)]) needed[g] = true;
  }
  objects.reserve(static_cast<std::size_t>(n));
  for (int g = 0; g < n; ++g) {
    narrowphase_reaches_fcl = narrowphase_reaches_fcl || needed[g];
    objects.push_back(
        needed[g] ? std::make_unique<fcl::CollisionObjectd>(makeFclGeometry(shapes[g])) : nullptr);
  }
  any_fcl_pair = narrowphase_reaches_fcl;
  request = fcl::CollisionRequestd(static_cast<std::size_t>(options.max_points_per_pair), true);
  if (!options.broadphase) return;
  std::vector<int> planes;
  boxes.resize(static_cast<std::size_t>(n));
  fat.resize(static_cast<std::size_t>(n));
  has_mesh_local.assign(static_cast<std::size_t>(n), 0);
  bounded.reserve(static_cast<std::size_t>(n));
  for (int g = 0; g < n; ++g) {
    if (shapes[g].type == ShapeType::kHalfSpace) {
      planes.push_back(g);
      continue;
    }
    bounded.push_back(g);
    if (shapes[g].mesh && shapes[g].mesh->vertices.size() > 64) {
      if (mesh_local.empty()) mesh_local.resize(static_cast<std::size_t>(n));
      Aabb& local = mesh_local[static_cast<std::size_t>(g)];
      local.lo = local.hi = shapes[g].mesh->vertices.front();
      for (const Eigen::Vector3d& v : shapes[g].mesh->vertices) {
        local.lo = local.lo.cwiseMin(v);
        local.hi = local.hi.cwiseMax(v);
      }
      has_mesh_local[static_cast<std::size_t>(g)] = 1;
    }
  }
  if (rule) {
    for (int h : planes)
      for (int g = 0; g < n; ++g)
        if (const int id = rule->pairId(g, h); id >= 0) {
          const auto [a, b] = rule->geometries(id);
          unbounded.push_back(candidate(id, a, b));
        }
    std::sort(unbounded.begin(), unbounded.end(),
              [](const Candidate& x, const Candidate& y) { return x.id < y.id; });
  } else {
    for (const Candidate& c : listed)
      if (shapes[c.a].type == ShapeType::kHalfSpace || shapes[c.b].type == ShapeType::kHalfSpace)
        unbounded.push_back(c);
  }
}

CollisionDetector::CollisionDetector(std::vector<Shape> shapes,
                                     std::vector<std::pair<int, int>> pairs,
                                     CollisionOptions options)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.shapes = std::move(shapes);
  m.options = options;
  m.listKindsOfTypes();
  const int n = static_cast<int>(m.shapes.size());
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    const auto [a, b] = pairs[p];
    if (a < 0 || b < 0 || a >= n || b >= n || a == b)
      throw std::invalid_argument("contact pair " + std::to_string(p) +
                                  ": geometry index out of range or pair with itself");
    if (m.shapes[a].type == ShapeType::kHalfSpace && m.shapes[b].type == ShapeType::kHalfSpace)
      throw std::invalid_argument("contact pair " + std::to_string(p) +
                                  ": two half-spaces cannot be in contact");
    m.listed.push_back(m.candidate(static_cast<int>(p), a, b));
    m.pair_index[pairKey(a, b)] = static_cast<int>(p);
  }
  m.setUp();
}

CollisionDetector::CollisionDetector(std::vector<Shape> shapes,
                                     std::unique_ptr<const PairRule> rule, CollisionOptions options)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.shapes = std::move(shapes);
  m.rule = std::move(rule);
  m.options = options;
  m.options.broadphase = true;
  m.listKindsOfTypes();
  m.setUp();
}

CollisionDetector::~CollisionDetector() = default;
CollisionDetector::CollisionDetector(CollisionDetector&&) noexcept = default;
CollisionDetector& CollisionDetector::operator=(CollisionDetector&&) noexcept = default;

bool CollisionDetector::watchQueries(double limit_seconds,
                                     QueryWatchdog::OverrunHandler on_overrun) {
  Impl& m = *impl_;
  if (!m.narrowphase_reaches_fcl || m.watchdog) return m.watchdog != nullptr;
  m.watchdog = std::make_unique<QueryWatchdog>(limit_seconds, std::move(on_overrun),
                                               static_cast<int>(m.lanes.size()));
  return true;
}

void CollisionDetector::setTiming(bool timing) { impl_->timing = timing; }
void CollisionDetector::setThreads(int threads) {
  impl_->threads = std::max(1, threads);
  impl_->grid.setThreads(impl_->threads);
  impl_->cells.setThreads(impl_->threads);
}
double CollisionDetector::fclSeconds() const { return impl_->fcl_seconds; }
long CollisionDetector::skinListBuilds() const { return impl_->skin_builds; }
long CollisionDetector::cellListBuilds() const { return impl_->cell_list_builds; }
void CollisionDetector::setFclScopeHook(FclScopeHook hook) {
  fcl_scope_hook.store(hook, std::memory_order_relaxed);
}

void CollisionDetector::detect(std::span<const Eigen::Isometry3d> poses,
                               std::vector<ContactPoint>& out) {
  Impl& m = *impl_;
  out.clear();
  if (m.any_fcl_pair)
    for (std::size_t g = 0; g < m.objects.size(); ++g)
      if (m.objects[g]) m.objects[g]->setTransform(poses[g]);
  if (!m.options.broadphase) {
    m.narrowphaseAll(m.listed, poses, out);
    return;
  }
  constexpr std::size_t kBoxesPerThread = 512;
  const bool skin = m.options.broadphase_skin > 0.0;
  std::atomic<bool> escaped{false};  // some tight box left its fat box
  parallelFor(m.bounded.size(), threadsFor(m.bounded.size(), m.threads, kBoxesPerThread),
              [&m, poses, skin, &escaped](std::size_t k) {
                const auto g = static_cast<std::size_t>(m.bounded[k]);
                m.boxes[g] = worldBox(m.shapes[g], poses[g],
                                      m.has_mesh_local[g] ? &m.mesh_local[g] : nullptr);
                if (skin && !contains(m.fat[g], m.boxes[g]))
                  escaped.store(true, std::memory_order_relaxed);
              });
  if (skin) {
    // The skin list holds every pair whose tight boxes can overlap while each stays in its fat
    // box; its narrowphase skips the pairs whose tight boxes do not: the grid's candidates on
    // the tight boxes, in the same id order.
    if (!m.skin_valid || escaped.load(std::memory_order_relaxed)) m.buildSkinList();
    m.narrowphaseAll(m.skin_list, poses, out);
    return;
  }
  m.grid.overlappingPairs(m.boxes, m.bounded, m.close_pairs);
  m.candidates.assign(m.unbounded.begin(), m.unbounded.end());
  for (const auto& [g, h] : m.close_pairs) m.candidateFound(g, h);
  sortById(m.candidates, m.sort_scratch, m.sort_start);  // deterministic order
  m.narrowphaseAll(m.candidates, poses, out);
}

}  // namespace tribo::contact
