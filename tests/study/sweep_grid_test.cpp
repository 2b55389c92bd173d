// Sweep grids: the values an axis spans, the order of the points, and the errors a user
// sees for malformed --grid/--list options.
#include "study/sweep/sweep_grid.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace tribo::study {
namespace {

using Values = std::vector<std::string>;

// The number a value's text reads as (strtod: std::stod refuses subnormal numbers).
double number(const std::string& text) { return std::strtod(text.c_str(), nullptr); }

TEST(SweepGrid, GridSpansCountValuesWithBothEnds) {
  const SweepAxis a = parseGridAxis("v_b=0.5:5:4");
  EXPECT_EQ(a.name, "v_b");
  EXPECT_EQ(a.values, (Values{"0.5", "2", "3.5", "5"}));
  // Twelve significant digits keep decimal steps decimal.
  EXPECT_EQ(parseGridAxis("x=0.1:0.3:3").values, (Values{"0.1", "0.2", "0.3"}));
  EXPECT_EQ(parseGridAxis("x=3:1:3").values, (Values{"3", "2", "1"}));  // descending
  EXPECT_EQ(parseGridAxis("x=2:2:1").values, (Values{"2"}));
  EXPECT_EQ(parseGridAxis("mu_s=0.31:0.5:20").values.back(), "0.5");
}

// fuzz/regressions/cli_values_fuzzer/timeout-grid-count-3913919: a grid of millions of values
// took over 10 s (a set of every value's text to find duplicates); equal texts of a grid are
// neighbours, so one pass finds them. Grids are now at most kMaxPoints, refused before any
// value is made.
TEST(SweepGrid, ManyValuesParseInOnePassAndCloseValuesGetTheDigitsTheyNeed) {
  const SweepAxis a = parseGridAxis("a=0:1:" + std::to_string(SweepGrid::kMaxPoints));
  ASSERT_EQ(a.values.size(), SweepGrid::kMaxPoints);
  EXPECT_EQ(a.values.front(), "0");
  EXPECT_EQ(a.values.back(), "1");
  // Steps below the 12 significant digits of the text: the axis is written exactly.
  const Values close = parseGridAxis("a=1:1.000000000001:5").values;
  ASSERT_EQ(close.size(), 5u);
  for (std::size_t i = 0; i < close.size(); ++i) {
    const double expected = std::lerp(1.0, 1.000000000001, i / 4.0);
    EXPECT_EQ(number(close[i]), i == 4 ? 1.000000000001 : expected) << close[i];
    if (i > 0) {
      EXPECT_LT(number(close[i - 1]), number(close[i]));
    }
  }
  // Steps below a double's precision: neighbours would be the same number.
  try {
    parseGridAxis("a=1:1.0000000000000002:5");
    ADD_FAILURE() << "accepted";
  } catch (const SweepSpecError& e) {
    EXPECT_NE(std::string(e.what()).find("below the precision of a double"), std::string::npos)
        << e.what();
  }
}

// Ends of every magnitude, both signs, equal ends and counts 1, 2, 3 and many: values are
// finite, distinct, in order, read back as the evenly spaced numbers, and never the empty
// text a non-finite middle value once gave ("value '' appears twice" for -1e308:1e308:3).
TEST(SweepGrid, EndsOfEveryMagnitudeGiveDistinctFiniteValues) {
  const std::vector<std::pair<double, double>> ends{
      {-1e308, 1e308},    {1e308, -1e308},   {-1.7976931348623157e308, 1.7976931348623157e308},
      {1e300, 2e300},     {-1e-300, 1e-300}, {1e-300, 3e-300},
      {4.9e-324, 1e-320}, {0, 1e-300},       {-5, 7}};
  for (const auto& [start, stop] : ends)
    for (const long count : {2L, 3L, 4L, 11L, 1001L}) {
      char text[120];
      std::snprintf(text, sizeof text, "x=%.17g:%.17g:%ld", start, stop, count);
      const SweepAxis a = parseGridAxis(text);
      ASSERT_EQ(a.values.size(), static_cast<std::size_t>(count)) << text;
      for (std::size_t i = 0; i < a.values.size(); ++i) {
        ASSERT_FALSE(a.values[i].empty()) << text;
        const double v = number(a.values[i]);
        EXPECT_TRUE(std::isfinite(v)) << text;
        const double expected = std::lerp(start, stop, static_cast<double>(i) / (count - 1));
        // The text reads back to the value to its 12 digits, or exactly.
        EXPECT_NEAR(v, expected, 1e-11 * std::max(std::abs(start), std::abs(stop))) << text;
        if (i > 0) {
          EXPECT_NE(a.values[i], a.values[i - 1]) << text;
        }
      }
      EXPECT_EQ(number(a.values.front()), start) << text;
      EXPECT_EQ(number(a.values.back()), stop) << text;
    }
  EXPECT_EQ(parseGridAxis("v_b=-1e308:1e308:3").values, (Values{"-1e+308", "0", "1e+308"}));
  // Equal ends: one value (COUNT 1), else the same value twice.
  for (const std::string v : {"1e-300", "1e300", "0", "-2.5"}) {
    EXPECT_EQ(parseGridAxis("x=" + v + ":" + v + ":1").values.size(), 1u);
    for (const std::string count : {"2", "3", "1000"})
      EXPECT_THROW(parseGridAxis("x=" + v + ":" + v + ":" + count), SweepSpecError) << v;
  }
}

// A grid is sized before it is made: a COUNT past kMaxPoints, or axes whose product is,
// fails at once naming the count and the limit (a 10-million-point grid once took 2.4 GB
// and wrote a 249 MB sweep.json before its first point).
TEST(SweepGrid, HugeGridsAreRefusedBeforeTheyAreMadeNamingCountAndLimit) {
  const std::string limit = std::to_string(SweepGrid::kMaxPoints);
  for (const std::string& count :
       {std::to_string(SweepGrid::kMaxPoints + 1), std::string("10000000"),
        std::string("9223372036854775807"), std::string("99999999999999999999999")}) {
    const auto t0 = std::chrono::steady_clock::now();
    try {
      parseGridAxis("a=0:1:" + count);
      ADD_FAILURE() << count << " accepted";
    } catch (const SweepSpecError& e) {
      EXPECT_NE(std::string(e.what()).find(limit), std::string::npos) << e.what();
    }
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 0.5);
  }
  for (const auto& [a, b] : std::vector<std::pair<int, int>>{{1001, 1000}, {10000, 10000}}) {
    try {
      SweepGrid({parseGridAxis("a=0:1:" + std::to_string(a)),
                 parseGridAxis("b=0:1:" + std::to_string(b))});
      ADD_FAILURE() << a << " x " << b << " accepted";
    } catch (const SweepSpecError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(std::to_string(a) + " a x " + std::to_string(b) + " b"),
                std::string::npos)
          << what;
      EXPECT_NE(what.find(limit), std::string::npos) << what;
    }
  }
  EXPECT_EQ(SweepGrid({parseGridAxis("a=0:1:1000"), parseGridAxis("b=0:1:1000")}).size(),
            SweepGrid::kMaxPoints);
}

