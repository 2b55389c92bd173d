// Checks the sizes a COLLADA (DAE) document declares against what it holds, before assimp
// reads it. assimp 5.2.5 (Debian 12) trusts them: it reserves memory for an array's or a
// primitive list's `count` before reading the values (a `count` of 4e9 in a 1 kB file asks
// for gigabytes), and it reads a <p> index list until its end, which a token that is not a
// number never lets it reach (it appends zeros until memory runs out); it reads an
// accessor's values without checking the array holds them. Refused here, with
// contact::MeshError naming the file, the element, its line and the numbers expected and
// found:
//   - a `count`, `stride` or `offset` attribute that is not a whole number, or a count (times
//     its stride) larger than the file's bytes could hold (each value takes at least a byte);
//   - an `*_array` whose `count` exceeds the values written in it;
//   - a <p> or <vcount> list with anything but whole numbers between spaces, vcounts summing
//     past the file's size;
//   - a <triangles>, <lines> or <polylist> whose `count` needs more indices in a <p> (times
//     the inputs per vertex, the largest `offset` + 1) than the <p> holds; the other
//     primitive lists need at least `count` times the inputs per vertex indices in all;
//   - an <accessor> reading past what its array declares (offset + count x stride), with a
//     stride below the values its <param>s name, or reading numbers for a mesh from a
//     Name_array or IDREF_array: assimp reads such values unchecked, past the array's end or
//     from address 0.
// Not here: XML well-formedness, references between elements, what assimp itself reads
// safely (it refuses a <p> whose length differs from the count); other formats.
#pragma once

#include <string>
#include <string_view>

namespace tribo::io {

// Throws contact::MeshError "mesh file 'NAME': line L: ..." for the first size that does not fit.
void checkColladaSizes(std::string_view text, const std::string& name);

}  // namespace tribo::io
