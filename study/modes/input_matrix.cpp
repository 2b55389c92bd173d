#include "study/modes/input_matrix.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "friction/dynamic_law.hpp"
#include "study/file_commit.hpp"

namespace tribo::study {

namespace {

std::string coordinateName(const ReducedCoordinates& coords, int j) {
  if (coords.size() == coords.fullSize()) return coords.fullName(j);
  Eigen::Index i = 0;
  coords.basis().col(j).cwiseAbs().maxCoeff(&i);
  std::string name = "c";  // appended piece by piece: GCC 12 warns wrongly on "c" + string
  name.append(std::to_string(j)).append("~").append(coords.fullName(static_cast<int>(i)));
  return name;
}

void writeMatrixMarket(const std::filesystem::path& file, const Eigen::MatrixXd& m) {
  std::string text = "%%MatrixMarket matrix coordinate real general\n";
  long nonzero = 0;
  for (Eigen::Index j = 0; j < m.cols(); ++j)
    for (Eigen::Index i = 0; i < m.rows(); ++i) nonzero += m(i, j) != 0.0 ? 1 : 0;
  text += std::to_string(m.rows()) + " " + std::to_string(m.cols()) + " " +
          std::to_string(nonzero) + "\n";
  char line[96];
  for (Eigen::Index j = 0; j < m.cols(); ++j)
    for (Eigen::Index i = 0; i < m.rows(); ++i)
      if (m(i, j) != 0.0) {
        std::snprintf(line, sizeof line, "%ld %ld %.17g\n", static_cast<long>(i + 1),
                      static_cast<long>(j + 1), m(i, j));
        text += line;
      }
  writeFileWhole(file, text);
}

}  // namespace

LinearModel linearModel(Dynamics& dynamics, const ReducedCoordinates& coords, const State& at,
                        const Linearization& lin) {
  LinearModel out;
  out.a = firstOrderMatrix(lin);
  out.k = lin.stiffness;
  out.c = lin.damping;
  const int n = coords.size();
  out.basis = coords.basis();
  for (int i = 0; i < coords.fullSize(); ++i) out.coordinates.push_back(coords.fullName(i));
  for (int j = 0; j < n; ++j) out.states.push_back(std::string("q:") + coordinateName(coords, j));
  for (int j = 0; j < n; ++j) out.states.push_back(std::string("u:") + coordinateName(coords, j));
  const Model& model = dynamics.model();
  // Friction state names in State::friction_values' order: joints' first, then contacts'
  // records by their index.
  std::vector<std::string> zs;
  for (const Joint& j : model.joints)
    if (j.elements.friction)
      if (const friction::DynamicFrictionLaw* d = j.elements.friction->law->dynamic())
        for (int i = 0; i < d->stateSize(); ++i)
          zs.push_back(std::string("z:").append(j.name).append(".").append(d->stateName(i)));
  const std::size_t joint_states = zs.size();
  for (std::size_t i = joint_states; i < at.friction_values.size(); ++i)
    zs.push_back(std::string("z:contact[").append(std::to_string(i - joint_states)).append("]"));
  zs.resize(at.friction_values.size());
  out.states.insert(out.states.end(), zs.begin(), zs.end());
  const auto rows = static_cast<Eigen::Index>(out.states.size());

  std::vector<Eigen::VectorXd> columns;
  auto difference = [&](const auto& set) {  // set(+h), set(-h), then restore with set(0)
    const double h = 1.0;
    set(h);
    const Eigen::VectorXd plus = reducedResponse(dynamics, coords, at, true);
    set(-h);
    const Eigen::VectorXd minus = reducedResponse(dynamics, coords, at, true);
    set(0.0);
    Eigen::VectorXd col = Eigen::VectorXd::Zero(rows);
    col.segment(n, plus.size()) = (plus - minus) / (2 * h);
    columns.push_back(col);
  };
  static const char* kParts[] = {".fx", ".fy", ".fz", ".tx", ".ty", ".tz"};
  for (std::size_t l = 0; l < model.loads.size(); ++l)
    for (int p = 0; p < 6; ++p) {
      out.inputs.push_back(model.loads[l].name + kParts[p]);
      difference([&](double h) {
        Vec3 f = Vec3::Zero(), t = Vec3::Zero();
        (p < 3 ? f : t)[p % 3] = h;
        dynamics.setLoadOffset(l, f, t);
      });
    }
  for (std::size_t j = 0; j < model.joints.size(); ++j) {
    const auto& act = model.joints[j].elements.actuator;
    if (!act) continue;
    out.inputs.push_back(act->name);
    const double w0 = act->target.value(at.time);
    difference([&](double h) {
      dynamics.setActuatorCommand(static_cast<int>(j),
                                  h == 0.0 ? std::numeric_limits<double>::quiet_NaN() : w0 + h);
    });
  }
  out.b = Eigen::MatrixXd::Zero(rows, static_cast<Eigen::Index>(columns.size()));
  for (std::size_t c = 0; c < columns.size(); ++c)
    out.b.col(static_cast<Eigen::Index>(c)) = columns[c];
  return out;
}

void writeLinearModel(const std::filesystem::path& folder, const LinearModel& model) {
  writeMatrixMarket(folder / "A.mtx", model.a);
  writeMatrixMarket(folder / "B.mtx", model.b);
  writeMatrixMarket(folder / "K.mtx", model.k);
  writeMatrixMarket(folder / "C.mtx", model.c);
  writeMatrixMarket(folder / "N.mtx", model.basis);
  nlohmann::json j;
  j["equation"] = "y' = A y + B w; K = dq''/dq, C = dq''/du (per unit mass: M is divided out)";
  j["states"] = model.states;
  j["inputs"] = model.inputs;
  j["coordinates"] = model.coordinates;
  j["files"] = {{"A", "A.mtx"}, {"B", "B.mtx"}, {"K", "K.mtx"}, {"C", "C.mtx"}, {"N", "N.mtx"}};
  j["format"] = "Matrix Market coordinate real general (scipy.io.mmread, MATLAB mmread)";
  writeFileWhole(folder / "linear_model.json", j.dump(2) + "\n");
}

}  // namespace tribo::study
