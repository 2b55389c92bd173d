#include "contact/box_box_contacts.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace tribo::contact {

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

constexpr double kFaceBias = 0.98;  // a face of B must beat a face of A by 2 %
constexpr double kEdgeBias = 0.95;  // an edge pair must beat the face by 5 %
constexpr double kParallel = 1e-6;  // |A_i x B_j| below this: no edge axis (faces cover it)
constexpr double kFlush = 1e-9;     // a vertex this far (times the box size) outside is on
constexpr int kReferenceOnB = 64;
constexpr int kEdgeFeature = 128;

// Signs of the incident quad's corners along its two edge directions, in loop order.
constexpr std::array<double, 4> kS1{1, -1, -1, 1}, kS2{1, 1, -1, -1};

// One vertex of the clipped incident polygon, in the reference box's frame: its feature and
// the tag of the polygon edge leaving it (0-3: incident face edge, 4 + p: on side plane p).
struct Vertex {
  Vector3d x;
  int feature;
  int edge;
};
// A quad clipped by 4 planes has at most 8 vertices; room for rounding to add more.
constexpr int kMaxVertices = 16;
using Polygon = std::array<Vertex, kMaxVertices>;

// Sutherland-Hodgman against the side plane sign * x[axis] <= limit (plane index p). A vertex
// less than `tol` outside counts as on the plane: boxes of the same size stacked flush would
// otherwise have each corner split by rounding into two points a few ulp apart.
int clipSide(const Polygon& in, int n, int axis, double sign, double limit, double tol, int p,
             Polygon& out) {
  int m = 0;
  for (int i = 0; i < n; ++i) {
    const Vertex& v = in[i];
    const Vertex& w = in[i + 1 < n ? i + 1 : 0];
    const double dv = limit - sign * v.x[axis], dw = limit - sign * w.x[axis];
    const bool v_in = dv >= -tol, w_in = dw >= -tol;
    if (m + 2 > kMaxVertices) break;
    if (v_in) {
      out[m++] = v;
      if (w_in) continue;
    } else if (!w_in) {
      continue;
    }
    // The edge crosses the plane: the crossing's feature is the incident edge cut by the
    // plane, or, for an edge already on side plane q, the reference corner of planes q and p.
    const double f = dv / (dv - dw);
    const int feature = v.edge < 4 ? 8 + 4 * v.edge + p
                                   : 24 + 4 * std::min(v.edge - 4, p) + std::max(v.edge - 4, p);
    out[m++] = {v.x + f * (w.x - v.x), feature, v_in ? 4 + p : v.edge};
  }
  return m;
}

int faceContacts(const Eigen::Isometry3d& ref_pose, const Vector3d& hr, const Matrix3d& axes,
                 const Vector3d& centre, const Vector3d& hi, int k, bool ref_is_b, int pair,
                 std::vector<ContactPoint>& out) {
  // Everything in the reference box's frame: `axes` are the incident box's axes, `centre`
  // its centre. u = sg e_k points from the reference box towards the incident one.
  const double sg = centre[k] >= 0.0 ? 1.0 : -1.0;
  int m = 0;
  (axes.row(k).cwiseAbs()).maxCoeff(&m);
  const double si = axes(k, m) * sg > 0.0 ? -1.0 : 1.0;  // incident face normal si * axes.col(m)
  const int m1 = (m + 1) % 3, m2 = (m + 2) % 3;
  const Vector3d face = centre + si * hi[m] * axes.col(m);
  const Vector3d e1 = hi[m1] * axes.col(m1), e2 = hi[m2] * axes.col(m2);
  Polygon a, b;  // not zeroed (1 kB): a vertex is read only after it is written
  for (int v = 0; v < 4; ++v) {
    const int corner = ((si > 0) << m) | ((kS1[v] > 0) << m1) | ((kS2[v] > 0) << m2);
    a[v] = {face + kS1[v] * e1 + kS2[v] * e2, corner, v};
  }
  int n = 4;
  const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
  const double tol = kFlush * hr.maxCoeff();
  // A quad with every corner within the four side planes (a box resting inside a larger
  // face) comes out of the four clips as it went in: they are skipped, by the clips' own test.
  bool inside = true;
  for (int v = 0; v < 4; ++v)
    for (const int axis : {k1, k2})
      for (const double sign : {1.0, -1.0})
        inside = inside && hr[axis] - sign * a[v].x[axis] >= -tol;
  if (!inside) {
    n = clipSide(a, n, k1, 1.0, hr[k1], tol, 0, b);
    n = clipSide(b, n, k1, -1.0, hr[k1], tol, 1, a);
    n = clipSide(a, n, k2, 1.0, hr[k2], tol, 2, b);
    n = clipSide(b, n, k2, -1.0, hr[k2], tol, 3, a);
  }
  const Vector3d u_world = sg * ref_pose.linear().col(k);
  int added = 0;
  for (int i = 0; i < n; ++i) {
    const double depth = hr[k] - sg * a[i].x[k];
    if (!(depth > 0.0)) continue;
    Vector3d x = a[i].x;
    x[k] += 0.5 * depth * sg;
    ContactPoint& cp = out.emplace_back();
    cp.pair = pair;
    cp.feature = a[i].feature + (ref_is_b ? kReferenceOnB : 0);
    cp.position = ref_pose * x;
    cp.normal = ref_is_b ? Vector3d(-u_world) : u_world;
    cp.depth = depth;
    ++added;
  }
  return added;
}

}  // namespace

