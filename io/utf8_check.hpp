// Well-formed UTF-8 for every text a user gives Tribo (scene files, URDF files, --set,
// --list, paths that end up in JSON): the check, and the words of its error messages.
// Well-formed means RFC 3629: no overlong encodings, no surrogates (U+D800..U+DFFF), nothing
// above U+10FFFF, no lone continuation bytes, no sequence cut off by the end of the text.
// NUL is refused too: no text file or argument of Tribo's holds one.
// Not here: what a caller throws (each entry point raises its own typed error, naming its
// file or option), any conversion or repair of the text.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace tribo::io {

// Offset of the first byte of `text` that does not start a well-formed UTF-8 character (or
// is a NUL); std::string::npos when the whole text is well-formed.
std::size_t firstBadUtf8(std::string_view text);

// What is wrong at `offset` (a result of firstBadUtf8), e.g.
//   "byte 0xC0 (an overlong encoding)", "byte 0xED (a UTF-16 surrogate, U+D800..U+DFFF)",
//   "byte 0xE6 (a 3-byte sequence cut off by the end of the text)".
std::string badUtf8Reason(std::string_view text, std::size_t offset);

// 1-based line and column (in bytes) of `offset` in `text`.
struct TextPosition {
  int line = 1;
  int column = 1;
};
TextPosition positionOf(std::string_view text, std::size_t offset);

// `text` for an error message: bytes that are not well-formed UTF-8 become \xNN, so that
// the message itself is valid UTF-8 (it may go into a JSON file).
std::string printableText(std::string_view text);

}  // namespace tribo::io
