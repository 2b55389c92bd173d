#include "contact/collision_detector.hpp"

#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/halfspace.h>
#include <fcl/narrowphase/collision.h>

#include <map>
#include <stdexcept>
#include <string>

namespace tribo::contact {

namespace {

enum class PairKind { kBoxHalfSpace, kHalfSpaceBox, kFcl };

std::shared_ptr<fcl::CollisionGeometryd> makeFclGeometry(const Shape& shape) {
  switch (shape.type) {
    case ShapeType::kBox:
      return std::make_shared<fcl::Boxd>(2.0 * shape.half_extents);
    case ShapeType::kHalfSpace:
      return std::make_shared<fcl::Halfspaced>(Eigen::Vector3d::UnitZ(), 0.0);
  }
  throw std::invalid_argument("unsupported shape");
}

}  // namespace

struct CollisionDetector::Impl {
  std::vector<Shape> shapes;
  std::vector<std::pair<int, int>> pairs;
  std::vector<PairKind> kinds;
  CollisionOptions options;
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects;
  std::map<std::pair<int, int>, int> pair_index;  // (min geom, max geom) -> pair
  fcl::DynamicAABBTreeCollisionManagerd manager;
  fcl::CollisionRequestd request;
  fcl::CollisionResultd result;
  std::vector<int> candidates;
  std::vector<int> unbounded_pairs;  // pairs with a half-space: never culled

  void narrowphase(int p, std::span<const Eigen::Isometry3d> poses,
                   std::vector<ContactPoint>& out) {
    const auto [a, b] = pairs[p];
    switch (kinds[p]) {
      case PairKind::kHalfSpaceBox:
        boxHalfSpaceContacts(poses[b], shapes[b].half_extents, poses[a], p, out);
        return;
      case PairKind::kBoxHalfSpace: {
        const auto first = out.size();
        boxHalfSpaceContacts(poses[a], shapes[a].half_extents, poses[b], p, out);
        for (auto i = first; i < out.size(); ++i) out[i].normal = -out[i].normal;
        return;
      }
      case PairKind::kFcl:
        break;
    }
    result.clear();
    fcl::collide(objects[a].get(), objects[b].get(), request, result);
    for (std::size_t i = 0; i < result.numContacts(); ++i) {
      const auto& c = result.getContact(i);
      ContactPoint cp;
      cp.pair = p;
      cp.position = c.pos;
      cp.normal = c.normal.normalized();  // FCL: from o1 (A) to o2 (B)
      cp.depth = c.penetration_depth;
      out.push_back(cp);
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
    m.objects.push_back(std::make_unique<fcl::CollisionObjectd>(makeFclGeometry(m.shapes[g])));
    m.objects.back()->setUserData(reinterpret_cast<void*>(static_cast<std::intptr_t>(g)));
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
    if (options.closed_form_box_halfspace) {
      if (ta == ShapeType::kHalfSpace && tb == ShapeType::kBox) kind = PairKind::kHalfSpaceBox;
      if (ta == ShapeType::kBox && tb == ShapeType::kHalfSpace) kind = PairKind::kBoxHalfSpace;
    }
    m.kinds.push_back(kind);
    m.pair_index[{std::min(a, b), std::max(a, b)}] = static_cast<int>(p);
  }
  m.request = fcl::CollisionRequestd(static_cast<std::size_t>(options.max_points_per_pair), true);
  if (options.broadphase) {
    // Half-spaces have infinite AABBs, which FCL's tree cannot hold: they stay out of it,
    // and their pairs are always handed to the narrowphase (a cheap closed form).
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

void CollisionDetector::detect(std::span<const Eigen::Isometry3d> poses,
                               std::vector<ContactPoint>& out) {
  Impl& m = *impl_;
  out.clear();
  const bool need_fcl_poses =
      m.options.broadphase ||
      std::any_of(m.kinds.begin(), m.kinds.end(), [](PairKind k) { return k == PairKind::kFcl; });
  if (need_fcl_poses) {
    for (std::size_t g = 0; g < m.objects.size(); ++g) {
      m.objects[g]->setTransform(poses[g]);
      if (m.options.broadphase) m.objects[g]->computeAABB();
    }
  }
  if (!m.options.broadphase) {
    for (std::size_t p = 0; p < m.pairs.size(); ++p) m.narrowphase(static_cast<int>(p), poses, out);
    return;
  }
  m.manager.update();
  m.candidates.assign(m.unbounded_pairs.begin(), m.unbounded_pairs.end());
  struct Data {
    Impl* impl;
  } data{&m};
  m.manager.collide(&data, [](fcl::CollisionObjectd* o1, fcl::CollisionObjectd* o2, void* d) {
    auto* self = static_cast<Data*>(d)->impl;
    const int a = static_cast<int>(reinterpret_cast<std::intptr_t>(o1->getUserData()));
    const int b = static_cast<int>(reinterpret_cast<std::intptr_t>(o2->getUserData()));
    const auto it = self->pair_index.find({std::min(a, b), std::max(a, b)});
    if (it != self->pair_index.end()) self->candidates.push_back(it->second);
    return false;  // keep going
  });
  std::sort(m.candidates.begin(), m.candidates.end());  // deterministic order
  for (int p : m.candidates) m.narrowphase(p, poses, out);
}

int boxHalfSpaceContacts(const Eigen::Isometry3d& box_pose, const Eigen::Vector3d& half_extents,
                         const Eigen::Isometry3d& plane_pose, int pair,
                         std::vector<ContactPoint>& out) {
  const Eigen::Vector3d n = plane_pose.linear().col(2);
  const double offset = n.dot(plane_pose.translation());
  int added = 0;
  for (int k = 0; k < 8; ++k) {
    const Eigen::Vector3d local((k & 1) ? half_extents.x() : -half_extents.x(),
                                (k & 2) ? half_extents.y() : -half_extents.y(),
                                (k & 4) ? half_extents.z() : -half_extents.z());
    const Eigen::Vector3d corner = box_pose * local;
    const double depth = offset - n.dot(corner);
    if (depth <= 0.0) continue;
    ContactPoint cp;
    cp.pair = pair;
    cp.position = corner + 0.5 * depth * n;
    cp.normal = n;
    cp.depth = depth;
    out.push_back(cp);
    ++added;
  }
  return added;
}

}  // namespace tribo::contact