// --grid and --list text that is not UTF-8 (it would reach sweep.json): refused at parse,
// naming the option, with the bad bytes shown as \xNN.
TEST(SweepGrid, OptionTextThatIsNotUtf8IsRefusedNamingTheOption) {
  for (const std::string& bad :
       {std::string("\xC0\x80"), std::string("\x80"), std::string("\xED\xA0\x80"),
        std::string("\xF5"), std::string("\xFF"), std::string("\xE6\x91")})
    for (const bool grid : {false, true})
      for (const std::string& spec :
           grid ? std::vector<std::string>{"k" + bad + "=1:2:2", "k=1:2:2" + bad}
                : std::vector<std::string>{"k=a" + bad + ",b", "k=a,b" + bad, "k" + bad + "=a"}) {
        try {
          grid ? parseGridAxis(spec) : parseListAxis(spec);
          ADD_FAILURE() << "accepted";
        } catch (const SweepSpecError& e) {
          const std::string what = e.what();
          EXPECT_EQ(what.rfind(grid ? "--grid '" : "--list '", 0), 0u) << what;
          EXPECT_NE(what.find("expected UTF-8 text"), std::string::npos) << what;
          EXPECT_NE(what.find("\\x"), std::string::npos) << what;
        }
      }
  EXPECT_EQ(parseListAxis("law=\xC2\xB5,\xE6\x91\xA9\xE6\x93\xA6").values,
            (Values{"\xC2\xB5", "\xE6\x91\xA9\xE6\x93\xA6"}));
}

