// The text of result files, written one way everywhere: numbers in the shortest exact
// form to a chosen number of significant digits (std::to_chars, locale-free; non-finite
// numbers become empty fields, never "nan"), CSV fields quoted when they hold a comma or a
// quote (RFC 4180: quotes doubled; line breaks become spaces so each row stays one line),
// and rows of fields. Not here: reading CSV (study/sweep/sweep_results.cpp), messages
// (core/number_text.hpp words numbers for people).
#pragma once

#include <string>
#include <vector>

namespace tribo::study {

// `digits` significant digits (10 by default: far below every figure's accuracy, and short).
std::string csvNumber(double v, int digits = 10);
// The same into [first, last) without allocating (bulk writers); returns the end of the text.
char* csvNumberTo(char* first, char* last, double v, int digits = 10);
std::string csvField(std::string text);
// Fields joined by commas, each through csvField, ending in a line break.
std::string csvLine(const std::vector<std::string>& fields);

}  // namespace tribo::study
