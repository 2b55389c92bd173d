// Builds and validates a Model. Every add* checks what it can at once; build() checks the
// whole (names, references, joint frames) and returns the immutable model. Errors are
// ModelError with a message naming the element and what was expected.
// Not here: file formats (io/), anything that runs.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "core/model.hpp"

namespace tribo {

// The most steps (duration / time_step) a model may ask for: 1e15 is still an exact integer
// in a double and years of wall time for the cheapest scene; beyond it the numbers are a
// typo, not a run.
inline constexpr double kMaxSteps = 1e15;

class ModelError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class ModelBuilder {
 public:
  // Mass > 0 and a valid inertia for dynamic bodies, a finite pose and velocities, each
  // coordinate of the position within +-contact::kMaxLength.
  BodyIndex addBody(const Body& body);
  // Geometry on a body (or the world) at a pose in that body's frame. Returns its index.
  int addGeometry(const std::string& name, BodyIndex body, const contact::Shape& shape,
                  const Eigen::Isometry3d& local_pose = Eigen::Isometry3d::Identity());
  // What addGeometry checks of one geometry, for a loader that wants the error before it
  // uses the shape (its inertia): valid dimensions (contact::Shape::validate), each at most
  // contact::kMaxLength, as every mesh vertex coordinate and the position's coordinates.
  // Throws ModelError "geometry 'NAME': what: expected ..., found ...".
  static void checkGeometry(const std::string& name, const contact::Shape& shape,
                            const Eigen::Isometry3d& local_pose);
  int addMaterial(const contact::Material& material);
  void addContactPair(int geometry_a, int geometry_b, int material);
  // Automatic contacts (used when no contact pair is added): a geometry's surface material
  // and collision filter, the contact material of a surface pair, and the default material
  // for pairs no surface entry covers. build() then pairs every two geometries that may
  // touch: on different bodies, at least one dynamic, not both half-spaces, not joined by a
  // joint (unless options().collision.joined_bodies_collide), passing the group/mask test.
  void setGeometrySurface(int geometry, const std::string& surface);
  void setCollisionFilter(int geometry, std::uint32_t group, std::uint32_t mask);
  void addSurfacePairMaterial(const std::string& surface_a, const std::string& surface_b,
                              int material);
  void setDefaultMaterial(int material);
  // Joints (core/model_builder_joints.cpp). Each returns the joint's index.
  // Joint given in the initial configuration: anchor point and axis in world coordinates;
  // the joint coordinate is 0 there.
  int addJoint(const std::string& name, JointType type, BodyIndex parent, BodyIndex child,
               const Vec3& anchor_world, const Vec3& axis_world);
  // The same with the joint frame's x axis given (world): the zero-angle reference, and for a
  // universal joint the child's rotation axis (required, normal to axis_world).
  int addJoint(const std::string& name, JointType type, BodyIndex parent, BodyIndex child,
               const Vec3& anchor_world, const Vec3& axis_world, const Vec3& reference_world);
  // URDF convention: the joint frame's pose in the parent's frame (the world's for the world)
  // and in the child's frame (for URDF, the inverse of the child's inertial origin: Tribo
  // bodies have their origin at the centre of mass), and the axis in the joint frame. The
  // coordinate is 0 where the two frames coincide. URDF revolute and continuous map to
  // kRevolute, prismatic, fixed and planar to theirs, floating to kFree (or no joint).
  int addJointInFrames(const std::string& name, JointType type, BodyIndex parent, BodyIndex child,
                       const Eigen::Isometry3d& joint_in_parent,
                       const Eigen::Isometry3d& joint_in_child, const Vec3& axis_in_joint);
  // On a revolute or prismatic joint's coordinate (core/joint_elements.hpp). URDF <limit
  // lower upper> maps to a JointLimit (gains derived when 0), <dynamics damping> to
  // setJointDamping, <dynamics friction> to a JointFriction with a coulomb law (mu 1),
  // load kConstant, normal_force = friction, radius 1.
  void setJointLimit(int joint, const JointLimit& limit);
  void setJointSpring(int joint, const JointSpring& spring);
  void setJointDamping(int joint, double damping);
  void setJointEffort(int joint, double effort);
  void setJointFriction(int joint, const JointFriction& friction);
  void setJointDrive(int joint, const JointDrive& drive);
  // The joint's rated effort and speed (URDF <limit effort velocity>), both > 0 (infinite:
  // none), the defaults of an actuator's limits.
  void setJointRating(int joint, double effort, double velocity);
  // An actuator (core/joint_actuator.hpp), its name unique among actuators, one per joint and
  // not on a driven joint; gains finite and >= 0 as its kind needs them (motor: none;
  // position servo: kp or kd > 0; velocity servo: kd > 0, kp = 0), limits > 0, infinite
  // ones taking the joint's rating.
  void setJointActuator(int joint, JointActuator actuator);
  // q_follower = multiplier q_leader + offset (URDF <mimic joint multiplier offset>).
  int addJointCoupling(const std::string& name, int leader, int follower, double multiplier,
                       double offset);
  std::optional<int> findJoint(const std::string& name) const;
  const std::vector<Joint>& joints() const { return model_.joints; }
  // Spring-damper with attachment points in world coordinates at the initial
  // configuration; a negative rest length means "the initial distance".
  void addSpring(const std::string& name, BodyIndex a, const Vec3& point_a_world, BodyIndex b,
                 const Vec3& point_b_world, double stiffness, double damping, double rest_length);
  // Force elements with rotation (core/model_builder_elements.cpp). A bushing's frames are
  // given in their bodies' frames (the world's for the world; core/bushing.hpp); gains finite
  // and >= 0, the bodies different.
  void addBushing(const Bushing& bushing);
  // Torsional spring-damper about `axis_world` (any length > 0, at the initial configuration,
  // fixed in A from there; core/torsional_spring.hpp); its angle is 0 at the initial
  // configuration and it is relaxed at `rest_angle` [rad].
  void addTorsionalSpring(const std::string& name, BodyIndex a, BodyIndex b, const Vec3& axis_world,
                          double stiffness, double damping, double rest_angle);
  // Applied load (core/applied_load.hpp) on a dynamic body, its point finite; the name
  // unique among loads (core/model_builder_elements.cpp).
  void addLoad(const AppliedLoad& load);