TEST(SweepGrid, ListKeepsTheValuesAsWritten) {
  const SweepAxis a = parseListAxis("friction=roh_yoo,recurdyn");
  EXPECT_EQ(a.name, "friction");
  EXPECT_EQ(a.values, (Values{"roh_yoo", "recurdyn"}));
  EXPECT_EQ(parseListAxis("k=1e3,300").values, (Values{"1e3", "300"}));
}

TEST(SweepGrid, MalformedOptionsNameTheOptionAndWhatWasExpected) {
  struct Case {
    std::string spec;
    bool grid;
    std::string expected;
  };
  for (const Case& c :
       {Case{"v_b", true, "found no '='"}, Case{"v_b=1:5", true, "found 2 fields"},
        Case{"v_b=1:x:3", true, "STOP: expected a number, found 'x'"},
        Case{"v_b=1:5:0", true, "COUNT: expected a whole number"},
        Case{"v_b=1:5:2.5", true, "COUNT: expected a whole number"},
        Case{"v_b=1:5:1", true, "COUNT 1 needs START = STOP"},
        Case{"v_b=1:1:3", true, "values 1 and 2 are both 1"},
        Case{"1x=1:2:2", true, "expected a parameter name"},
        Case{"k=1,,2", false, "expected a value between commas"},
        Case{"k=1,2,1", false, "value '1' appears twice"}, Case{"k", false, "found no '='"}}) {
    try {
      c.grid ? parseGridAxis(c.spec) : parseListAxis(c.spec);
      ADD_FAILURE() << c.spec << " was accepted";
    } catch (const SweepSpecError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(c.grid ? "--grid '" + c.spec + "'" : "--list '" + c.spec + "'"),
                std::string::npos)
          << what;
      EXPECT_NE(what.find(c.expected), std::string::npos) << what;
    }
  }
}

TEST(SweepGrid, PointsAreTheProductWithTheLastAxisFastest) {
  const SweepGrid g({parseListAxis("a=1,2"), parseListAxis("b=x,y,z")});
  ASSERT_EQ(g.size(), 6u);
  EXPECT_EQ(g.values(0), (Values{"1", "x"}));
  EXPECT_EQ(g.values(1), (Values{"1", "y"}));
  EXPECT_EQ(g.values(3), (Values{"2", "x"}));
  EXPECT_EQ(g.values(5), (Values{"2", "z"}));
  EXPECT_EQ(g.overrides(4), (Values{"a=2", "b=y"}));
  EXPECT_THROW(g.values(6), std::out_of_range);
}

TEST(SweepGrid, RejectsEmptyRepeatedAndHugeGrids) {
  EXPECT_THROW(SweepGrid({}), SweepSpecError);
  EXPECT_THROW(SweepGrid({parseListAxis("a=1,2"), parseListAxis("a=3")}), SweepSpecError);
  EXPECT_THROW(SweepGrid({SweepAxis{"a", {}}}), SweepSpecError);
}

}  // namespace
}  // namespace tribo::study
