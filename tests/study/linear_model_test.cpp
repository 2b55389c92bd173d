// The linear model with inputs (study/modes/input_matrix.hpp) of a small scene against the
// model written here by hand: a block (m1) on a slide with a joint spring k and damper c,
// pushed by a load F, and a slider (m2) held by a position servo (kp, kd) at r. In full
// coordinates (full = N q):
//   block.x'' = (-k x - c x' + F) / m1,   slider.x'' = (kp (r - x) - kd x') / m2,
// so N K N^T, N C N^T and N B hold -k/m1, -c/m1, -kp/m2, -kd/m2, 1/m1 (push.fx) and kp/m2
// (servo) at those coordinates and nothing else; and the files: Matrix Market that reads back
// to the same numbers, and the names.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "io/scene_loader.hpp"
#include "study/modes/modes.hpp"

namespace tribo::study {
namespace {

const std::string kScene = R"(parameters: {m1: 2.0, m2: 0.5, k: 300, c: 4, kp: 80, kd: 3}
simulation: {duration: 1, time_step: 0.001, gravity: [0, 0, 0]}
bodies:
  - {name: block, mass: $m1, inertia: [0.1, 0.1, 0.1]}
  - {name: slider, mass: $m2, inertia: [0.1, 0.1, 0.1], position: [0, 1, 0]}
joints:
  - {name: slide, type: prismatic, parent: world, child: block, anchor: [0, 0, 0],
     axis: [1, 0, 0], spring: {stiffness: $k}, damping: $c}
  - {name: rail, type: prismatic, parent: world, child: slider, anchor: [0, 1, 0],
     axis: [1, 0, 0]}
loads:
  - {name: push, body: block, force: [2, 0, 0]}
actuators:
  - {name: servo, joint: rail, type: position, target: 0.05, kp: $kp, kd: $kd}
)";

int index(const std::vector<std::string>& names, const std::string& name) {
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return static_cast<int>(i);
  ADD_FAILURE() << "no " << name;
  return 0;
}

TEST(LinearModel, MatchesTheHandWrittenModel) {
  const io::Scene scene = io::loadSceneFromString(kScene, "linear.yaml");
  ModesSpec spec;
  spec.linear_model = true;
  const ModesResult r = analyzeModes(scene, spec);
  ASSERT_TRUE(r.linear);
  const LinearModel& lm = *r.linear;
  const int n = static_cast<int>(lm.k.rows());
  ASSERT_EQ(n, 2);
  ASSERT_EQ(lm.a.rows(), 4);
  ASSERT_EQ(lm.states.size(), 4u);
  EXPECT_EQ(lm.inputs, (std::vector<std::string>{"push.fx", "push.fy", "push.fz", "push.tx",
                                                 "push.ty", "push.tz", "servo"}));
  const Eigen::MatrixXd& nb = lm.basis;
  const Eigen::MatrixXd k = nb * lm.k * nb.transpose(), c = nb * lm.c * nb.transpose();
  const Eigen::MatrixXd b = nb * lm.b.bottomRows(n);
  const int bx = index(lm.coordinates, "block.x"), sx = index(lm.coordinates, "slider.x");
  const double m1 = 2.0, m2 = 0.5;
  Eigen::MatrixXd k_want = Eigen::MatrixXd::Zero(k.rows(), k.cols()), c_want = k_want;
  k_want(bx, bx) = -300 / m1;
  k_want(sx, sx) = -80 / m2;
  c_want(bx, bx) = -4 / m1;
  c_want(sx, sx) = -3 / m2;
  Eigen::MatrixXd b_want = Eigen::MatrixXd::Zero(b.rows(), b.cols());
  b_want(bx, 0) = 1 / m1;   // push.fx
  b_want(sx, 6) = 80 / m2;  // servo target
  // Central differences of a linear response: rounding only (steps 1e-7 on gains ~1e2).
  EXPECT_LT((k - k_want).cwiseAbs().maxCoeff(), 1e-6 * 160) << k;
  EXPECT_LT((c - c_want).cwiseAbs().maxCoeff(), 1e-6 * 6) << c;
  EXPECT_LT((b - b_want).cwiseAbs().maxCoeff(), 1e-9 * 160) << b;
  EXPECT_EQ(lm.b.topRows(n).cwiseAbs().maxCoeff(), 0.0);
  // The top of A is [0, I].
  EXPECT_EQ(lm.a.topLeftCorner(n, n).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ((lm.a.topRightCorner(n, n) - Eigen::MatrixXd::Identity(n, n)).cwiseAbs().maxCoeff(),
            0.0);
}

TEST(LinearModel, FilesReadBackAsTheMatrices) {
  const io::Scene scene = io::loadSceneFromString(kScene, "linear.yaml");
  ModesSpec spec;
  spec.linear_model = true;
  const ModesResult r = analyzeModes(scene, spec);
  const auto dir = std::filesystem::temp_directory_path() / "tribo_linear_model_test";
  std::filesystem::create_directories(dir);
  writeLinearModel(dir, *r.linear);
  // Matrix Market coordinate: header, "rows cols entries", then "i j value" (1-based).
  std::ifstream in(dir / "B.mtx");
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "%%MatrixMarket matrix coordinate real general");
  long rows = 0, cols = 0, entries = 0;
  in >> rows >> cols >> entries;
  ASSERT_EQ(rows, r.linear->b.rows());
  ASSERT_EQ(cols, r.linear->b.cols());
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(rows, cols);
  for (long e = 0; e < entries; ++e) {
    long i = 0, j = 0;
    double v = 0;
    in >> i >> j >> v;
    b(i - 1, j - 1) = v;
  }
  EXPECT_EQ(b, r.linear->b);  // %.17g: every double exactly
  std::ifstream json(dir / "linear_model.json");
  const nlohmann::json j = nlohmann::json::parse(json);
  EXPECT_EQ(j["inputs"].get<std::vector<std::string>>(), r.linear->inputs);
  EXPECT_EQ(j["states"].get<std::vector<std::string>>(), r.linear->states);
  EXPECT_EQ(j["files"]["B"], "B.mtx");
  for (const char* f : {"A.mtx", "K.mtx", "C.mtx", "N.mtx"})
    EXPECT_TRUE(std::filesystem::exists(dir / f)) << f;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tribo::study
