// Collision detection over a fixed set of geometries and their pairs: the one place FCL is
// used (behind a pimpl, so no FCL type leaks into Tribo headers), for the narrowphase only. Pairs
// are either listed (pair id = index in the list) or decided on demand by a PairRule (automatic
// contacts): then only the pairs the broadphase reports close are looked at, and nothing is kept
// per geometry pair, so memory and set-up are linear in the geometries.
//
// Each pair (A, B) yields contact points with the normal from A into B. Pairs with a closed
// form (contact/primitive_contacts.hpp: any shape on a half-space, sphere/sphere,
// sphere/box; contact/box_box_contacts.hpp: box/box; contact/box_round_contacts.hpp:
// capsule/box, and cylinder/box where the cylinder rests on one face;
// contact/round_contacts.hpp: sphere/capsule, capsule/capsule) use it unless switched off;
// every other pair (cylinder, cone, convex and triangle meshes with each other and with
// spheres and capsules, a cylinder over a box edge) goes to FCL's narrowphase (libccd GJK/EPA,
// FCL's box/box manifold when the closed forms are off, BVH traversal for meshes), at most
// `max_points_per_pair` points. A convex mesh with a box or a convex mesh grows EPA's single
// point into the face manifold (contact/polyhedron_contacts.hpp) unless switched off. With
// `broadphase` on, a hashed uniform grid culls the pairs first (contact/broadphase.hpp);
// half-spaces stay out of it (their box is infinite) and their pairs are always tested.
// The grid runs on the geometries' tight world boxes each grown by a skin on every side
// (`broadphase_skin` times the median box's largest extent, fixed at the first call); when
// these fat boxes are of about one size (the largest within 1.5 times the first median: a
// pile, a chute) the cell list of contact/cell_list.hpp pairs them instead, with the same
// answer. The pairs reported, filtered by the list or the rule, are kept with the half-space pairs
// sorted by pair id: a Verlet neighbour list (Verlet, Phys. Rev. 159, 98 (1967); LAMMPS's
// neighbor skin), reused for as long as every tight box lies inside its grown box and
// rebuilt on the call where one does not (a NaN box never does). A call then computes the
// tight boxes and runs the narrowphase on the kept pairs whose tight boxes overlap: exactly
// the pairs the grid on the tight boxes reports, in the same order, so the points are the
// same bit for bit as with `broadphase_skin` 0 (the grid on the tight boxes every call).
// The skin (a tenth of the median box) was chosen by measurement on a falling sphere pile,
// a resting box grid and a sphere chute (bench/contact/detect_skin_bench.cpp,
// docs/performance.md). FCL objects exist only for geometries its narrowphase
// may be asked about: a scene of boxes, spheres, capsules and half-spaces never calls FCL.
// Does not allocate once its buffers have grown to their working size; FCL's narrowphase
// may (libccd's EPA, the box/box manifold), which a test hook brackets.
// Not here: forces, materials, which pairs exist (the model builder), contact identity
// between steps (contact/stick_anchor.hpp), a per-body update of the kept list (one box
// leaving its grown box rebuilds the whole list), continuous (swept) detection.
#pragma once

#include <Eigen/Geometry>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "contact/contact_point.hpp"
#include "contact/primitive_contacts.hpp"
#include "contact/query_watchdog.hpp"
#include "contact/shape.hpp"

