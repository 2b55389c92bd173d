// The signal kinds read from files and expressions (io/scene_signal.cpp,
// io/time_expression.cpp, io/signal_table_file.cpp): an expression of t with parameters
// against its closed form (value, and derivative by the five-point difference or by a given
// expression) over time and amplitude scales; copies evaluated on several threads at once;
// a force a t driven by an expression moving a free body as x = a t^3 / (6 m), alike with
// the same load as a ramp; CSV tables (header or not, by column name or position, linear or
// cubic, relative to the scene's folder) and inline cubic tables against their points; and
// every refusal with its message: the scene's file:line, the key and, for a CSV, its
// file:line:column. An expression's listed breakpoints (reported, splitting its integral,
// refused when they do not increase) and a joint drive given as a signal (velocity: the
// table, its area and slope; position: a sine and its second derivative; `signal` with the
// function's keys refused).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <thread>
#include <vector>

#include "core/simulator.hpp"
#include "io/scene_loader.hpp"
#include "support/scene_text.hpp"

namespace tribo::io {
namespace {

namespace fs = std::filesystem;
using test::replaced;
using test::sceneErrorOf;
constexpr double kPi = std::numbers::pi;

std::string sceneWith(const std::string& force_x, const std::string& parameters = "{F0: 2}") {
  return "parameters: " + parameters +
         "\nsimulation: {duration: 1, time_step: 0.001, gravity: [0, 0, 0]}\n"
         "bodies:\n  - {name: block, mass: 2, inertia: [0.1, 0.1, 0.1]}\n"
         "loads:\n  - name: push\n    body: block\n    force: [" +
         force_x + ", 0, 0]\n";
}

const Signal& forceX(const Scene& s) { return s.model->loads.at(0).force[0]; }

TEST(ExpressionSignal, IsItsClosedFormWithParameters) {
  for (double ts : {1e-3, 1.0, 1e3})
    for (double a : {1e-3, 1.0, 1e3}) {
      const std::string params = "{A: " + std::to_string(a) + ", P: " + std::to_string(ts) +
                                 ", F0: " + std::to_string(-0.5 * a) + "}";
      const Scene s = loadSceneFromString(
          sceneWith("{expression: {value: \"$A * sin(2*pi*t/$P) + $F0\", time_scale: $P}}", params),
          "e.yaml");
      const Signal& f = forceX(s);
      EXPECT_EQ(f.kind(), Signal::Kind::kFunction);
      EXPECT_TRUE(f.breakpoints().empty());
      const double w = 2 * kPi / ts;
      for (double x : {0.0, 0.1, 0.25, 0.77, 3.0, 41.3}) {
        const double t = x * ts;
        EXPECT_NEAR(f.value(t), a * std::sin(w * t) - 0.5 * a, 1e-13 * a) << ts << " " << a;
        // The stated bound of core/signal.hpp at tau = P: below 1e-9 of A w.
        EXPECT_NEAR(f.derivative(t), a * w * std::cos(w * t), 1e-9 * a * w) << ts << " " << x;
      }
    }
}

TEST(ExpressionSignal, StringFormAndGivenDerivative) {
  const Scene s = loadSceneFromString(sceneWith("{expression: \"0.5 * sin(2*pi*3*t) + $F0\"}"),
                                      "e.yaml", {"F0=4"});
  const double w = 2 * kPi * 3;
  for (double t : {0.0, 0.01, 0.3, 7.0}) {
    EXPECT_NEAR(forceX(s).value(t), 0.5 * std::sin(w * t) + 4, 1e-14);
    EXPECT_NEAR(forceX(s).derivative(t), 0.5 * w * std::cos(w * t), 1e-9 * 0.5 * w);
  }
  const Scene d = loadSceneFromString(
      sceneWith("{expression: {value: \"t^3\", derivative: \"3 * t^2 + $F0\"}}"), "e.yaml");
  EXPECT_EQ(forceX(d).value(2.0), 8.0);
  EXPECT_EQ(forceX(d).derivative(2.0), 14.0);  // the given expression, exactly
}

TEST(ExpressionSignal, CopiesEvaluateOnThreadsAtOnce) {
  const Scene s = loadSceneFromString(sceneWith("{expression: \"sin(t) * $F0\"}"), "e.yaml");
  const Signal original = forceX(s);
  std::vector<int> wrong(4, 0);
  std::vector<std::thread> threads;
  for (int k = 0; k < 4; ++k)
    threads.emplace_back([&, k] {
      const Signal mine = original;  // each thread its own copy, and one shared
      for (int i = 0; i < 20000; ++i) {
        const double t = 1e-3 * (i + k);
        if (mine.value(t) != std::sin(t) * 2.0) ++wrong[k];
        if (original.value(t) != std::sin(t) * 2.0) ++wrong[k];
      }
    });
  for (auto& t : threads) t.join();
  EXPECT_EQ(wrong, std::vector<int>(4, 0));
}

// F = a t on mass m from rest: x = a t^3 / (6 m), v = a t^2 / (2 m). RK4 integrates a cubic
// exactly (a quadrature of a polynomial of degree <= 3 per stage), so only rounding remains.
TEST(ExpressionSignal, DrivesAFreeBodyLikeTheSameRamp) {
  const double a = 3.0, m = 2.0;
  const Scene e = loadSceneFromString(sceneWith("{expression: \"$a * t\"}", "{a: 3}"), "e.yaml");
  const Scene r = loadSceneFromString(sceneWith("{ramp: {rate: $a}}", "{a: 3}"), "r.yaml");
  Simulator se(e.model), sr(r.model);
  while (se.state().time < 1.0 - 1e-12) ASSERT_TRUE(se.step().ok && sr.step().ok);
  const double t = se.state().time;
  const double x = a * t * t * t / (6 * m), v = a * t * t / (2 * m);
  EXPECT_NEAR(se.state().bodies[0].position.x(), x, 1e-9 * x);
  EXPECT_NEAR(se.state().bodies[0].velocity.x(), v, 1e-9 * v);
  EXPECT_NEAR(sr.state().bodies[0].position.x(), x, 1e-9 * x);
  EXPECT_NEAR(se.state().bodies[0].position.x(), sr.state().bodies[0].position.x(), 1e-12 * x);
}

TEST(ExpressionSignal, RefusalsNameTheExpression) {
  struct Case {
    std::string signal, says;
  };
  for (const Case& c : {
           Case{"{expression: \"sin(2*pi*\"}", "e.yaml:8:26: "},
           Case{"{expression: \"sin(2*pi*\"}",
                "loads[0].force[0].expression: expression 'sin(2*pi*'"},
           Case{"{expression: \"2 * x + t\"}", "expression '2 * x + t': Unexpected token \"x\""},
           Case{"{expression: \"$G * t\"}", "unknown parameter '$G' (known: F0)"},
           Case{"{expression: \"1 / t\"}", "expression '1 / t': the value at t = 0 is inf"},
           Case{"{expression: \"sqrt(t - 1)\"}", "nan (division by zero"},
           Case{"{expression: {value: \"t\", derivative: \"q\"}}",
                "loads[0].force[0].expression.derivative: expression 'q'"},
           Case{"{expression: {value: \"t\", time_scale: 0}}",
                "loads[0].force[0].expression.time_scale: expected a number > 0"},
           Case{"{expression: {derivative: \"1\"}}", "missing required key 'value'"},
       }) {
    const std::string e = sceneErrorOf(sceneWith(c.signal), "e.yaml");
    EXPECT_NE(e.find(c.says), std::string::npos) << c.signal << "\n -> " << e;
  }
}

TEST(ExpressionSignal, ListedBreakpointsAreReportedAndSplitTheIntegral) {
  // A speed step up at 1 s and down at 3 s: the integral is the step function's area.
  const Scene s = loadSceneFromString(
      sceneWith("{expression: {value: \"t < 1 ? $F0 : (t < 3 ? 3 * $F0 : $F0)\", "
                "derivative: \"0\", breakpoints: [1, '3 * $F0 / 2']}}"),
      "e.yaml");
  const Signal& f = forceX(s);
  EXPECT_EQ(f.breakpoints(), (std::vector<double>{1.0, 3.0}));
  for (double t : {0.5, 1.0, 2.2, 3.0, 7.5})
    // Rounding of the running sum over t / tau = 1000 t panels: 1e-13 relative.
    EXPECT_NEAR(f.integral(t), 2.0 * t + 4.0 * std::clamp(t - 1.0, 0.0, 2.0), 1e-13 * (1 + 4 * t))
        << t;
  struct Case {
    std::string signal, says;
  };
  for (const Case& c : {
           Case{"{expression: {value: \"t\", breakpoints: [2, 1]}}",
                "loads[0].force[0].expression.breakpoints[1]: breakpoints must increase "
                "strictly: 1 follows 2"},
           Case{"{expression: {value: \"t\", breakpoints: 1}}", "a sequence of times"},
           Case{"{expression: {value: \"t\", breakpoints: [a]}}", "breakpoints[0]"},
       }) {
    const std::string e = sceneErrorOf(sceneWith(c.signal), "e.yaml");
    EXPECT_NE(e.find(c.says), std::string::npos) << c.signal << "\n -> " << e;
  }
}

// A slider on a rail along x, velocity-driven by `drive`.
std::string drivenSlider(const std::string& drive) {
  return "simulation: {duration: 1, time_step: 0.001, gravity: [0, 0, 0]}\n"
         "bodies:\n  - {name: block, mass: 2, inertia: [0.1, 0.1, 0.1]}\n"
         "joints:\n  - {name: rail, type: prismatic, parent: world, child: block, axis: [1, 0, "
         "0],\n"
         "     drive: " +
         drive + "}\n";
}

TEST(DriveSignal, ADriveTakesAnySignalAndRefusesTwoForms) {
  const Scene s = loadSceneFromString(
      drivenSlider("{mode: velocity, signal: {table: [[0, 0], [1, 2]]}}"), "d.yaml");
  const JointDrive& d = *s.model->joints.at(0).elements.drive;
  ASSERT_TRUE(d.signal);
  EXPECT_EQ(d.mode, DriveMode::kVelocity);
  EXPECT_DOUBLE_EQ(d.velocity(0.5), 1.0);      // the table
  EXPECT_DOUBLE_EQ(d.position(0.5), 0.25);     // its area, t^2
  EXPECT_DOUBLE_EQ(d.acceleration(0.5), 2.0);  // its slope
  const Scene p = loadSceneFromString(
      drivenSlider("{signal: {sines: [{amplitude: 0.1, frequency: 2}]}}"), "d.yaml");
  const JointDrive& q = *p.model->joints.at(0).elements.drive;
  EXPECT_EQ(q.mode, DriveMode::kPosition);
  EXPECT_NEAR(q.position(0.1), 0.1 * std::sin(0.4 * kPi), 1e-15);
  EXPECT_NEAR(q.acceleration(0.1), -0.1 * 16 * kPi * kPi * std::sin(0.4 * kPi), 1e-12);
  const std::string e =
      sceneErrorOf(drivenSlider("{mode: velocity, constant: 1, signal: 2}"), "d.yaml");
  EXPECT_NE(e.find("joints[0].drive.signal: a drive takes either `signal` or the function's "
                   "keys (constant, slope, amplitude, frequency, phase), not both; found "
                   "`constant` too"),
            std::string::npos)
      << e;
  EXPECT_NE(sceneErrorOf(drivenSlider("{signal: {step: {time: 1}}}"), "d.yaml")
                .find("joints[0].drive.signal.step"),
            std::string::npos);
}

// A folder with the scene's CSV files, removed at the end.
class TableFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("tribo_signal_" + std::string(info->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "data");
  }
  void TearDown() override { fs::remove_all(dir_); }
  void write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name) << text;
  }
  std::string scene() const { return (dir_ / "scene.yaml").string(); }
  fs::path dir_;
};

