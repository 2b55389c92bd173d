#include "io/collada_check.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "contact/mesh_shape.hpp"

namespace tribo::io {

namespace {

using Count = std::uint64_t;
constexpr Count kHuge = std::numeric_limits<Count>::max();

// Saturating arithmetic: a product past 2^64 stays "too many".
Count times(Count a, Count b) { return (a != 0 && b > kHuge / a) ? kHuge : a * b; }
Count plus(Count a, Count b) { return b > kHuge - a ? kHuge : a + b; }

// The separators assimp skips between the numbers of a list (it also stops at others).
bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
bool isDigit(char c) { return c >= '0' && c <= '9'; }

// Built by appending: GCC 12 warns (-Wrestrict, wrongly) on "text" + std::string temporaries.
std::string quoted(std::string_view s) {
  constexpr std::size_t kShown = 20;
  std::string out("'");
  out.append(s.substr(0, kShown)).append(s.size() > kShown ? "...'" : "'");
  return out;
}

std::string tagOf(std::string_view name) {
  std::string out("<");
  out.append(name).push_back('>');
  return out;
}

// A primitive list (<triangles>, <polylist>, ...) being read: what its <p> lists must hold.
struct Primitives {
  std::string name;
  int line = 0;
  Count count = 0;
  Count inputs = 1;    // indices per vertex: the largest <input> offset + 1
  Count vertices = 0;  // <polylist>: the sum of its <vcount>
  Count vcounts = 0;   // <polylist>: how many <vcount> numbers it has
  bool has_vcount = false;
  struct List {
    int line;
    Count numbers;
  };
  std::vector<List> lists;  // its <p> elements
};

constexpr std::pair<std::string_view, std::string_view> kSkipped[] = {
    {"<!--", "-->"}, {"<![CDATA[", "]]>"}, {"<?", "?>"}, {"<!", ">"}};

// An <accessor>: where it reads in which array.
struct Accessor {
  int line = 0;
  std::string source;  // the array's id
  Count count = 0;
  Count stride = 1;
  Count offset = 0;
  Count width = 0;     // values per element its <param>s name
  std::string holder;  // the id of the <source> it is in
};

// What assimp keeps of an array: how many values it reads, and whether they are numbers.
struct Array {
  Count count = 0;
  bool numbers = true;  // float_array, not a Name_array or IDREF_array
};

class Checker {
 public:
  Checker(std::string_view text, const std::string& name) : text_(text), name_(name) {}

  void run() {
    std::size_t pos = 0;
    while ((pos = text_.find('<', pos)) != std::string_view::npos) {
      // Comments, CDATA, processing instructions and declarations hold no element.
      bool skipped = false;
      for (const auto& [open, close] : kSkipped) {
        if (text_.substr(pos).starts_with(open)) {
          const std::size_t end = text_.find(close, pos + open.size());
          pos = end == std::string_view::npos ? text_.size() : end + close.size();
          skipped = true;
          break;
        }
      }
      if (!skipped) pos = tag(pos);
    }
    while (!open_.empty()) {  // not closed: checked all the same
      finish(open_.back());
      open_.pop_back();
    }
    for (const Accessor& a : accessors_) check(a);
  }

 private:
  [[noreturn]] void fail(int line, const std::string& what) const {
    throw contact::MeshError("mesh file '" + name_ + "': line " + std::to_string(line) + ": " +
                             what);
  }

  // The line of a position; positions are asked for in increasing order.
  int lineAt(std::size_t pos) {
    line_ += static_cast<int>(std::count(text_.begin() + static_cast<long>(counted_),
                                         text_.begin() + static_cast<long>(pos), '\n'));
    counted_ = pos;
    return line_;
  }