void closestOnSegments(const Vector3d& p, const Vector3d& d, double hp, const Vector3d& q,
                       const Vector3d& e, double hq, Vector3d& cp, Vector3d& cq) {
  const Vector3d r = p - q;
  const double b = d.dot(e), c = d.dot(r), f = e.dot(r);
  const double denom = 1.0 - b * b;
  double s = denom > 1e-12 ? std::clamp((b * f - c) / denom, -hp, hp) : 0.0;
  double t = std::clamp(b * s + f, -hq, hq);
  s = std::clamp(b * t - c, -hp, hp);
  cp = p + s * d;
  cq = q + t * e;
}

void thinSmallManifold(std::vector<ContactPoint>& out, std::size_t first, int max_points) {
  const std::size_t n = out.size() - first;
  if (max_points <= 0 || n <= static_cast<std::size_t>(max_points) || n > 16) return;
  // Order out[first..] so the kept points come first: selection in place.
  std::array<double, 16> dist;
  dist.fill(std::numeric_limits<double>::infinity());
  auto at = [&](std::size_t i) -> ContactPoint& { return out[first + i]; };
  std::size_t pick = 0;
  for (std::size_t i = 1; i < n; ++i)
    if (at(i).depth > at(pick).depth) pick = i;
  for (std::size_t k = 0; k < static_cast<std::size_t>(max_points); ++k) {
    std::swap(at(k), at(pick));
    std::swap(dist[k], dist[pick]);
    double best = -1.0;
    for (std::size_t i = k + 1; i < n; ++i) {
      dist[i] = std::min(dist[i], (at(i).position - at(k).position).squaredNorm());
      if (dist[i] > best) best = dist[i], pick = i;
    }
  }
  out.resize(first + static_cast<std::size_t>(max_points));
}

