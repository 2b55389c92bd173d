// Parameter grids for sweeps: the axes given on the command line and the points they span.
//   --grid NAME=START:STOP:COUNT   COUNT values evenly spaced from START to STOP, both ends
//                                  included: v_i = START + i (STOP - START) / (COUNT - 1)
//                                  (COUNT = 1 gives START alone)
//   --list NAME=V1,V2,...          the values as written: numbers or words
//                                  (friction=roh_yoo,recurdyn)
// The points are the Cartesian product of the axes in row-major order: the first axis varies
// slowest, the last fastest, so point i is the same point in every run of the same axes.
// Values are kept as text, and a point's override NAME=TEXT uses that text: a grid value is
// written with 12 significant digits (0.1:0.3:3 gives 0.1, 0.2, 0.3), so the text, and the
// value the scene reads, is the same in every run; the two ends read back exactly as the
// numbers given (more digits when 12 do not hold them). When two neighbours agree to 12 digits
// (1:1.000000000001:5), the axis's values are written with the digits each needs to read
// back exactly; neighbours equal as doubles are an error. Ends may be any finite numbers
// (-1e308:1e308:3 gives -1e+308, 0, 1e+308).
// A sweep has at most SweepGrid::kMaxPoints points (1,000,000): a --grid COUNT above it is
// refused before any value is made, and so is a product of axes above it.
// Option text must be well-formed UTF-8 (io/utf8_check.hpp).
// Not here: whether NAME is a parameter of the scene (loading the point's scene says so),
// running points, files.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace tribo::study {

// A malformed --grid/--list option or grid. what() reads
//   "--grid 'v_b=1:5': expected NAME=START:STOP:COUNT, found 2 fields"
class SweepSpecError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

struct SweepAxis {
  std::string name;                 // a scene parameter name
  std::vector<std::string> values;  // in sweep order, no duplicates
};

// "NAME=START:STOP:COUNT" (the text after --grid). Throws SweepSpecError.
SweepAxis parseGridAxis(std::string_view spec);
// "NAME=V1,V2,..." (the text after --list). Throws SweepSpecError.
SweepAxis parseListAxis(std::string_view spec);

class SweepGrid {
 public:
  // Largest number of points a grid may span.
  // Largest number of points a grid may span (README, Parameter sweeps): a million runs is
  // already weeks of simulation; beyond it sweep.json and the plan's memory grow past use.
  static constexpr std::size_t kMaxPoints = 1'000'000;

  // Throws SweepSpecError for no axes, an axis without values, a name given twice, or more
  // than kMaxPoints points (naming the count, the axes and the limit).
  explicit SweepGrid(std::vector<SweepAxis> axes);

  const std::vector<SweepAxis>& axes() const { return axes_; }
  std::size_t size() const { return size_; }

  // Value of each axis at point `i` (< size()), in axis order.
  std::vector<std::string> values(std::size_t i) const;
  // The same as NAME=VALUE overrides for the scene loader.
  std::vector<std::string> overrides(std::size_t i) const;

 private:
  std::vector<SweepAxis> axes_;
  std::size_t size_ = 0;
};

}  // namespace tribo::study