  // The value of attribute `key` in a tag's attribute text (the first, as the XML parser
  // assimp uses does), without its quotes.
  static std::optional<std::string_view> attribute(std::string_view attrs, std::string_view key) {
    std::size_t i = 0;
    while (i < attrs.size()) {
      while (i < attrs.size() && (isSpace(attrs[i]) || attrs[i] == '/')) ++i;
      const std::size_t name_begin = i;
      while (i < attrs.size() && attrs[i] != '=' && !isSpace(attrs[i])) ++i;
      const std::string_view name = attrs.substr(name_begin, i - name_begin);
      while (i < attrs.size() && isSpace(attrs[i])) ++i;
      if (i >= attrs.size() || attrs[i] != '=') {
        if (name.empty()) return std::nullopt;
        continue;
      }
      ++i;
      while (i < attrs.size() && isSpace(attrs[i])) ++i;
      if (i >= attrs.size() || (attrs[i] != '"' && attrs[i] != '\'')) continue;
      const char quote = attrs[i++];
      const std::size_t end = attrs.find(quote, i);
      const std::string_view value =
          attrs.substr(i, end == std::string_view::npos ? std::string_view::npos : end - i);
      if (name == key) return value;
      i = end == std::string_view::npos ? attrs.size() : end + 1;
    }
    return std::nullopt;
  }

  // A size attribute: absent is nothing; otherwise a whole number (spaces around allowed).
  std::optional<Count> number(std::string_view attrs, std::string_view key,
                              std::string_view element, int line) {
    const auto text = attribute(attrs, key);
    if (!text) return std::nullopt;
    std::string_view s = *text;
    while (!s.empty() && isSpace(s.front())) s.remove_prefix(1);
    while (!s.empty() && isSpace(s.back())) s.remove_suffix(1);
    if (s.empty() || !std::all_of(s.begin(), s.end(), isDigit))
      fail(line, tagOf(element) + " " + std::string(key) + "=" + quoted(*text) +
                     ": expected a whole number");
    Count value = 0;
    for (char c : s) value = plus(times(value, 10), static_cast<Count>(c - '0'));
    return value;
  }

  // The whitespace-separated words of an element's text, up to the next markup.
  struct Words {
    Count count = 0;
    Count sum = 0;                // of the numbers, for <vcount>
    std::string_view first_bad;   // a word that is not a whole number (when asked)
    bool markup_follows = false;  // the text is followed by markup other than the end tag
  };
  Words words(std::size_t begin, std::string_view element, bool signs = true) const {
    Words w;
    std::size_t end = text_.find('<', begin);
    if (end == std::string_view::npos) end = text_.size();
    const std::string_view body = text_.substr(begin, end - begin);
    std::string closing("</");
    closing.append(element);
    w.markup_follows = end < text_.size() && !text_.substr(end).starts_with(closing);
    std::size_t i = 0;
    while (i < body.size()) {
      while (i < body.size() && isSpace(body[i])) ++i;
      if (i == body.size()) break;
      const std::size_t word_begin = i;
      while (i < body.size() && !isSpace(body[i])) ++i;
      std::string_view word = body.substr(word_begin, i - word_begin);
      ++w.count;
      std::string_view digits = word;
      if (signs && !digits.empty() && (digits.front() == '-' || digits.front() == '+'))
        digits.remove_prefix(1);
      if (digits.empty() || !std::all_of(digits.begin(), digits.end(), isDigit)) {
        if (w.first_bad.empty()) w.first_bad = word;
        continue;
      }
      Count value = 0;
      for (char c : digits) value = plus(times(value, 10), static_cast<Count>(c - '0'));
      if (word.front() != '-') w.sum = plus(w.sum, value);
    }
    return w;
  }

  // A list that assimp reads number by number: whole numbers only, no markup inside.
  // (assimp reads <p> numbers with a sign, <vcount> numbers without).
  Words numberList(std::size_t begin, std::string_view element, int line) const {
    const Words w = words(begin, element, element == "p");
    if (!w.first_bad.empty())
      fail(line, tagOf(element) + " holds " + quoted(w.first_bad) +
                     ": expected whole numbers separated by spaces");
    if (w.markup_follows) fail(line, tagOf(element) + " holds markup: expected whole numbers only");
    return w;
  }

  static bool isPrimitives(std::string_view name) {
    return name == "triangles" || name == "lines" || name == "polylist" || name == "polygons" ||
           name == "trifans" || name == "tristrips" || name == "linestrips";
  }