int boxBoxContacts(const Eigen::Isometry3d& pose_a, const Vector3d& ha,
                   const Eigen::Isometry3d& pose_b, const Vector3d& hb, int pair, int max_points,
                   std::vector<ContactPoint>& out) {
  const Matrix3d& ra = pose_a.linear();
  const Matrix3d r = ra.transpose() * pose_b.linear();  // column j: B's axis j in A's frame
  const Vector3d t = ra.transpose() * (pose_b.translation() - pose_a.translation());
  const Matrix3d abs_r = r.cwiseAbs();

  // Faces of A, faces of B: the separation along each; the largest of each family.
  int face_a = 0, face_b = 0;
  double s_a = -std::numeric_limits<double>::infinity(), s_b = s_a;
  for (int k = 0; k < 3; ++k) {
    const double s = std::abs(t[k]) - (ha[k] + hb.dot(abs_r.row(k)));
    if (s >= 0.0) return 0;
    if (s > s_a) s_a = s, face_a = k;
  }
  for (int k = 0; k < 3; ++k) {
    const double s = std::abs(t.dot(r.col(k))) - (hb[k] + ha.dot(abs_r.col(k)));
    if (s >= 0.0) return 0;
    if (s > s_b) s_b = s, face_b = k;
  }
  // Edge pairs: L = A_i x B_j, in A's frame L[i1] = -R(i2, j), L[i2] = R(i1, j). Each pair's
  // separation is gap / |L| with |L| <= 1 (entries of a rotation: no overflow, so a square
  // root, not hypot); the largest is found without dividing, gap * |L_best| > gap_best * |L|
  // (both lengths positive), and divided out once.
  constexpr std::array<int, 3> kNext{1, 2, 0}, kPrev{2, 0, 1};
  int edge_i = -1, edge_j = -1;
  double gap_e = -1.0, len_e = 1.0;
  for (int i = 0; i < 3; ++i) {
    const int i1 = kNext[i], i2 = kPrev[i];
    for (int j = 0; j < 3; ++j) {
      const int j1 = kNext[j], j2 = kPrev[j];
      const double len = std::sqrt(r(i1, j) * r(i1, j) + r(i2, j) * r(i2, j));
      if (len < kParallel) continue;
      const double ra_l = ha[i1] * abs_r(i2, j) + ha[i2] * abs_r(i1, j);
      const double rb_l = hb[j1] * abs_r(i, j2) + hb[j2] * abs_r(i, j1);
      const double tl = t[i2] * r(i1, j) - t[i1] * r(i2, j);
      const double gap = std::abs(tl) - ra_l - rb_l;
      if (gap >= 0.0) return 0;
      if (edge_i < 0 || gap * len_e > gap_e * len) gap_e = gap, len_e = len, edge_i = i, edge_j = j;
    }
  }
  const double s_e = edge_i >= 0 ? gap_e / len_e : -std::numeric_limits<double>::infinity();

  const bool ref_is_b = s_b > kFaceBias * s_a;
  const double s_face = ref_is_b ? s_b : s_a;
  const std::size_t first = out.size();
  if (!(edge_i >= 0 && s_e > kEdgeBias * s_face)) {
    const int added = ref_is_b ? faceContacts(pose_b, hb, r.transpose(), -(r.transpose() * t), ha,
                                              face_b, true, pair, out)
                               : faceContacts(pose_a, ha, r, t, hb, face_a, false, pair, out);
    if (added > 0) {
      thinSmallManifold(out, first, max_points);
      return static_cast<int>(out.size() - first);
    }
    if (edge_i < 0) return 0;  // nothing below the face after clipping (a grazing touch)
  }
  // Edge pair (i, j): the edge of A parallel to A_i farthest along n, the edge of B parallel
  // to B_j farthest along -n, in A's frame.
  const int i = edge_i, j = edge_j;
  Vector3d n = Vector3d::Zero();
  n[(i + 1) % 3] = -r((i + 2) % 3, j);
  n[(i + 2) % 3] = r((i + 1) % 3, j);
  n.normalize();
  if (n.dot(t) < 0.0) n = -n;
  Vector3d pa = Vector3d::Zero();
  for (int k = 0; k < 3; ++k)
    if (k != i) pa[k] = n[k] >= 0.0 ? ha[k] : -ha[k];
  Vector3d pb = t;
  for (int k = 0; k < 3; ++k)
    if (k != j) pb -= (n.dot(r.col(k)) >= 0.0 ? hb[k] : -hb[k]) * r.col(k);
  Vector3d ca, cb;
  closestOnSegments(pa, Vector3d::Unit(i), ha[i], pb, r.col(j), hb[j], ca, cb);
  ContactPoint& cp = out.emplace_back();
  cp.pair = pair;
  cp.feature = kEdgeFeature + 3 * i + j;
  cp.position = pose_a * (0.5 * (ca + cb));
  cp.normal = ra * n;
  cp.depth = -s_e;
  return 1;
}

}  // namespace tribo::contact
