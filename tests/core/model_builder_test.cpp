// ModelBuilder rejects what would make a simulation meaningless, with a message that names
// the element and what was expected.
#include "core/model_builder.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <utility>

#include "support/test_models.hpp"

namespace tribo {
namespace {

Body dynamicBody(const std::string& name) {
  Body b;
  b.name = name;
  b.mass = 1.0;
  b.inertia = Mat3::Identity() * 0.1;
  return b;
}

TEST(ModelBuilder, RejectsBadBodies) {
  ModelBuilder b;
  Body neg = dynamicBody("heavy");
  neg.mass = -1.0;
  EXPECT_NE(test::modelErrorOf([&] { b.addBody(neg); }).find("body 'heavy': mass must be > 0"),
            std::string::npos);
  Body flat = dynamicBody("flat");
  flat.inertia = Vec3(1.0, 1.0, 0.0).asDiagonal();
  EXPECT_NE(test::modelErrorOf([&] { b.addBody(flat); }).find("positive definite"),
            std::string::npos);
  Body tri = dynamicBody("tri");
  tri.inertia = Vec3(1.0, 1.0, 3.0).asDiagonal();
  EXPECT_NE(test::modelErrorOf([&] { b.addBody(tri); }).find("triangle inequality"),
            std::string::npos);
  b.addBody(dynamicBody("a"));
  EXPECT_NE(test::modelErrorOf([&] { b.addBody(dynamicBody("a")); }).find("already exists"),
            std::string::npos);
  EXPECT_NE(test::modelErrorOf([&] { b.addBody(dynamicBody("world")); }).find("not 'world'"),
            std::string::npos);
}

// A builder done with (std::move(builder).build()) gives its model without copying it, and
// reserve() only makes room: the model is the one the copying build() gives, body by body,
// geometry by geometry, with the same automatic contacts and joints.
TEST(ModelBuilder, AMovedOrReservedBuildIsTheCopiedOne) {
  auto make = [](bool reserve) {
    ModelBuilder b;
    b.options().time_step = 1e-3;
    if (reserve) b.reserve(100, 300);
    b.addGeometry("ground", BodyIndex::world(), contact::Shape::halfSpace());
    b.setDefaultMaterial(b.addMaterial(test::coulombMaterial(0.3, 1e5, 50)));
    for (int i = 0; i < 40; ++i) {
      Body d = dynamicBody(std::string("d").append(std::to_string(i)));
      d.position = Vec3(0.3 * i, 1.0, 0.2);
      const BodyIndex id = b.addBody(d);
      b.addGeometry(std::string("g").append(std::to_string(i)), id,
                    contact::Shape::box(Vec3(0.1, 0.1, 0.1)));
    }
    b.addJoint("hinge", JointType::kRevolute, BodyIndex{0}, BodyIndex{1}, Vec3(0.15, 1.0, 0.2),
               Vec3::UnitY());
    return b;
  };
  ModelBuilder copied = make(false), moved = make(true);
  const std::shared_ptr<const Model> a = copied.build();
  const std::shared_ptr<const Model> again = copied.build();  // a copying build keeps it
  const std::shared_ptr<const Model> c = std::move(moved).build();
  for (const Model* m : {again.get(), c.get()}) {
    ASSERT_EQ(m->bodies.size(), a->bodies.size());
    ASSERT_EQ(m->geometries.size(), a->geometries.size());
    for (std::size_t i = 0; i < a->bodies.size(); ++i) {
      EXPECT_EQ(m->bodies[i].name, a->bodies[i].name);
      EXPECT_EQ(m->bodies[i].position, a->bodies[i].position);
      EXPECT_EQ(m->bodies[i].mass, a->bodies[i].mass);
    }
    for (std::size_t i = 0; i < a->geometries.size(); ++i) {
      EXPECT_EQ(m->geometries[i].name, a->geometries[i].name);
      EXPECT_EQ(m->geometries[i].body, a->geometries[i].body);
    }
    EXPECT_EQ(m->joints.size(), a->joints.size());
    EXPECT_EQ(m->constraint_equations, a->constraint_equations);
    EXPECT_EQ(m->automatic_contacts, a->automatic_contacts);
    EXPECT_EQ(m->contact_pairs.size(), a->contact_pairs.size());
  }
  EXPECT_TRUE(a->automatic_contacts);
}

TEST(ModelBuilder, RejectsBadJointsSpringsAndPairs) {
  ModelBuilder b;
  const BodyIndex a = b.addBody(dynamicBody("a"));
  EXPECT_NE(test::modelErrorOf([&] {
              b.addJoint("j", JointType::kRevolute, a, BodyIndex::world(), Vec3::Zero(),
                         Vec3::UnitZ());
            }).find("joint 'j': the child must be a dynamic body"),
            std::string::npos);
  EXPECT_NE(test::modelErrorOf([&] {
              b.addJoint("j", JointType::kRevolute, BodyIndex::world(), a, Vec3::Zero(),
                         Vec3::Zero());
            }).find("axis non-zero"),
            std::string::npos);
  EXPECT_NE(test::modelErrorOf([&] {
              b.addSpring("s", BodyIndex::world(), Vec3::Zero(), a, Vec3::UnitX(), -5, 0, -1);
            }).find("spring 's': stiffness must be >= 0"),
            std::string::npos);
  const int g1 = b.addGeometry("ground", BodyIndex::world(), contact::Shape::halfSpace());
  const int g2 = b.addGeometry("ceiling", BodyIndex::world(), contact::Shape::halfSpace());
  const int mat = b.addMaterial(test::coulombMaterial(0.3, 1e5, 0.0));
  EXPECT_NE(test::modelErrorOf([&] { b.addContactPair(g1, g2, mat); }).find("(ground, ceiling)"),
            std::string::npos);
  EXPECT_NE(test::modelErrorOf([&] {
              b.addGeometry("bad", a, contact::Shape::box(Vec3(0.1, 0, 0.1)));
            }).find("geometry 'bad': box half extents must be > 0"),
            std::string::npos);
  contact::Material soft = test::coulombMaterial(0.3, 1e5, 0.0);
  soft.normal.stiffness = 0.0;
  EXPECT_NE(test::modelErrorOf([&] { b.addMaterial(soft); }).find("stiffness must be > 0"),
            std::string::npos);
}

TEST(ModelBuilder, RejectsBadOptionsAndEmptyModels) {
  // A model where nothing moves (a static URDF such as a ground plane) is valid.
  ModelBuilder empty;
  EXPECT_EQ(empty.build()->dynamicBodyCount(), 0);
  ModelBuilder b;
  b.addBody(dynamicBody("a"));
  b.options().time_step = 0.0;
  EXPECT_NE(test::modelErrorOf([&] { b.build(); }).find("time step must be > 0"),
            std::string::npos);
  // A step longer than the run, and a step count no run could finish, name both values.
  b.options().duration = 60;
  b.options().time_step = 1e300;
  EXPECT_EQ(test::modelErrorOf([&] { b.build(); }),
            "options: time_step (1e+300 s) is larger than the duration (60 s)");
  b.options().time_step = 60;  // one step is a valid run
  EXPECT_EQ(test::modelErrorOf([&] { b.build(); }), "");
  b.options().duration = 1e12;
  b.options().time_step = 1e-4;
  const std::string many = test::modelErrorOf([&] { b.build(); });
  EXPECT_NE(many.find("1e+16 steps"), std::string::npos) << many;
  EXPECT_NE(many.find("time_step 0.0001 s"), std::string::npos) << many;
}

TEST(ModelBuilder, JointFramesCoincideInTheInitialConfiguration) {
  ModelBuilder b;
  Body body = dynamicBody("a");
  body.position = Vec3(1, 2, 3);
  body.orientation = Quat(Eigen::AngleAxisd(0.7, Vec3(1, 1, 0).normalized()));
  const BodyIndex a = b.addBody(body);
  b.addJoint("j", JointType::kRevolute, BodyIndex::world(), a, Vec3(0.5, 0.5, 0.5), Vec3(0, 0, 2));
  const auto model = b.build();
  const Joint& j = model->joints[0];
  const Mat3 r = body.orientation.toRotationMatrix();
  EXPECT_TRUE((body.position + r * j.anchor_in_child).isApprox(j.anchor_in_parent));
  EXPECT_TRUE((r * j.axes_in_child).isApprox(j.axes_in_parent));
  EXPECT_TRUE(j.axes_in_parent.col(2).isApprox(Vec3::UnitZ()));
  EXPECT_NEAR((j.axes_in_parent.transpose() * j.axes_in_parent - Mat3::Identity()).norm(), 0,
              1e-12);
}

}  // namespace
}  // namespace tribo
