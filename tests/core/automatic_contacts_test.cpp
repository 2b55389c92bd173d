// Automatic contacts on demand (core/automatic_contacts.hpp): the rule's pairs against a
// brute-force reading of the documented rule over random models of several sizes; a run
// with automatic contacts against the same run with every pair listed, bit for bit; memory
// of model and detector set-up linear in the geometries (heap bytes counted by a replaced
// operator new: a 16-fold grid may take at most twice the bytes per box of the small one,
// where a record per geometry pair would take 16 times); the errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>
#include <new>
#include <random>
#include <tuple>
#include <utility>
#include <vector>

#include "core/dynamics.hpp"
#include "core/model_builder.hpp"
#include "core/simulator.hpp"

namespace {

std::atomic<bool> counting{false};
std::atomic<std::size_t> counted_bytes{0};

}  // namespace

// GCC sees std::free applied to what operator new returned once it inlines them and warns
// (-Wmismatched-new-delete); here the pairing is by design, every new below is malloc.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpragmas"
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void* operator new(std::size_t size) {
  if (counting.load(std::memory_order_relaxed))
    counted_bytes.fetch_add(size, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return operator new(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  if (counting.load(std::memory_order_relaxed))
    counted_bytes.fetch_add(size, std::memory_order_relaxed);
  return std::malloc(size == 0 ? 1 : size);
}
void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept {
  return operator new(size, tag);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
#pragma GCC diagnostic pop

namespace tribo {
namespace {

std::string numbered(const char* prefix, int i) {
  std::string name = prefix;
  name += std::to_string(i);
  return name;
}

contact::Material material(double mu, double stiffness = 1e5) {
  contact::Material m;
  m.normal = {contact::NormalLawType::kLinear, stiffness, 2e-3 * stiffness};
  m.friction = friction::makeFrictionLaw({"coulomb", {{"mu", mu}, {"v_eps", 0.01}}, {}});
  return m;
}

struct Reference {
  int a, b, material;
  bool operator==(const Reference&) const = default;
};

// The documented rule, read directly off the geometries (no shared code with the engine).
std::vector<Reference> referencePairs(
    const Model& m, const std::map<std::pair<std::string, std::string>, int>& by_surface,
    int fallback) {
  std::vector<Reference> out;
  const int n = static_cast<int>(m.geometries.size());
  auto dynamic = [&](const Geometry& g) {
    return !g.body.isWorld() && m.bodies[g.body.value].kind == BodyKind::kDynamic;
  };
  auto plane = [](const Geometry& g) { return g.shape.type == contact::ShapeType::kHalfSpace; };
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      const Geometry& g = m.geometries[i];
      const Geometry& h = m.geometries[j];
      if (g.body == h.body || (!dynamic(g) && !dynamic(h)) || (plane(g) && plane(h))) continue;
      if ((g.collision_group & h.collision_mask) == 0 ||
          (h.collision_group & g.collision_mask) == 0)
        continue;
      bool joined = false;
      for (const Joint& jt : m.joints)
        joined = joined || (jt.parent == g.body && jt.child == h.body) ||
                 (jt.parent == h.body && jt.child == g.body);
      if (joined && !m.options.collision.joined_bodies_collide) continue;
      int mat = fallback;
      if (auto it = by_surface.find({g.surface, h.surface}); it != by_surface.end())
        mat = it->second;
      if (auto it = by_surface.find({h.surface, g.surface}); it != by_surface.end())
        mat = it->second;
      // B: the dynamic one when only one is; A the half-space when there is one; else h.
      const bool swap = dynamic(g) && (!dynamic(h) || (!plane(g) && plane(h)));
      out.push_back(swap ? Reference{j, i, mat} : Reference{i, j, mat});
    }
  return out;
}

struct RandomModel {
  std::shared_ptr<const Model> model;
  std::map<std::pair<std::string, std::string>, int> by_surface;
  int fallback = -1;
};

RandomModel randomModel(int geometries, unsigned seed, bool joined_collide) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  ModelBuilder b;
  b.options().collision.joined_bodies_collide = joined_collide;
  RandomModel out;
  const int m0 = b.addMaterial(material(0.3));
  const int m1 = b.addMaterial(material(0.6));
  b.addSurfacePairMaterial("steel", "rubber", m1);
  out.by_surface[{"steel", "rubber"}] = m1;
  b.setDefaultMaterial(m0);
  out.fallback = m0;
  std::vector<BodyIndex> bodies = {BodyIndex::world()};
  std::vector<bool> moves = {false};  // dynamic
  const char* surfaces[] = {"steel", "rubber", "wood"};
  const std::uint32_t groups[] = {1u, 2u, 3u, 0xffffffffu};
  for (int g = 0; g < geometries; ++g) {
    // A new body (dynamic 4 in 5, kinematic else) or one of the bodies so far.
    BodyIndex body = bodies[static_cast<std::size_t>(unit(rng) * bodies.size())];
    if (unit(rng) < 0.7) {
      Body nb;
      nb.name = numbered("b", g);
      nb.mass = 0.01 + 100 * unit(rng);
      nb.kind = unit(rng) < 0.8 ? BodyKind::kDynamic : BodyKind::kKinematic;
      nb.position = Vec3(unit(rng), unit(rng), 1 + unit(rng));
      body = b.addBody(nb);
      bodies.push_back(body);
      moves.push_back(nb.kind == BodyKind::kDynamic);
    }
    const contact::Shape shape = unit(rng) < 0.1   ? contact::Shape::halfSpace()
                                 : unit(rng) < 0.5 ? contact::Shape::sphere(0.01 + unit(rng))
                                                   : contact::Shape::box(Vec3(0.1, 0.2, 0.3));
    const int id = b.addGeometry(numbered("g", g), body, shape);
    b.setGeometrySurface(id, surfaces[rng() % 3]);
    if (unit(rng) < 0.5) b.setCollisionFilter(id, groups[rng() % 4], groups[rng() % 4]);
  }
  for (int j = 0; j < geometries / 6; ++j) {  // joints between random distinct bodies
    const std::size_t child = rng() % bodies.size();
    const BodyIndex p = bodies[rng() % bodies.size()], c = bodies[child];
    if (p == c || !moves[child]) continue;
    bool taken = false;  // one joint per child
    for (const Joint& jt : b.joints()) taken = taken || jt.child == c;
    if (taken) continue;
    b.addJoint(numbered("j", j), JointType::kSpherical, p, c, Vec3(0, 0, 1), Vec3::UnitZ());
  }
  b.options().constraints.redundant = RedundancyPolicy::kRemove;
  out.model = b.build();
  return out;
}

TEST(AutomaticContacts, PairsFollowTheDocumentedRuleOverRandomModels) {
  int checked = 0;
  for (int n : {4, 25, 120, 300})
    for (unsigned seed = 1; seed <= 6; ++seed)
      for (bool joined : {false, true}) {
        RandomModel r;
        try {
          r = randomModel(n, seed * 7919u + static_cast<unsigned>(n), joined);
        } catch (const ModelError& e) {
          std::cerr << e.what() << "\n";
          continue;  // a random joint set the builder refuses (a loop it cannot close)
        }
        const Model& m = *r.model;
        ASSERT_TRUE(m.automatic_contacts);
        EXPECT_TRUE(m.contact_pairs.empty());
        const std::vector<Reference> expected = referencePairs(m, r.by_surface, r.fallback);
        std::vector<Reference> got;
        for (const ContactPair& p : allAutomaticPairs(m))
          got.push_back({p.geometry_a, p.geometry_b, p.material});
        ASSERT_EQ(got, expected) << "n " << n << " seed " << seed;
        // Every id the rule gives names its pair; representatives are among all pairs.
        for (int g = 0; g < n; ++g)
          for (int h = 0; h < n; ++h) {
            const int id = automaticPairId(m, g, h);
            if (id < 0) continue;
            const ContactPair p = m.contactPair(id);
            EXPECT_TRUE((p.geometry_a == g && p.geometry_b == h) ||
                        (p.geometry_a == h && p.geometry_b == g));
            EXPECT_EQ(id, automaticPairId(m, h, g));
          }
        for (const ContactPair& p : representativeAutomaticPairs(m))
          EXPECT_NE(std::find(expected.begin(), expected.end(),
                              Reference{p.geometry_a, p.geometry_b, p.material}),
                    expected.end());
        ++checked;
      }
  EXPECT_GT(checked, 30);
}

// A surface per link, as a URDF robot has (io/urdf_model.cpp): every link's pair with the
// ground has its own material, some link pairs one of theirs, the rest the default. The
// materials follow the documented rule at every size; with the robot's filter (its links
// leave each other out) the stable step's representatives are exactly the links on the
// ground, and with self-collision each link also meets a lighter link.
TEST(AutomaticContacts, ASurfacePerLinkGetsEachPairsMaterialAtEverySize) {
  for (const int links : {3, 40, 400}) {
    for (const bool self_collision : {false, true}) {
      ModelBuilder b;
      std::map<std::pair<std::string, std::string>, int> by_surface;
      const int fallback = b.addMaterial(material(0.2));
      b.setDefaultMaterial(fallback);
      b.setGeometrySurface(b.addGeometry("ground", BodyIndex::world(), contact::Shape::halfSpace()),
                           "ground");
      for (int i = 0; i < links; ++i) {
        Body body;
        body.name = numbered("link", i);
        body.mass = 1.0 + i;
        body.position = Vec3(0.3 * i, 0, 0.5);
        const int g = b.addGeometry(numbered("box", i), b.addBody(body),
                                    contact::Shape::box(Vec3(0.1, 0.1, 0.1)));
        const std::string surface = numbered("link", i);
        b.setGeometrySurface(g, surface);
        if (!self_collision) b.setCollisionFilter(g, 2u, ~2u);
        const int mine = b.addMaterial(material(0.3 + 0.001 * i));
        b.addSurfacePairMaterial(surface, "ground", mine);
        by_surface[{surface, "ground"}] = mine;
        if (i % 7 == 3) {  // one pair between links, given in either order
          const int between = b.addMaterial(material(0.9));
          const std::string other = numbered("link", i - 1);
          if (i % 2)
            b.addSurfacePairMaterial(other, surface, between);
          else
            b.addSurfacePairMaterial(surface, other, between);
          by_surface[{other, surface}] = between;
        }
      }
      EXPECT_THROW(b.addSurfacePairMaterial("ground", "link0", fallback), ModelError);
      const auto model = b.build();
      const std::vector<Reference> expected = referencePairs(*model, by_surface, fallback);
      std::vector<Reference> got;
      for (const ContactPair& p : allAutomaticPairs(*model))
        got.push_back({p.geometry_a, p.geometry_b, p.material});
      ASSERT_EQ(got, expected) << links << " links, self-collision " << self_collision;
      const std::vector<ContactPair> representatives = representativeAutomaticPairs(*model);
      int on_ground = 0, between_links = 0;
      for (const ContactPair& p : representatives) {
        EXPECT_NE(std::find(expected.begin(), expected.end(),
                            Reference{p.geometry_a, p.geometry_b, p.material}),
                  expected.end());
        (p.geometry_a == 0 ? on_ground : between_links) += 1;
      }
      EXPECT_EQ(on_ground, links);
      if (self_collision)
        EXPECT_GE(between_links, links - 1);  // each link with the lightest other one at least
      else
        EXPECT_EQ(between_links, 0);
    }
  }
}

// A pile of boxes and spheres of several sizes and masses dropped on the ground and on each
// other; `listed` gives every pair the rule gives, in the same order, as listed contacts.
std::shared_ptr<const Model> pile(int count, double size, bool listed) {
  ModelBuilder b;
  b.options().integrator = IntegratorType::kSemiImplicitEuler;
  b.options().time_step = 2e-4;
  b.options().collision.broadphase = true;
  // Contact stiffness from the typical mass: 50 Hz on a point, well resolved at the step.
  const double typical_mass = 1000.0 * std::pow(0.8 * size, 3);
  const int mat = b.addMaterial(material(0.4, typical_mass * std::pow(2 * M_PI * 50, 2)));
  b.setDefaultMaterial(mat);
  b.addGeometry("ground", BodyIndex::world(), contact::Shape::halfSpace());
  for (int i = 0; i < count; ++i) {
    Body body;
    body.name = numbered("p", i);
    const double s = size * (0.6 + 0.1 * (i % 5));
    body.mass = 1000.0 * s * s * s;
    body.inertia = Mat3::Identity() * body.mass * s * s / 6.0;
    // 2 x 2 per layer, 1.4 sizes apart; each layer shifted half a pitch onto the one below.
    const int layer = i / 4;
    const double shift = 0.7 * size * (layer % 2);
    body.position = Vec3(size * 1.4 * (i % 2) + shift, size * 1.4 * ((i / 2) % 2) + shift,
                         size * (1 + 1.9 * layer));
    body.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.3 * i, Vec3(1, 2, 3).normalized()));
    b.addGeometry(
        numbered("s", i), b.addBody(body),
        i % 2 ? contact::Shape::sphere(s / 2) : contact::Shape::box(Vec3::Constant(s / 2)));
  }
  std::shared_ptr<const Model> automatic = b.build();
  if (!listed) return automatic;
  ModelBuilder again = b;
  for (const ContactPair& p : allAutomaticPairs(*automatic))
    again.addContactPair(p.geometry_a, p.geometry_b, p.material);
  return again.build();
}

TEST(AutomaticContacts, RunsBitForBitAsTheSamePairsListed) {
  for (auto [count, size] : {std::pair{6, 0.01}, {12, 0.2}, {16, 1.0}}) {
    const auto automatic = pile(count, size, false);
    const auto listed = pile(count, size, true);
    ASSERT_TRUE(automatic->automatic_contacts);
    ASSERT_FALSE(listed->automatic_contacts);
    ASSERT_EQ(listed->contact_pairs.size(), allAutomaticPairs(*automatic).size());
    Simulator a(automatic), l(listed);
    std::size_t touched = 0, among = 0;  // points; points between two bodies
    for (int i = 0; i < 6000; ++i) {
      const auto status = a.step();
      ASSERT_TRUE(status.ok) << status.message;
      ASSERT_TRUE(l.step().ok);
      ASSERT_EQ(a.current().contacts.size(), l.current().contacts.size()) << i;
      touched = std::max(touched, a.current().contacts.size());
      for (const auto& c : a.current().contacts)
        among += automatic->contactPair(c.point.pair).geometry_a != 0 ? 1 : 0;
    }
    EXPECT_GE(touched, static_cast<std::size_t>(count / 2)) << "the pile comes to the ground";
    EXPECT_GT(among, 100u) << "the bodies touch each other";
    for (std::size_t k = 0; k < automatic->bodies.size(); ++k) {
      EXPECT_EQ(a.state().bodies[k].position, l.state().bodies[k].position) << k;
      EXPECT_EQ(a.state().bodies[k].velocity, l.state().bodies[k].velocity) << k;
      EXPECT_EQ(a.state().bodies[k].orientation.coeffs(), l.state().bodies[k].orientation.coeffs());
    }
  }
}

// Spheres of three surfaces (three materials between them, the fallback for the rest) dropped
// in a column that topples onto the ground: contacts come and go every few steps. Each point's
// pair, which a step takes from the last detection's pairs when it had the id
// (core/dynamics.cpp), is at every step the documented rule's pair for its geometries
// (referencePairs) and the model's pair for its id.
TEST(AutomaticContacts, EveryPointsPairIsTheRulesAsContactsComeAndGo) {
  ModelBuilder b;
  b.options().integrator = IntegratorType::kSemiImplicitEuler;
  b.options().time_step = 2e-4;
  b.options().collision.broadphase = true;
  std::map<std::pair<std::string, std::string>, int> by_surface;
  const int fallback = b.addMaterial(material(0.3, 2e4));
  b.setDefaultMaterial(fallback);
  const char* surfaces[] = {"steel", "rubber", "wood"};
  for (const auto& [x, y, mu] :
       {std::tuple{"steel", "rubber", 0.6}, {"wood", "wood", 0.5}, {"rubber", "ground", 0.9}}) {
    const int mat = b.addMaterial(material(mu, 2e4));
    b.addSurfacePairMaterial(x, y, mat);
    by_surface[{x, y}] = mat;
  }
  b.setGeometrySurface(b.addGeometry("ground", BodyIndex::world(), contact::Shape::halfSpace()),
                       "ground");
  for (int i = 0; i < 24; ++i) {
    Body body;
    body.name = numbered("p", i);
    body.mass = 0.5 + 0.1 * (i % 4);
    body.inertia = Mat3::Identity() * 0.4 * body.mass * 0.05 * 0.05;
    body.position = Vec3(0.02 * std::sin(1.3 * i), 0.02 * std::cos(0.7 * i), 0.06 + 0.11 * i);
    const int g = b.addGeometry(numbered("s", i), b.addBody(body), contact::Shape::sphere(0.05));
    b.setGeometrySurface(g, surfaces[i % 3]);
  }
  const auto model = b.build();
  const std::vector<Reference> rule = referencePairs(*model, by_surface, fallback);
  Simulator sim(model);
  std::vector<int> last_ids;
  int changes = 0;
  std::size_t points = 0, between_spheres = 0, not_fallback = 0;
  for (int step = 0; step < 5000; ++step) {
    ASSERT_TRUE(sim.step().ok) << step;
    const Workspace& ws = sim.current();
    ASSERT_EQ(ws.contact_pair.size(), ws.contacts.size());
    std::vector<int> ids;
    for (std::size_t i = 0; i < ws.contacts.size(); ++i) {
      const int id = ws.contacts[i].point.pair;
      const ContactPair& p = ws.contact_pair[i];
      const Reference got{p.geometry_a, p.geometry_b, p.material};
      ASSERT_NE(std::find(rule.begin(), rule.end(), got), rule.end())
          << "step " << step << " point " << i << ": geometries " << got.a << ", " << got.b
          << ", material " << got.material;
      const ContactPair direct = model->contactPair(id);
      ASSERT_EQ(got, (Reference{direct.geometry_a, direct.geometry_b, direct.material})) << step;
      ids.push_back(id);
      between_spheres += p.geometry_a != 0;
      not_fallback += p.material != fallback;
    }
    changes += ids != last_ids;
    points += ids.size();
    last_ids = std::move(ids);
  }
  EXPECT_GT(changes, 100) << "contacts came and went";
  EXPECT_GT(between_spheres, 1000u);
  EXPECT_GT(not_fallback, 1000u);
  EXPECT_GT(points, 20000u);
}

std::size_t bytesToSetUp(int side) {
  ModelBuilder b;
  const int mat = b.addMaterial(material(0.5));
  b.setDefaultMaterial(mat);
  b.addGeometry("ground", BodyIndex::world(), contact::Shape::halfSpace());
  for (int i = 0; i < side * side; ++i) {
    Body body;
    body.name = numbered("b", i);
    body.mass = 8;
    body.position = Vec3(0.25 * (i % side), 0.25 * (i / side), 0.1);
    b.addGeometry(numbered("s", i), b.addBody(body), contact::Shape::box(Vec3::Constant(0.1)));
  }
  counted_bytes = 0;
  counting = true;
  {
    const std::shared_ptr<const Model> model = b.build();
    Dynamics dynamics(model);
    State s = dynamics.initialState();
    dynamics.evaluate(s);
  }
  counting = false;
  return counted_bytes.load();
}

TEST(AutomaticContacts, SetUpMemoryGrowsLinearlyWithTheBoxes) {
  const double small = static_cast<double>(bytesToSetUp(10)) / 100.0;
  const double large = static_cast<double>(bytesToSetUp(40)) / 1600.0;
  // Quadratic bookkeeping would take 16 times the bytes per box at 1600 boxes.
  EXPECT_LT(large, 2.0 * small) << small << " vs " << large << " bytes per box";
}

TEST(AutomaticContacts, TooManyGeometriesAndMissingMaterialsAreNamed) {
  ModelBuilder b;
  const int mat = b.addMaterial(material(0.5));
  b.setDefaultMaterial(mat);
  Body body;
  body.name = "many";
  const BodyIndex one = b.addBody(body);
  for (int i = 0; i <= kMaxAutomaticGeometries; ++i)
    b.addGeometry(numbered("s", i), one, contact::Shape::sphere(0.1));
  try {
    b.build();
    FAIL() << "46341 geometries built";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("46341 geometries"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("list the contacts"), std::string::npos) << e.what();
  }

  ModelBuilder c;  // steel meets wood with no material for that pair and no default
  const int m1 = c.addMaterial(material(0.5));
  c.addSurfacePairMaterial("steel", "steel", m1);
  const std::vector<std::pair<std::string, std::string>> parts = {
      {"one", "steel"}, {"two", "steel"}, {"three", "wood"}};
  for (const auto& [name, surface] : parts) {
    Body x;
    x.name = name;
    c.setGeometrySurface(c.addGeometry(name + "_g", c.addBody(x), contact::Shape::sphere(0.1)),
                         surface);
  }
  try {
    c.build();
    FAIL() << "built without a steel/wood material";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("no material for surfaces ('steel', 'wood')"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace tribo