  // Reads the tag at pos (text_[pos] == '<'); returns the position after it.
  std::size_t tag(std::size_t pos) {
    const int line = lineAt(pos);
    std::size_t i = pos + 1;
    const bool closing = i < text_.size() && text_[i] == '/';
    if (closing) ++i;
    const std::size_t name_begin = i;
    while (i < text_.size() && !isSpace(text_[i]) && text_[i] != '>' && text_[i] != '/') ++i;
    const std::string_view name = text_.substr(name_begin, i - name_begin);
    // The end of the tag: the first '>' outside quotes.
    const std::size_t attrs_begin = i;
    char quote = 0;
    while (i < text_.size() && (quote != 0 || text_[i] != '>')) {
      if (quote == 0 && (text_[i] == '"' || text_[i] == '\''))
        quote = text_[i];
      else if (quote != 0 && text_[i] == quote)
        quote = 0;
      ++i;
    }
    if (i >= text_.size()) return text_.size();  // an unfinished tag: the XML parser refuses it
    const std::string_view attrs = text_.substr(attrs_begin, i - attrs_begin);
    const bool empty = !attrs.empty() && attrs.back() == '/';
    const std::size_t after = i + 1;

    if (closing) {
      if (name == "accessor") reading_accessor_ = false;
      if (name == "source") source_ = {};
      if (name == "mesh" && meshes_ > 0) --meshes_;
      if (!open_.empty() && open_.back().name == name) {
        finish(open_.back());
        open_.pop_back();
      }
      return after;
    }

    // Any element: its declared sizes must fit in the file.
    const Count bytes = text_.size();
    const auto count = number(attrs, "count", name, line);
    const auto stride = number(attrs, "stride", name, line);
    const auto offset = number(attrs, "offset", name, line);
    const std::string element = tagOf(name);
    if (count && times(*count, std::max<Count>(stride.value_or(1), 1)) > bytes)
      fail(line, element + " declares count=" + std::to_string(*count) +
                     (stride ? " stride=" + std::to_string(*stride) : std::string()) +
                     ": more values than the file's " + std::to_string(bytes) +
                     " bytes could hold");
    if (stride && *stride > bytes)
      fail(line, element + " declares stride=" + std::to_string(*stride) +
                     ": more than the file's " + std::to_string(bytes) + " bytes could hold");
    if (offset && *offset > bytes)
      fail(line, element + " declares offset=" + std::to_string(*offset) +
                     ": more than the file's " + std::to_string(bytes) + " bytes could hold");

    if (name.ends_with("_array")) {
      const Count declared = count.value_or(0);  // what assimp reads
      if (const auto id = attribute(attrs, "id")) {
        const auto [it, added] = arrays_.try_emplace(std::string(*id), Array{declared, true});
        it->second.count = std::min(it->second.count, declared);
        it->second.numbers = it->second.numbers && name == "float_array";
      }
      if (!empty) {
        const Words w = words(after, name);
        if (declared > w.count)
          fail(line, element + " declares count=" + std::to_string(declared) + ", its text holds " +
                         std::to_string(w.count) + " values");
      }
    } else if (name == "accessor") {
      std::string_view source = attribute(attrs, "source").value_or("");
      if (source.starts_with('#')) source.remove_prefix(1);
      accessors_.push_back({line, std::string(source), count.value_or(0), stride.value_or(1),
                            offset.value_or(0), 0, std::string(source_)});
      reading_accessor_ = !empty;
    } else if (name == "source" && !empty) {
      source_ = attribute(attrs, "id").value_or("");
    } else if (name == "mesh" && !empty) {
      ++meshes_;
    } else if (name == "input" && meshes_ > 0) {
      std::string_view source = attribute(attrs, "source").value_or("");
      if (source.starts_with('#')) source.remove_prefix(1);
      mesh_inputs_.emplace(source);
    } else if (name == "param" && reading_accessor_) {
      // The values of one element: 16 for a matrix, else 1.
      accessors_.back().width += attribute(attrs, "type").value_or("") == "float4x4" ? 16 : 1;
    } else if (isPrimitives(name) && !empty) {
      Primitives e;
      e.name = name;
      e.line = line;
      e.count = count.value_or(0);
      open_.push_back(std::move(e));
    }
    if (!open_.empty() && name == "input") {
      open_.back().inputs = std::max(open_.back().inputs, plus(offset.value_or(0), 1));
    } else if (name == "vcount" && !empty) {
      const Words w = numberList(after, name, line);
      if (w.sum > bytes)
        fail(line, "<vcount> numbers add up to " + std::to_string(w.sum) +
                       ": more than the file's " + std::to_string(bytes) + " bytes could hold");
      if (!open_.empty()) {
        open_.back().has_vcount = true;
        open_.back().vcounts = plus(open_.back().vcounts, w.count);
        open_.back().vertices = plus(open_.back().vertices, w.sum);
      }
    } else if (!open_.empty() && name == "p" && !empty) {
      open_.back().lists.push_back({line, numberList(after, name, line).count});
    }
    return after;
  }

