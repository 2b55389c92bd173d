#include "core/constraint_rank.hpp"

#include <cmath>
#include <numeric>

#include "core/constraint_jacobian.hpp"
#include "core/multiplier_matrix.hpp"

namespace tribo {

bool needsRankCheck(const Model& model) {
  if (!model.couplings.empty()) return true;
  // Union-find over the dynamic bodies plus one node for the world and kinematic bodies.
  std::vector<int> parent(model.bodies.size() + 1);
  std::iota(parent.begin(), parent.end(), 0);
  auto node = [&](BodyIndex b) {
    return (b.isWorld() || model.bodies[b.value].kind != BodyKind::kDynamic) ? 0 : b.value + 1;
  };
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const Joint& j : model.joints) {
    if (j.elements.drive) return true;
    if (jointEquations(j.type).empty()) continue;
    const int a = find(node(j.parent)), b = find(node(j.child));
    if (a == b) return true;
    parent[a] = b;
  }
  return false;
}

std::vector<std::string> droppedEquationNotes(const Model& model) {
  std::vector<std::string> notes;
  for (const Joint& j : model.joints) {
    if (j.dropped_equations == 0) continue;
    std::string list;
    int count = 0;
    const auto& equations = jointEquations(j.type);
    for (std::size_t e = 0; e < equations.size(); ++e) {
      if (!((j.dropped_equations >> e) & 1u)) continue;
      list += (count++ ? ", " : "") + equationName(equations[e]);
    }
    notes.push_back("joint '" + j.name + "': " + std::to_string(count) +
                    " redundant equation(s) dropped (" + list +
                    "); the other joints of its loop impose them");
  }
  return notes;
}

std::vector<int> findRedundantRows(const Model& model, const std::vector<ConstraintRow>& rows,
                                   double relative_tolerance) {
  const int m = static_cast<int>(rows.size());
  std::vector<int> redundant;
  if (m == 0) return redundant;
  const std::size_t nb = model.bodies.size();
  State state;
  std::vector<Mat3> rotation(nb), inv_inertia(nb, Mat3::Zero());
  std::vector<double> inv_mass(nb, 0.0);
  for (std::size_t b = 0; b < nb; ++b) {
    const Body& body = model.bodies[b];
    state.bodies.push_back({body.position, body.orientation, body.velocity, body.angular_velocity});
    rotation[b] = body.orientation.toRotationMatrix();
    if (body.kind == BodyKind::kDynamic) {
      inv_mass[b] = 1.0 / body.mass;
      inv_inertia[b] = rotation[b] * body.inertia.inverse() * rotation[b].transpose();
    }
  }
  std::vector<RowValue> values(m);
  evaluateRows(rows, rowGroups(rows), MotionView(state, rotation), 0.0, values);
  ConstraintJacobian jacobian;
  jacobian.init(rows, static_cast<int>(nb));
  for (int r = 0; r < m; ++r) jacobian.setRow(r, values[r]);
  jacobian.computeMassWeighted(inv_mass, inv_inertia);
  MultiplierMatrix a;
  a.init(m, jacobian.pattern(), false);
  jacobian.bindSlots(a);
  a.setZero();
  jacobian.assemble(a);
  const Eigen::Map<const Eigen::MatrixXd> full(a.values(), m, m);  // lower triangle valid

  Eigen::MatrixXd l = Eigen::MatrixXd::Zero(m, m);
  std::vector<int> kept;
  for (int i = 0; i < m; ++i) {
    for (std::size_t kk = 0; kk < kept.size(); ++kk) {
      const int k = kept[kk];
      double s = full(i, k);
      for (std::size_t pp = 0; pp < kk; ++pp) s -= l(i, kept[pp]) * l(k, kept[pp]);
      l(i, k) = s / l(k, k);
    }
    double d = full(i, i);
    for (int k : kept) d -= l(i, k) * l(i, k);
    if (!(d > relative_tolerance * full(i, i)) || !(full(i, i) > 0.0)) {
      redundant.push_back(i);
      for (int k : kept) l(i, k) = 0.0;
      continue;
    }
    l(i, i) = std::sqrt(d);
    kept.push_back(i);
  }
  return redundant;
}

}  // namespace tribo