TEST_F(TableFiles, ReadsColumnsByNameOrPositionLinearOrCubic) {
  write("data/forces.csv", "# measured\nt, fx, fy\n0, 1, 10\n1, 3, 20\n\n3, -1, 0\n");
  write("bare.csv", "0,0\n1,0\n3,2\n");
  struct Case {
    std::string table;
    double at_half, at_two;  // the closed forms at t = 0.5 and t = 2
  };
  for (const Case& c : {
           Case{"{file: data/forces.csv}", 2.0, 1.0},
           Case{"{file: data/forces.csv, column: fy}", 15.0, 10.0},
           Case{"{file: data/forces.csv, column: 3}", 15.0, 10.0},
           Case{"{file: data/forces.csv, column: fx, interpolation: linear}", 2.0, 1.0},
           // The natural spline through (0, 0), (1, 0), (3, 2) (tests/core/signal_cubic_test):
           // (x^3 - x) / 6 on [0, 1], (x - 1) + (3 - x)^3 / 12 - (3 - x) / 3 on [1, 3].
           Case{"{file: bare.csv, interpolation: cubic}", (0.125 - 0.5) / 6,
                1 + 1.0 / 12 - 1.0 / 3},
           Case{"{points: [[0, 0], [1, 0], [3, 2]], interpolation: cubic}", (0.125 - 0.5) / 6,
                1 + 1.0 / 12 - 1.0 / 3},
           Case{"{points: [[0, 1], [1, 3], [3, -1]]}", 2.0, 1.0},
       }) {
    const Scene s = loadSceneFromString(sceneWith("{table: " + c.table + "}"), scene());
    EXPECT_NEAR(forceX(s).value(0.5), c.at_half, 1e-15) << c.table;
    EXPECT_NEAR(forceX(s).value(2.0), c.at_two, 1e-15) << c.table;
    EXPECT_EQ(forceX(s).breakpoints(), (std::vector<double>{0, 1, 3})) << c.table;
  }
  const Scene cubic =
      loadSceneFromString(sceneWith("{table: {file: bare.csv, interpolation: cubic}}"), scene());
  EXPECT_EQ(forceX(cubic).kind(), Signal::Kind::kCubicTable);
  EXPECT_NEAR(forceX(cubic).derivative(0.0), -1.0 / 6, 1e-15);
  EXPECT_NEAR(forceX(cubic).derivative(2.0), 1 - 0.25 + 1.0 / 3, 1e-15);
}

