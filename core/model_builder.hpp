// Builds and validates a Model. Every add* checks what it can at once; build() checks the
// whole (names, references, joint frames) and returns the immutable model. Errors are
// ModelError with a message naming the element and what was expected.
// Not here: file formats (io/), anything that runs.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

#include "core/model.hpp"

namespace tribo {

class ModelError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class ModelBuilder {
 public:
  BodyIndex addBody(const Body& body);
  // Geometry on a body (or the world) at a pose in that body's frame. Returns its index.
  int addGeometry(const std::string& name, BodyIndex body, const contact::Shape& shape,
                  const Eigen::Isometry3d& local_pose = Eigen::Isometry3d::Identity());
  int addMaterial(const contact::Material& material);
  void addContactPair(int geometry_a, int geometry_b, int material);
  // Joint given in the initial configuration: anchor point and axis in world coordinates.
  void addJoint(const std::string& name, JointType type, BodyIndex parent, BodyIndex child,
                const Vec3& anchor_world, const Vec3& axis_world);
  // Spring-damper with attachment points in world coordinates at the initial
  // configuration; a negative rest length means "the initial distance".
  void addSpring(const std::string& name, BodyIndex a, const Vec3& point_a_world, BodyIndex b,
                 const Vec3& point_b_world, double stiffness, double damping,
                 double rest_length);

  SimulationOptions& options() { return options_; }
  std::optional<BodyIndex> findBody(const std::string& name) const;
  std::optional<int> findGeometry(const std::string& name) const;
  const std::vector<Body>& bodies() const { return model_.bodies; }

  std::shared_ptr<const Model> build() const;

 private:
  Body checkedBody(BodyIndex index, const std::string& what) const;
  Model model_;
  SimulationOptions options_;
};

}  // namespace tribo