  // An accessor reads count elements of `width` values, `stride` apart, from `offset` on in
  // its source array, which assimp 5.2.5 does not check: they must lie in what the array
  // declares, and its elements must not overlap.
  void check(const Accessor& a) const {
    const auto array = arrays_.find(a.source);
    if (array == arrays_.end() || a.count == 0) return;  // an unknown source: assimp refuses it
    std::string what = "<accessor source=\"#" + a.source + "\" count=\"";
    what.append(std::to_string(a.count))
        .append("\" stride=\"")
        .append(std::to_string(a.stride))
        .append("\" offset=\"")
        .append(std::to_string(a.offset))
        .append("\">");
    if (a.stride < std::max<Count>(a.width, 1))
      fail(a.line, what + ": a stride of at least its " + std::to_string(a.width) +
                       " values per element expected");
    const Count needed = plus(a.offset, times(a.count, a.stride));
    if (needed > array->second.count)
      fail(a.line, what + " reads " + std::to_string(needed) + " values, its array declares " +
                       std::to_string(array->second.count));
    // A mesh reads numbers through it: a Name_array or IDREF_array has none for assimp.
    if (!array->second.numbers && mesh_inputs_.contains(a.holder))
      fail(a.line, what +
                       ", read by a mesh's <input>: a <float_array> expected, found an "
                       "array of names");
  }

  // The checks of a primitive list once all its inputs and lists are known.
  void finish(const Primitives& e) const {
    std::string element("<");
    element.append(e.name).append(" count=\"").append(std::to_string(e.count)).append("\">");
    const std::string per_vertex = std::to_string(e.inputs) + " per vertex";
    if (e.name == "polylist" && e.has_vcount && e.count > e.vcounts)
      fail(e.line, element + " needs " + std::to_string(e.count) +
                       " numbers in its <vcount>, found " + std::to_string(e.vcounts));
    if (e.count == 0) return;  // assimp reads no index then
    if (e.name == "triangles" || e.name == "lines" || e.name == "polylist") {
      const Count corners = e.name == "triangles" ? times(3, e.count)
                            : e.name == "lines"   ? times(2, e.count)
                                                  : e.vertices;
      const Count needed = times(corners, e.inputs);
      for (const auto& list : e.lists)
        if (list.numbers < needed)
          fail(list.line, element + " needs " + std::to_string(needed) + " indices in its <p> (" +
                              std::to_string(corners) + " corners, " + per_vertex + "), found " +
                              std::to_string(list.numbers));
      return;
    }
    Count found = 0;
    for (const auto& list : e.lists) found = plus(found, list.numbers);
    const Count needed = times(e.count, e.inputs);
    if (!e.lists.empty() && found < needed)
      fail(e.line, element + " needs at least " + std::to_string(needed) + " indices in its <p> (" +
                       per_vertex + "), found " + std::to_string(found));
  }

  std::string_view text_;
  const std::string& name_;
  std::vector<Primitives> open_;
  std::map<std::string, Array, std::less<>> arrays_;  // by id
  std::set<std::string, std::less<>> mesh_inputs_;    // sources an <input> of a <mesh> names
  std::string_view source_;                           // the id of the <source> being read
  int meshes_ = 0;                                    // <mesh> elements open
  std::vector<Accessor> accessors_;
  bool reading_accessor_ = false;
  int line_ = 1;
  std::size_t counted_ = 0;
};

}  // namespace

void checkColladaSizes(std::string_view text, const std::string& name) {
  Checker(text, name).run();
}

}  // namespace tribo::io
