#include "core/model_detector.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace tribo {

namespace {

// Automatic contacts: the model's rule (core/automatic_contacts.hpp), asked on demand.
class ModelPairRule : public contact::PairRule {
 public:
  explicit ModelPairRule(std::shared_ptr<const Model> model) : model_(std::move(model)) {}
  int pairId(int g, int h) const override { return automaticPairId(*model_, g, h); }
  std::pair<int, int> geometries(int id) const override { return automaticGeometries(*model_, id); }

 private:
  std::shared_ptr<const Model> model_;
};

// A geometry as a message names it: 'name' of body 'body' (or of the world).
std::string geometryLabel(const Model& model, int g) {
  const Geometry& geometry = model.geometries[static_cast<std::size_t>(g)];
  return "geometry '" + geometry.name + "' (" +
         (geometry.body.isWorld() ? std::string("world")
                                  : "body '" + model.bodies[geometry.body.value].name + "'") +
         ")";
}

// An FCL query that never returns (contact/query_watchdog.hpp) cannot be interrupted: say
// which pair, then end the process with status 7; the outputs stay as .partial files.
void queryOverrun(const std::shared_ptr<const Model>& model, int a, int b, double seconds) {
  std::fprintf(stderr,
               "tribo: the collision query between %s and %s has run %.0f s without finishing "
               "(limit %.0f s; FCL/libccd has no iteration limit for convex pairs: is one of "
               "them a mesh of extreme shape?); the run cannot continue, its outputs stay as "
               ".partial files\n",
               geometryLabel(*model, a).c_str(), geometryLabel(*model, b).c_str(), seconds,
               model->options.collision.query_time_limit);
  std::fflush(stderr);
  std::_Exit(kQueryOverrunStatus);
}

}  // namespace

contact::CollisionDetector makeModelDetector(const std::shared_ptr<const Model>& shared) {
  const Model& model = *shared;
  std::vector<contact::Shape> shapes;
  shapes.reserve(model.geometries.size());
  for (const auto& g : model.geometries) shapes.push_back(g.shape);
  std::vector<std::pair<int, int>> pairs;
  pairs.reserve(model.contact_pairs.size());
  for (const auto& p : model.contact_pairs) pairs.emplace_back(p.geometry_a, p.geometry_b);
  contact::CollisionDetector detector =
      model.automatic_contacts
          ? contact::CollisionDetector(std::move(shapes), std::make_unique<ModelPairRule>(shared),
                                       model.options.collision)
          : contact::CollisionDetector(std::move(shapes), std::move(pairs),
                                       model.options.collision);
  if (const double limit = model.options.collision.query_time_limit;
      limit > 0.0 && std::isfinite(limit))
    detector.watchQueries(
        limit, [shared](int a, int b, double seconds) { queryOverrun(shared, a, b, seconds); });
  return detector;
}

}  // namespace tribo
