// Sweep grids: the values an axis spans, the order of the points, and the errors a user
// sees for malformed --grid/--list options.
#include "study/sweep/sweep_grid.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace tribo::study {
namespace {

using Values = std::vector<std::string>;

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
// neighbours, so one pass finds them.
TEST(SweepGrid, ManyValuesParseInOnePassAndCloseValuesStillCollide) {
  const SweepAxis a = parseGridAxis("a=0:1:3913919");
  ASSERT_EQ(a.values.size(), 3913919u);
  EXPECT_EQ(a.values.front(), "0");
  EXPECT_EQ(a.values.back(), "1");
  // Steps below the 12 significant digits of the text give neighbours with the same text.
  EXPECT_THROW(parseGridAxis("a=1:1.000000000001:5"), SweepSpecError);
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
        Case{"v_b=1:1:3", true, "appears twice"},
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
  EXPECT_THROW(SweepGrid({parseGridAxis("a=0:1:10000"), parseGridAxis("b=0:1:10000")}),
               SweepSpecError);
}

}  // namespace
}  // namespace tribo::study