namespace tribo::contact {

struct CollisionOptions {
  bool broadphase = false;  // cull pairs with the grid (contact/broadphase.hpp)
  // With the broadphase: the skin of the cached pair list (a Verlet list), a fraction of the
  // median geometry's largest extent added to each side of every box; the list is rebuilt
  // when a tight box leaves its grown box. 0: no list, the grid runs on every call. The same
  // contact points either way.
  double broadphase_skin = 0.1;
  bool closed_form_box_halfspace = true;  // exact corners instead of FCL's single point
  // Other closed forms: primitive_contacts.hpp, box/box (box_box_contacts.hpp), capsule/box and
  // cylinder/box (box_round_contacts.hpp), sphere/capsule and capsule/capsule
  // (round_contacts.hpp). Off: those pairs go to FCL.
  bool closed_form_primitives = true;
  // Convex meshes resting on boxes or on each other: the face manifold around FCL's single
  // GJK/EPA point (contact/polyhedron_contacts.hpp).
  bool polyhedron_manifold = true;
  int max_points_per_pair = 8;
  // Automatic pairs (a scene that lists no contacts): do bodies joined by a joint collide?
  bool joined_bodies_collide = false;
  // Contact identity for stateful friction when the narrowphase gives no feature id: a
  // contact continues the previous step's nearest contact of the same pair within this
  // distance [m] (contact/stick_anchor.hpp).
  double match_radius = 0.01;
  // The longest one FCL narrowphase query may run [s] before the run is ended naming the
  // pair (contact/query_watchdog.hpp; a legitimate query takes microseconds to
  // milliseconds). 0 (or not finite): not watched.
  double query_time_limit = 60.0;
};

// Which two geometries may touch, decided per pair the broadphase reports: their pair id
// (>= 0; ids sort in the order points are produced) or -1, and the id's (A, B).
class PairRule {
 public:
  virtual ~PairRule() = default;
  virtual int pairId(int g, int h) const = 0;
  virtual std::pair<int, int> geometries(int id) const = 0;
};

class CollisionDetector {
 public:
  // Listed pairs. Throws std::invalid_argument for a pair that cannot collide
  // (half-space/half-space), an index out of range or an invalid shape.
  CollisionDetector(std::vector<Shape> shapes, std::vector<std::pair<int, int>> pairs,
                    CollisionOptions options = {});
  // Pairs on demand: the broadphase is always on; a half-space's pairs are always tested.
  CollisionDetector(std::vector<Shape> shapes, std::unique_ptr<const PairRule> rule,
                    CollisionOptions options = {});
  ~CollisionDetector();
  CollisionDetector(CollisionDetector&&) noexcept;
  CollisionDetector& operator=(CollisionDetector&&) noexcept;

  // World poses of all geometries in, contact points out (cleared first), grouped by pair
  // in increasing pair id. Does not allocate once `out` has grown to its working size
  // (FCL's own narrowphase may).
  void detect(std::span<const Eigen::Isometry3d> poses, std::vector<ContactPoint>& out);

  // Threads for the narrowphase (contact/parallel_range.hpp; 1 by default): the candidate
  // pairs are split in contiguous runs, each thread's points joined in pair order, so the
  // output is the same bit for bit for any count. Few candidates use one thread.
  void setThreads(int threads);

  // A time limit on each FCL narrowphase query (contact/query_watchdog.hpp): one that runs
  // longer than `limit_seconds` calls `on_overrun` with the pair's geometries, from a
  // watchdog thread, and that handler must end the process. Started only when some pair can
  // reach FCL's narrowphase (no thread for boxes, spheres and half-spaces with their closed
  // forms); returns whether it was. Call before the first detect(), at most once.
  bool watchQueries(double limit_seconds, QueryWatchdog::OverrunHandler on_overrun);

  // Wall time spent inside FCL's narrowphase since construction [s];
  // measured only when `timing` is on (it costs two clock reads per call).
  void setTiming(bool timing);
  double fclSeconds() const;

  // How many times the skin list was built since construction (0 without the broadphase or
  // with broadphase_skin 0): for tests and benches.
  long skinListBuilds() const;
  // Of those, the builds whose pairs came from the cell list (contact/cell_list.hpp: fat boxes
  // of about one size) rather than the grid.
  long cellListBuilds() const;

  // Test hook, process-wide: when set, called with true right before and false right after
  // every call into FCL's narrowphase collide, so a test can tell FCL's own heap use from
  // Tribo's (tests/core/allocation_test.cpp). Null (the default): nothing is called.
  using FclScopeHook = void (*)(bool inside);
  static void setFclScopeHook(FclScopeHook hook);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tribo::contact
