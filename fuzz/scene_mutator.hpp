// Structure-aware mutation of scene YAML for fuzz/scene_yaml_fuzzer (its
// LLVMFuzzerCustomMutator): edits that byte-level mutation rarely makes, on the text read as
// YAML-ish lines ("key: value", the parameters: block, #set lines):
//   - a value becomes an expression or reference ($p, $p + $p, sqrt($p), ...), an extreme or
//     non-finite number (1e308, 1e-320, nan, inf, -0), or text that is not UTF-8;
//   - a parameter chain is added (each parameter `$q + $q` or `$q + 1` of the one before, up
//     to a few hundred long) and a value refers to its end;
//   - a cycle of parameters is added and referred to;
//   - a key is swapped for a word of the generated scene dictionary (io/scene_dictionary.hpp);
//   - a `#set NAME=VALUE` override line is added.
// The result depends only on the input and the random engine, so a seed reproduces it.
// Not here: byte-level mutation (libFuzzer's own), checking the result is valid YAML.
#pragma once

#include <cctype>
#include <cstddef>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "io/scene_dictionary.hpp"

namespace tribo::fuzz {

inline const std::vector<std::string>& hostileValues() {
  static const std::vector<std::string> values{
      "1e308",      "-1e308",    "1e-308",   "4.9e-324",
      "1e-320",     "-0",        "nan",      ".nan",
      "inf",        "-.inf",     "1e309",    "0",
      "2^1023 * 2", "1/0",       "sqrt(-1)", "0 * $p",
      "$p",         "$p + $p",   "$p * $p",  "sqrt($p)",
      "-$p",        "$p deg",    "$",        "$nope",
      "(($p)",      "\xff",      "\xc0\x80", "\xed\xa0\x80",
      "a\x80",      "\xe6\x91",  "\xc2\xb5", "\xe6\x91\xa9\xe6\x93\xa6",
      "''",         "[1, 2, 3]", "{}",       "~"};
  return values;
}

// The names in the block "parameters:\n  NAME: ..." of `text` (block style only).
inline std::vector<std::string> parameterNames(std::string_view text) {
  std::vector<std::string> out;
  const std::size_t head = text.find("parameters:\n");
  if (head == std::string_view::npos || (head != 0 && text[head - 1] != '\n')) return out;
  std::size_t at = head + 12;
  while (at < text.size() && text.compare(at, 2, "  ") == 0) {
    const std::size_t end = text.find('\n', at);
    const std::string_view line =
        text.substr(at + 2, end == std::string_view::npos ? end : end - at - 2);
    const std::size_t colon = line.find(':');
    if (colon != std::string_view::npos && colon > 0) out.emplace_back(line.substr(0, colon));
    if (end == std::string_view::npos) break;
    at = end + 1;
  }
  return out;
}

// Offsets of the values of "key: value" pairs: the character after ": " up to the next
// ',', '}', ']' or line end.
struct Span {
  std::size_t begin, end;
};
inline std::vector<Span> valueSpans(std::string_view text) {
  std::vector<Span> out;
  for (std::size_t at = text.find(": "); at != std::string_view::npos;
       at = text.find(": ", at + 1)) {
    const std::size_t begin = at + 2;
    if (begin >= text.size() || text[begin] == '{' || text[begin] == '[' || text[begin] == '\n')
      continue;
    std::size_t end = text.find_first_of(",}]\n", begin);
    if (end == std::string_view::npos) end = text.size();
    out.push_back({begin, end});
  }
  return out;
}

// Offsets of keys: a word before ": ".
inline std::vector<Span> keySpans(std::string_view text) {
  std::vector<Span> out;
  for (std::size_t at = text.find(": "); at != std::string_view::npos;
       at = text.find(": ", at + 1)) {
    std::size_t begin = at;
    while (begin > 0 &&
           (std::isalnum(static_cast<unsigned char>(text[begin - 1])) || text[begin - 1] == '_'))
      --begin;
    if (begin < at) out.push_back({begin, at});
  }
  return out;
}

// Adds `lines` (each "  NAME: VALUE\n") to the parameters block, making one if there is none.
inline std::string withParameters(std::string text, const std::string& lines) {
  const std::size_t head = text.find("parameters:\n");
  if (head != std::string::npos && (head == 0 || text[head - 1] == '\n'))
    return text.insert(head + 12, lines);
  if (text.find("parameters:") != std::string::npos) return text;  // flow style: leave it
  return "parameters:\n" + lines + text;
}

// `value` with each "$p" made "$NAME". The search resumes after the inserted name, so a name
// that itself holds "$p" is inserted once, not for ever.
inline std::string withName(std::string value, const std::string& name) {
  for (std::size_t at = value.find("$p"); at != std::string::npos;
       at = value.find("$p", at + 1 + name.size()))
    value.replace(at + 1, 1, name);
  return value;
}

template <class Rng>
std::string mutateScene(std::string text, Rng& rng) {
  const auto pick = [&](std::size_t n) { return static_cast<std::size_t>(rng() % n); };
  std::vector<std::string> names = parameterNames(text);
  const std::string p = names.empty() ? "p" : names[pick(names.size())];
  const auto hostile = [&] { return withName(hostileValues()[pick(hostileValues().size())], p); };
  const auto setSomeValue = [&](std::string& t, const std::string& v) {
    const auto spans = valueSpans(t);
    if (spans.empty()) return;
    const Span s = spans[pick(spans.size())];
    t.replace(s.begin, s.end - s.begin, v);
  };
  switch (pick(5)) {
    case 0:
      setSomeValue(text, hostile());
      break;
    case 1: {  // a chain, doubling or linear, referred to from one value
      static constexpr int kLengths[] = {2, 8, 33, 70, 300};
      const int n = kLengths[pick(5)];
      const bool doubling = pick(2) == 0;
      const std::string q = "q" + std::to_string(pick(100)) + "_";
      std::string lines = "  " + q + "0: " + (pick(2) ? "1" : hostile()) + "\n";
      for (int i = 1; i <= n; ++i) {
        const std::string prev = "$" + q + std::to_string(i - 1);
        lines += "  " + q + std::to_string(i) + ": " +
                 (doubling ? prev + " + " + prev : prev + " + 1") + "\n";
      }
      text = withParameters(text, lines);
      setSomeValue(text, "$" + q + std::to_string(n));
      break;
    }
    case 2: {  // a cycle
      const int n = 1 + static_cast<int>(pick(4));
      std::string lines;
      for (int i = 0; i < n; ++i)
        lines += "  c" + std::to_string(i) + ": $c" + std::to_string((i + 1) % n) + " + 1\n";
      text = withParameters(text, lines);
      setSomeValue(text, "$c0");
      break;
    }
    case 3: {  // a key swapped for a dictionary word
      const auto keys = keySpans(text);
      static const std::vector<std::string> words = io::sceneDictionaryWords();
      if (keys.empty() || words.empty()) break;
      const Span s = keys[pick(keys.size())];
      text.replace(s.begin, s.end - s.begin, words[pick(words.size())]);
      break;
    }
    default:  // an override line
      text += "\n#set " + p + "=" + hostile() + "\n";
      break;
  }
  return text;
}

}  // namespace tribo::fuzz