  SimulationOptions& options() { return options_; }
  std::optional<BodyIndex> findBody(const std::string& name) const;
  std::optional<int> findGeometry(const std::string& name) const;
  const std::vector<Body>& bodies() const { return model_.bodies; }

  // Room for `bodies` and `geometries` more (a pattern's copies, io/scene_bodies.cpp): the
  // model's vectors and the name indexes grow once instead of doubling as they fill.
  void reserve(std::size_t bodies, std::size_t geometries);

  // Options: time_step and duration finite and > 0, time_step <= duration, and at most
  // kMaxSteps steps. On a builder that is done (an rvalue: std::move(builder).build()), the
  // model is moved out instead of copied, and the builder is not to be used again.
  std::shared_ptr<const Model> build() const&;
  std::shared_ptr<const Model> build() &&;

 private:
  void checkOptions() const;
  // What build() does to its copy (or the moved model): joints, integrals, automatic contacts.
  std::shared_ptr<const Model> finish(std::shared_ptr<Model> model) const;
  Body checkedBody(BodyIndex index, const std::string& what) const;
  Joint& checkedJoint(int joint, const std::string& what, bool scalar_coordinate);
  int pushJoint(Joint joint);
  // Derived limit gains and the redundancy check on the built model (model_builder_joints.cpp).
  void finishJoints(Model& model) const;
  void addAutomaticContacts(Model& model) const;
  std::vector<SurfacePairMaterial> surface_materials_;
  int default_material_ = -1;
  Model model_;
  SimulationOptions options_;
  // Name -> index, so that adding n bodies and geometries costs O(n), not O(n^2).
  std::unordered_map<std::string, int> body_index_, geometry_index_, joint_index_;
  std::unordered_set<std::string> surface_pairs_;  // surface pairs given a material
};

}  // namespace tribo