TEST_F(TableFiles, RefusalsNameTheSceneKeyAndTheCsvPlace) {
  write("f.csv", "t, fx\n0, 1\n1, 2x\n");
  write("back.csv", "0, 1\n2, 2\n# note\n1, 3\n");
  write("short.csv", "t, fx, fy\n0, 1\n");
  write("one.csv", "0, 1\n");
  write("empty.csv", "# nothing\n");
  const std::string csv = (dir_ / "").string();
  struct Case {
    std::string table;
    std::vector<std::string> says;
  };
  for (const Case& c : {
           Case{"{file: nothere.csv}",
                {"scene.yaml:8:28: ", "loads[0].force[0].table.file: table file 'nothere.csv': ",
                 "cannot open signal table file '" + csv + "nothere.csv'"}},
           Case{"{file: f.csv}",
                {"table file 'f.csv': " + csv + "f.csv:3:4: expected a number, found '2x'"}},
           Case{"{file: back.csv}",
                {csv + "back.csv:4:1: times must be strictly increasing: t = 1 follows t = 2 "
                       "(line 2)"}},
           Case{"{file: short.csv, column: fy}",
                {csv +
                 "short.csv:2: expected at least 3 fields (the value column is 'fy'), found 2"}},
           Case{"{file: f.csv, column: fz}",
                {csv + "f.csv:1: no column named 'fz' in the header 't, fx'"}},
           Case{"{file: f.csv, column: 5}",
                {csv + "f.csv:1: no column 5: the header 't, fx' has 2"}},
           Case{"{file: one.csv, column: fx}",
                {"one.csv:1: no column named 'fx': the file has no header"}},
           Case{"{file: f.csv, column: 1}",
                {"table.column: expected a whole number >= 2, found '1'"}},
           Case{"{file: one.csv, interpolation: cubic}",
                {"table.file: table file 'one.csv': " + csv +
                 "one.csv: cubic table: needs at least 2 points, found 1"}},
           Case{"{file: empty.csv}", {"empty.csv:1: expected lines of 't, value', found no point"}},
           Case{"{points: [[0, 1]], interpolation: cubic}",
                {"loads[0].force[0].table.points: cubic table: needs at least 2 points"}},
           Case{
               "{points: [[0, 1], [0, 2]], interpolation: cubic}",
               {"cubic table: times must be strictly increasing (point 1 at t = 0 follows t = 0)"}},
           Case{"{points: [[0, 1]], file: one.csv}",
                {"expected one of 'points' and 'file', found both"}},
           Case{"{interpolation: cubic}", {"expected one of 'points' and 'file', found neither"}},
           Case{"{points: [[0, 1]], column: 2}",
                {"table.column: 'column' selects a column of a 'file'"}},
           Case{"{file: f.csv, interpolation: spline}",
                {"table.interpolation: expected one of linear, cubic, found 'spline'"}},
           Case{"{file: f.csv, rows: 3}",
                {"unknown key 'rows' (accepted keys: points, file, column, interpolation)"}},
       }) {
    const std::string e = sceneErrorOf(sceneWith("{table: " + c.table + "}"), scene());
    for (const std::string& says : c.says)
      EXPECT_NE(e.find(says), std::string::npos) << c.table << "\n -> " << e << "\n wants " << says;
  }
}

}  // namespace
}  // namespace tribo::io
