// Parameters that refer to parameters, at sizes a hand-written scene never reaches: doubling
// chains (each parameter `$p + $p` of the one before: exponential work if a parameter were
// evaluated per reference), linear chains of 10,000 (a stack overflow if evaluated by
// recursion), cycles of several lengths named in the message, a wide fan of parameters over
// one, and --set overrides (numbers and expressions) flowing through all of them.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "io/scene_loader.hpp"
#include "support/scene_text.hpp"

namespace tribo::io {
namespace {

using test::sceneErrorOf;

// A box whose mass is `mass`, after the parameter lines `parameters`.
std::string scene(const std::string& parameters, const std::string& mass) {
  return "parameters:\n" + parameters +
         "simulation: {duration: 0.01, time_step: 0.001}\n"
         "bodies:\n"
         "  - {name: box, mass: " +
         mass + ", geometry: [{name: g, shape: box, size: [0.1, 0.1, 0.1]}]}\n";
}

double massOf(const std::string& parameters, const std::string& mass,
              const std::vector<std::string>& overrides = {}) {
  return loadSceneFromString(scene(parameters, mass), "chain.yaml", overrides)
      .model->bodies[0]
      .mass;
}

// p0: 1, p_i: $p_{i-1} + $p_{i-1}: p_n = 2^n.
std::string doublingChain(int n) {
  std::string out = "  p0: 1\n";
  for (int i = 1; i <= n; ++i)
    out += "  p" + std::to_string(i) + ": $p" + std::to_string(i - 1) + " + $p" +
           std::to_string(i - 1) + "\n";
  return out;
}

// p0: 1, p_i: $p_{i-1} + 1, written first to last or last to first.
std::string linearChain(int n, bool reversed) {
  std::vector<std::string> lines{"  p0: 1\n"};
  for (int i = 1; i <= n; ++i)
    lines.push_back("  p" + std::to_string(i) + ": $p" + std::to_string(i - 1) + " + 1\n");
  std::string out;
  if (reversed)
    for (auto it = lines.rbegin(); it != lines.rend(); ++it) out += *it;
  else
    for (const auto& l : lines) out += l;
  return out;
}

double secondsOf(const std::function<void()>& f) {
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

TEST(SceneParameterChains, DoublingChainsAreExactPowersOfTwoInLinearTime) {
  for (const int n : {10, 32, 64}) {
    double mass = 0;
    // 2^32 evaluations per reference would take hours; one per parameter takes milliseconds
    // (the bound is loose for sanitized builds on a loaded machine).
    const double seconds =
        secondsOf([&] { mass = massOf(doublingChain(n), "$p" + std::to_string(n)); });
    EXPECT_EQ(mass, std::ldexp(1.0, n)) << n;
    EXPECT_LT(seconds, 10.0) << n;
    // As an expression over the top too, and with the root overridden (a number, then an
    // expression): every level sees the override.
    EXPECT_EQ(massOf(doublingChain(n), "$p" + std::to_string(n) + " * 3"), 3 * std::ldexp(1.0, n));
    EXPECT_EQ(massOf(doublingChain(n), "$p" + std::to_string(n), {"p0=3"}), 3 * std::ldexp(1.0, n));
    EXPECT_EQ(massOf(doublingChain(n), "$p" + std::to_string(n), {"p0=6+0.5"}),
              6.5 * std::ldexp(1.0, n));
    // An override in the middle cuts the chain there.
    EXPECT_EQ(massOf(doublingChain(n), "$p" + std::to_string(n), {"p5=1"}), std::ldexp(1.0, n - 5));
  }
}

TEST(SceneParameterChains, LinearChainsOfAnyLengthEvaluateWithoutRecursion) {
  for (const int n : {100, 1000, 10000})
    for (const bool reversed : {false, true}) {
      EXPECT_EQ(massOf(linearChain(n, reversed), "$p" + std::to_string(n)), n + 1.0)
          << n << (reversed ? " reversed" : "");
      EXPECT_EQ(massOf(linearChain(n, reversed), "$p" + std::to_string(n), {"p0=-5"}), n - 5.0);
    }
}

TEST(SceneParameterChains, CyclesOfEveryLengthAreNamedInTheMessage) {
  for (const int length : {1, 2, 5, 100}) {
    std::string parameters;
    std::string loop = "c0";
    for (int i = 0; i < length; ++i) {
      std::string next = "c";  // appended, not "c" + ...: GCC 12's -Wrestrict false alarm
      next += std::to_string((i + 1) % length);
      parameters += "  c" + std::to_string(i) + ": $" + next + " + 1\n";
      loop += " -> " + next;
    }
    const std::string direct = sceneErrorOf(scene(parameters, "$c0 * 2"), "loop.yaml");
    EXPECT_NE(direct.find("loop.yaml:"), std::string::npos) << direct;
    EXPECT_NE(direct.find("bodies[0].mass"), std::string::npos) << direct;
    EXPECT_NE(direct.find("cycle: " + loop), std::string::npos) << length << ": " << direct;
    // Reached through a chain into the loop: the loop is named, and where it was entered.
    const std::string via =
        sceneErrorOf(scene(parameters + "  x: $y * 2\n  y: $c0\n", "$x + 1"), "loop.yaml");
    EXPECT_NE(via.find("cycle: " + loop + " (reached from 'x')"), std::string::npos) << via;
    // An override that breaks the loop makes it load: c_{L-1} = 1, each one before adds 1.
    EXPECT_EQ(massOf(parameters, "$c0", {"c" + std::to_string(length - 1) + "=1"}),
              static_cast<double>(length));
  }
}

TEST(SceneParameterChains, AWideFanOverOneParameterSeesItsOverride) {
  for (const int n : {10, 1000}) {
    std::string parameters = "  base: 2\n";
    std::string total;
    for (int i = 1; i <= n; ++i) {
      parameters += "  f" + std::to_string(i) + ": $base * " + std::to_string(i) + "\n";
      total += (total.empty() ? "" : " + ") + std::string("$f") + std::to_string(i);
    }
    parameters += "  total: " + total + "\n";
    const double sum = n * (n + 1) / 2.0;
    EXPECT_EQ(massOf(parameters, "$total"), 2 * sum) << n;
    EXPECT_EQ(massOf(parameters, "$total", {"base=0.5"}), 0.5 * sum) << n;
  }
}

TEST(SceneParameterChains, SetTakesTheExpressionsOfTheSceneFile) {
  const std::string p = "  m: 4\n  k: 100\n  word: heavy\n";
  EXPECT_EQ(massOf(p, "$k", {"k=6+0.5"}), 6.5);
  EXPECT_EQ(massOf(p, "$k", {"k=2 * $m"}), 8.0);
  EXPECT_EQ(massOf(p, "$k", {"m=5", "k=sqrt($m * 5)"}), 5.0);  // sees the other override
  EXPECT_EQ(massOf(p, "$k", {"k=sqrt($m * 5)", "m=5"}), 5.0);  // in either order
  struct Case {
    std::string set, expected;
  };
  for (const Case& c :
       {Case{"k=abc", "expected a number or an expression, got 'abc'"},
        Case{"k=6+", "from --set k=6+"}, Case{"k=$k + 1", "cycle: k -> k"},
        Case{"k=1/0", "the result is inf"}, Case{"k=$word * 2", "from --set k=$word * 2"},
        Case{"k=$nope", "unknown parameter '$nope'"}}) {
    const std::string e = sceneErrorOf(scene(p, "$k"), "set.yaml", {c.set});
    EXPECT_NE(e.find("set.yaml:3:"), std::string::npos) << c.set << ": " << e;  // k's line
    EXPECT_NE(e.find("parameters.k"), std::string::npos) << c.set << ": " << e;
    EXPECT_NE(e.find(c.expected), std::string::npos) << c.set << ": " << e;
  }
}

}  // namespace
}  // namespace tribo::io
