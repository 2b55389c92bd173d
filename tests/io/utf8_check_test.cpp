// Text that is not well-formed UTF-8, at every entry a user's text has into the scene loader:
// the checker against each class of bad sequence (overlong, lone continuation, cut off at
// the end, surrogate, bytes F5..FF, above U+10FFFF, NUL) and valid multibyte text; then the
// scene file (anywhere in it: a parameter, a name, a comment), --set names and values, and
// the scene path, each refused with a SceneError naming the file and line or option.
#include "io/utf8_check.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/scene_loader.hpp"
#include "support/scene_text.hpp"

namespace tribo::io {
namespace {

using test::sceneErrorOf;

struct Bad {
  std::string bytes;   // a bad sequence
  std::string reason;  // words of the message
};

const std::vector<Bad>& badSequences() {
  static const std::vector<Bad> cases{
      {"\xC0\x80", "overlong"},         {"\xC1\xBF", "overlong"},
      {"\xE0\x80\x80", "overlong"},     {"\xE0\x9F\xBF", "overlong"},
      {"\xF0\x80\x80\x80", "overlong"}, {"\xF0\x8F\xBF\xBF", "overlong"},
      {"\x80", "continuation"},         {"\xBF", "continuation"},
      {"\xED\xA0\x80", "surrogate"},    {"\xED\xBF\xBF", "surrogate"},
      {"\xF4\x90\x80\x80", "U+10FFFF"}, {"\xF5\x80\x80\x80", "never used"},
      {"\xF8", "never used"},           {"\xFE", "never used"},
      {"\xFF", "never used"},           {"\xC3\x41", "not followed"},
      {"\xE6\x91\x41", "not followed"}, {std::string(1, '\0'), "NUL"}};
  return cases;
}

// Sequences cut off by the end of the text (they are fine with their last bytes).
const std::vector<std::string>& truncatedAtEnd() {
  static const std::vector<std::string> cases{"\xC3", "\xE6", "\xE6\x91", "\xF0\x9F",
                                              "\xF0\x9F\x98"};
  return cases;
}

const std::vector<std::string>& goodTexts() {
  static const std::vector<std::string> cases{"",
                                              "plain",
                                              "\xC2\xB5",                  // µ
                                              "\xE6\x91\xA9\xE6\x93\xA6",  // 摩擦
                                              "\xF0\x9F\x98\x80",          // U+1F600
                                              "\xED\x9F\xBF",  // U+D7FF, just below the surrogates
                                              "\xEE\x80\x80",  // U+E000, just above them
                                              "\xF4\x8F\xBF\xBF",  // U+10FFFF, the last code point
                                              "\xC2\x80",
                                              "\xE0\xA0\x80",
                                              "\xF0\x90\x80\x80"};  // the smallest of each length
  return cases;
}

TEST(Utf8Check, EachClassOfBadSequenceIsFoundWhereItStarts) {
  for (const Bad& b : badSequences())
    for (const std::string& before :
         {std::string(), std::string("ab\n"), std::string("\xC2\xB5")}) {
      const std::string text = before + b.bytes + "tail";
      EXPECT_EQ(firstBadUtf8(text), before.size()) << b.reason;
      const std::string why = badUtf8Reason(text, before.size());
      EXPECT_NE(why.find(b.reason), std::string::npos) << why;
      // The printable form is valid UTF-8 and keeps the good text around.
      const std::string shown = printableText(text);
      EXPECT_EQ(firstBadUtf8(shown), std::string::npos) << shown;
      EXPECT_NE(shown.find("\\x"), std::string::npos) << shown;
      EXPECT_NE(shown.find("tail"), std::string::npos) << shown;
    }
  for (const std::string& t : truncatedAtEnd()) {
    EXPECT_EQ(firstBadUtf8("ab" + t), 2u) << printableText(t);
    EXPECT_NE(badUtf8Reason("ab" + t, 2).find("cut off"), std::string::npos);
  }
}

TEST(Utf8Check, WellFormedTextOfEveryLengthPasses) {
  for (const std::string& t : goodTexts()) {
    EXPECT_EQ(firstBadUtf8(t), std::string::npos) << printableText(t);
    EXPECT_EQ(printableText(t), t);
  }
  const TextPosition p = positionOf("ab\ncd\nef", 7);
  EXPECT_EQ(p.line, 3);
  EXPECT_EQ(p.column, 2);
}

// A small scene with `text` put into a parameter's value (line 2), a body's name (line 6)
// or a comment (line 3).
std::string sceneWith(const std::string& parameter, const std::string& name,
                      const std::string& comment) {
  return "parameters:\n  k: " + parameter + "\n# " + comment +
         "\nsimulation: {duration: 0.01, time_step: 0.001}\n"
         "bodies:\n  - {name: " +
         name + ", mass: 1, geometry: [{name: g, shape: box, size: [0.1, 0.1, 0.1]}]}\n";
}

TEST(Utf8Check, SceneTextIsRefusedWithTheFileLineAndColumnOfTheFirstBadByte) {
  for (const Bad& b : badSequences()) {
    struct Place {
      std::string scene, where;
    };
    for (const Place& p : {Place{sceneWith("a" + b.bytes, "box", "c"), "bad.yaml:2:7:"},
                           Place{sceneWith("1", "bo" + b.bytes, "c"), "bad.yaml:6:14:"},
                           Place{sceneWith("1", "box", "x" + b.bytes), "bad.yaml:3:4:"}}) {
      const std::string e = sceneErrorOf(p.scene, "bad.yaml");
      EXPECT_NE(e.find(p.where), std::string::npos) << b.reason << ": " << e;
      EXPECT_NE(e.find("expected UTF-8 text"), std::string::npos) << e;
      EXPECT_NE(e.find(b.reason), std::string::npos) << e;
      EXPECT_EQ(firstBadUtf8(e), std::string::npos) << "the message itself is UTF-8";
    }
  }
  for (const std::string& t : truncatedAtEnd()) {
    const std::string e = sceneErrorOf(sceneWith("1", "box", "c") + "# " + t, "end.yaml");
    EXPECT_NE(e.find("end.yaml:7:3:"), std::string::npos) << e;
    EXPECT_NE(e.find("cut off"), std::string::npos) << e;
  }
}

TEST(Utf8Check, SetNamesAndValuesAreRefusedNamingTheOption) {
  for (const Bad& b : badSequences())
    for (const std::string& set : {"k=" + b.bytes, "k=1" + b.bytes, "k" + b.bytes + "=1"}) {
      const std::string e = sceneErrorOf(sceneWith("1", "box", "c"), "set.yaml", {set});
      EXPECT_NE(e.find("set.yaml: --set "), std::string::npos) << e;
      EXPECT_NE(e.find("expected UTF-8 text"), std::string::npos) << e;
      EXPECT_EQ(firstBadUtf8(e), std::string::npos) << "the message itself is UTF-8";
    }
  // A text parameter takes any valid UTF-8 from --set, and from the file.
  for (const std::string& t : goodTexts()) {
    if (t.empty() || t == "\xC2\x80") continue;  // U+0080: a control character, not YAML text
    const Scene s = loadSceneFromString(sceneWith("word", "box", "c"), "ok.yaml", {"k=" + t});
    EXPECT_EQ(s.parameters.at(0).second, t);
    EXPECT_NO_THROW(loadSceneFromString(sceneWith(t, "b" + t, t), "ok.yaml"));
  }
}

TEST(Utf8Check, AScenePathThatIsNotUtf8IsRefusedBeforeItIsRead) {
  for (const Bad& b : badSequences()) {
    if (b.bytes.find('\0') != std::string::npos) continue;  // not a path
    try {
      (void)loadScene("/tmp/scene" + b.bytes + ".yaml");
      ADD_FAILURE() << "loaded";
    } catch (const SceneError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("scene file path '/tmp/scene\\x"), std::string::npos) << what;
      EXPECT_NE(what.find("expected UTF-8 text"), std::string::npos) << what;
    }
  }
}

}  // namespace
}  // namespace tribo::io
