// docs/scene-format.md, the reference of every scene key, against the tables the loader checks
// each mapping with (io/scene_keys.hpp): each section there has a heading in the document
// naming it in backticks ("Top level" for the top level) with one key table under it, whose
// first column lists exactly that section's keys, each in backticks; every key table of the
// document is under such a heading; and every word the loader accepts in place of a value
// (body kinds, shapes, ...) appears in the document in backticks. So a key added to the loader
// without its line in the document, or a line left for a key that is gone, fails here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "io/scene_keys.hpp"

namespace tribo::io {
namespace {

const char* const kDoc = TRIBO_SOURCE_DIR "/docs/scene-format.md";

std::vector<std::string> docLines() {
  std::ifstream in(kDoc);
  EXPECT_TRUE(in) << kDoc;
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// The text between each pair of backticks of `line`.
std::vector<std::string> codeSpans(const std::string& line) {
  std::vector<std::string> out;
  for (std::size_t open = line.find('`'); open != std::string::npos;) {
    const std::size_t close = line.find('`', open + 1);
    if (close == std::string::npos) break;
    out.push_back(line.substr(open + 1, close - open - 1));
    open = line.find('`', close + 1);
  }
  return out;
}

std::string trimmed(const std::string& s) {
  const auto begin = s.find_first_not_of(' ');
  const auto end = s.find_last_not_of(' ');
  return begin == std::string::npos ? "" : s.substr(begin, end - begin + 1);
}

// The section a heading names: its first code span, else its text in lower case within
// parentheses ("## Top level" -> "(top level)", as io/scene_keys.hpp names it).
std::string sectionOf(const std::string& heading) {
  const auto spans = codeSpans(heading);
  if (!spans.empty()) return spans.front();
  std::string text = trimmed(heading.substr(heading.find_first_not_of('#')));
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return "(" + text + ")";
}

// The first cell of a table row.
std::string firstCell(const std::string& row) {
  const auto end = row.find('|', 1);
  return trimmed(row.substr(1, end == std::string::npos ? std::string::npos : end - 1));
}

struct KeyTables {
  std::map<std::string, std::vector<std::string>> keys;  // by section: the first column's keys
  std::vector<std::string> problems;                     // tables the document cannot have
};

// Every key table (a table whose header's first cell is "key") by the section of the heading
// above it.
KeyTables keyTables(const std::vector<std::string>& lines) {
  KeyTables out;
  std::string section;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string& line = lines[i];
    if (line.rfind('#', 0) == 0) section = sectionOf(line);
    if (line.rfind('|', 0) != 0 || firstCell(line) != "key") continue;
    if (out.keys.count(section)) out.problems.push_back("a second key table under " + section);
    std::vector<std::string>& keys = out.keys[section];
    for (++i; i < lines.size() && lines[i].rfind('|', 0) == 0; ++i) {
      const std::string cell = firstCell(lines[i]);
      if (cell.rfind("---", 0) == 0) continue;
      const auto spans = codeSpans(cell);
      if (spans.size() != 1 || "`" + spans.front() + "`" != cell)
        out.problems.push_back(section + ": a key table row whose key is not one `key`: " + cell);
      else
        keys.push_back(spans.front());
    }
    --i;
  }
  return out;
}

bool isWords(const scene_keys::Section& s) { return std::string(s.where).rfind("(words)", 0) == 0; }

TEST(SceneFormatDoc, EachSectionHasAKeyTableListingExactlyItsKeys) {
  const KeyTables tables = keyTables(docLines());
  for (const std::string& p : tables.problems) ADD_FAILURE() << kDoc << ": " << p;
  std::set<std::string> sections;
  for (const auto& s : scene_keys::sections()) {
    if (isWords(s)) continue;
    sections.insert(s.where);
    const auto table = tables.keys.find(s.where);
    if (table == tables.keys.end()) {
      ADD_FAILURE() << kDoc << ": no heading naming `" << s.where << "` with a key table under it";
      continue;
    }
    std::string missing, extra;
    for (const std::string& key : *s.words)
      if (std::count(table->second.begin(), table->second.end(), key) != 1) missing += " " + key;
    for (const std::string& key : table->second)
      if (std::count(s.words->begin(), s.words->end(), key) != 1) extra += " " + key;
    EXPECT_EQ(missing, "") << kDoc << ", " << s.where
                           << ": keys io/scene_keys.hpp accepts, not listed once in the table";
    EXPECT_EQ(extra, "") << kDoc << ", " << s.where
                         << ": keys the table lists that io/scene_keys.hpp does not accept";
  }
  for (const auto& [section, keys] : tables.keys)
    EXPECT_TRUE(sections.count(section))
        << kDoc << ": a key table under " << section << ", which io/scene_keys.hpp has no table of";
}

TEST(SceneFormatDoc, EveryAcceptedWordAppearsInBackticks) {
  std::string text;  // one line: a code span may run over a line break
  for (const std::string& line : docLines()) text += line + " ";
  std::set<std::string> spans;
  for (const std::string& span : codeSpans(text)) spans.insert(span);
  for (const auto& s : scene_keys::sections())
    for (const std::string& word : *s.words)
      EXPECT_TRUE(spans.count(word))
          << kDoc << ": `" << word << "` (" << s.where << ") is not in it";
}

}  // namespace
}  // namespace tribo::io
