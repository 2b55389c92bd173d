#include "contact/stick_anchor.hpp"

namespace tribo::contact {

namespace {

Eigen::Vector3d tangential(const Eigen::Vector3d& v, const Eigen::Vector3d& n) {
  return v - n.dot(v) * n;
}

}  // namespace

friction::StickView stickView(const StickAnchor* anchor, const ContactPoint& cp,
                              const AnchorFrames& f, double time) {
  friction::StickView view;
  if (anchor == nullptr) return view;
  const double dt = time - anchor->time;
  const Eigen::Vector3d pa = *f.pose_a * anchor->anchor_a + dt * f.surface_a;
  const Eigen::Vector3d pb = *f.pose_b * anchor->anchor_b + dt * f.surface_b;
  view.anchored = true;
  view.sliding = anchor->sliding;
  view.elongation = tangential(pb - pa, cp.normal);
  return view;
}

StickAnchor anchorAt(std::uint64_t key, const ContactPoint& cp, const AnchorFrames& f, double time,
                     const friction::StickUpdate& update) {
  const Eigen::Vector3d u = tangential(update.elongation, cp.normal);
  StickAnchor a;
  a.key = key;
  a.position = cp.position;
  a.anchor_a = f.pose_a->inverse() * Eigen::Vector3d(cp.position - 0.5 * u);
  a.anchor_b = f.pose_b->inverse() * Eigen::Vector3d(cp.position + 0.5 * u);
  a.time = time;
  a.sliding = update.sliding;
  return a;
}

}  // namespace tribo::contact
