#include "io/utf8_check.hpp"

#include <cstdio>

namespace tribo::io {
namespace {

enum class Fault {
  kNone,
  kNul,
  kContinuation,
  kInvalidLead,
  kTruncated,
  kOverlong,
  kSurrogate,
  kTooLarge,
  kBadContinuation
};

// Checks the character starting at `i`; on success `length` is its number of bytes.
Fault check(std::string_view text, std::size_t i, std::size_t& length) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char c = byte(i);
  if (c == 0) return Fault::kNul;
  if (c < 0x80) {
    length = 1;
    return Fault::kNone;
  }
  if (c < 0xC0) return Fault::kContinuation;
  if (c < 0xC2) return Fault::kOverlong;  // C0, C1: a 2-byte form of U+0000..U+007F
  if (c > 0xF4) return Fault::kInvalidLead;
  const std::size_t n = c < 0xE0 ? 2 : c < 0xF0 ? 3 : 4;
  if (i + n > text.size()) {
    for (std::size_t k = i + 1; k < text.size(); ++k)
      if ((byte(k) & 0xC0) != 0x80) return Fault::kBadContinuation;
    return Fault::kTruncated;
  }
  for (std::size_t k = 1; k < n; ++k)
    if ((byte(i + k) & 0xC0) != 0x80) return Fault::kBadContinuation;
  const unsigned char second = byte(i + 1);
  if (c == 0xE0 && second < 0xA0) return Fault::kOverlong;
  if (c == 0xED && second >= 0xA0) return Fault::kSurrogate;
  if (c == 0xF0 && second < 0x90) return Fault::kOverlong;
  if (c == 0xF4 && second >= 0x90) return Fault::kTooLarge;
  length = n;
  return Fault::kNone;
}

std::string hexByte(unsigned char c) {
  char out[8];
  std::snprintf(out, sizeof out, "0x%02X", static_cast<unsigned>(c));
  return out;
}

}  // namespace

std::size_t firstBadUtf8(std::string_view text) {
  for (std::size_t i = 0; i < text.size();) {
    std::size_t n = 0;
    if (check(text, i, n) != Fault::kNone) return i;
    i += n;
  }
  return std::string::npos;
}

std::string badUtf8Reason(std::string_view text, std::size_t offset) {
  if (offset >= text.size()) return "no bad byte";
  std::size_t n = 0;
  const Fault f = check(text, offset, n);
  std::string why;
  switch (f) {
    case Fault::kNone:
      return "no bad byte";
    case Fault::kNul:
      why = "a NUL character";
      break;
    case Fault::kContinuation:
      why = "a continuation byte with no lead byte";
      break;
    case Fault::kInvalidLead:
      why = "never used in UTF-8";
      break;
    case Fault::kTruncated:
      why = "a multi-byte sequence cut off by the end of the text";
      break;
    case Fault::kOverlong:
      why = "an overlong encoding";
      break;
    case Fault::kSurrogate:
      why = "a UTF-16 surrogate, U+D800..U+DFFF";
      break;
    case Fault::kTooLarge:
      why = "a code point above U+10FFFF";
      break;
    case Fault::kBadContinuation:
      why = "a lead byte not followed by its continuation bytes";
      break;
  }
  return "byte " + hexByte(static_cast<unsigned char>(text[offset])) + " (" + why + ")";
}

TextPosition positionOf(std::string_view text, std::size_t offset) {
  TextPosition p;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++p.line;
      p.column = 1;
    } else {
      ++p.column;
    }
  }
  return p;
}

std::string printableText(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    std::size_t n = 0;
    if (check(text, i, n) == Fault::kNone) {
      out.append(text.substr(i, n));
      i += n;
    } else {
      char esc[8];
      std::snprintf(esc, sizeof esc, "\\x%02X",
                    static_cast<unsigned>(static_cast<unsigned char>(text[i])));
      out += esc;
      ++i;
    }
  }
  return out;
}

}  // namespace tribo::io
