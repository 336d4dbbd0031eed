#include "liquid/scene/ply_reader.h"

#include "liquid/scene/mesh_parse.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cstring>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace liquid {
namespace {

using mesh_parse::fail;
using mesh_parse::quote;
using std::to_string;

// Real headers are a few hundred bytes; past this the file is not a PLY header at all.
constexpr size_t k_max_header_bytes = size_t(64) << 10;

enum class Type : std::uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

constexpr std::pair<std::string_view, Type> k_type_names[] = {
    {"char", Type::Int8},     {"int8", Type::Int8},       {"uchar", Type::UInt8},    {"uint8", Type::UInt8},
    {"short", Type::Int16},   {"int16", Type::Int16},     {"ushort", Type::UInt16},  {"uint16", Type::UInt16},
    {"int", Type::Int32},     {"int32", Type::Int32},     {"uint", Type::UInt32},    {"uint32", Type::UInt32},
    {"float", Type::Float32}, {"float32", Type::Float32}, {"double", Type::Float64}, {"float64", Type::Float64}};

std::optional<Type> type_named(std::string_view name) {
  for (const auto& [n, t] : k_type_names)
    if (n == name) return t;
  return std::nullopt;
}

std::string name_of(Type type) {
  for (const auto& [n, t] : k_type_names)
    if (t == type) return std::string(n);
  return "?";
}

size_t size_of(Type t) {
  switch (t) {
    case Type::Int8: case Type::UInt8: return 1;
    case Type::Int16: case Type::UInt16: return 2;
    case Type::Int32: case Type::UInt32: case Type::Float32: return 4;
    case Type::Float64: return 8;
  }
  return 1;
}

bool is_integer(Type t) { return t != Type::Float32 && t != Type::Float64; }

// Whether an ascii integer fits the type the header gave it.
bool fits(Type t, std::int64_t v) {
  const auto in = [v](auto lo, auto hi) { return v >= std::int64_t(lo) && v <= std::int64_t(hi); };
  switch (t) {
    case Type::Int8: return in(INT8_MIN, INT8_MAX);
    case Type::UInt8: return in(0, UINT8_MAX);
    case Type::Int16: return in(INT16_MIN, INT16_MAX);
    case Type::UInt16: return in(0, UINT16_MAX);
    case Type::Int32: return in(INT32_MIN, INT32_MAX);
    case Type::UInt32: return in(0, UINT32_MAX);
    default: return true;
  }
}

struct Property {
  std::string name;
  Type type = Type::Float32;  // a list's items
  bool list = false;
  Type count_type = Type::UInt8;
  int axis = -1;         // 0, 1, 2: the vertex's x, y, z
  bool corners = false;  // the face's vertex_indices
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
  size_t line = 0;  // where the header declares it
};

enum class Format { Ascii, BinaryLittle, BinaryBig };

struct Header {
  Format format = Format::Ascii;
  std::vector<Element> elements;
  size_t data_offset = 0;  // the first byte after end_header's line
  size_t lines = 0;        // the header's lines (the data starts on the next)
  std::uint64_t vertices = 0;
};

template <class Refuse>
std::uint64_t element_count(std::string_view token, const Refuse& refuse) {
  if (const auto value = mesh_parse::to_integer(token); value && *value < 0)
    refuse("element count " + quote(token) + " is negative");
  std::uint64_t value = 0;
  const char* end = token.data() + token.size();
  const auto [stop, error] = std::from_chars(token.data(), end, value, 10);
  if (error == std::errc::result_out_of_range) refuse("element count " + quote(token) + " is too large");
  if (error != std::errc() || stop != end) refuse("element count " + quote(token) + " is not a whole number");
  return value;
}

// The header's lines up to end_header, each checked; nothing is read past k_max_header_bytes.
Header read_header(std::string_view bytes, const std::string& name) {
  Header h;
  mesh_parse::LineReader lines(bytes.substr(0, std::min(bytes.size(), k_max_header_bytes)));
  std::string_view line;
  std::vector<std::string_view> t;
  const auto refuse = [&](const std::string& what) {
    fail(name, "header line " + to_string(lines.line_number()) + ": " + what);
  };
  const auto type = [&](std::string_view word) {
    const std::optional<Type> found = type_named(word);
    if (!found) refuse("unknown type " + quote(word));
    return *found;
  };
  if (!lines.next(line) || line != "ply") fail(name, "not a PLY file (its first line is not `ply`)");
  bool have_format = false;
  for (;;) {
    // A last line without its newline is cut too: "property fl" is not a property to read.
    if (!lines.next(line) || !lines.ended_by_newline())
      fail(name, bytes.size() > k_max_header_bytes ? "no end_header line in the first 64 KiB: not a PLY header"
                                                   : "the file ends inside the PLY header (no end_header line)");
    (void)mesh_parse::split(line, t);  // a header line is within the header's 64 KiB
    if (t.empty() || t[0] == "comment" || t[0] == "obj_info") continue;
    if (t[0] == "end_header") {
      if (t.size() != 1) refuse("nothing may follow end_header on its line");
      break;
    }
    if (t[0] == "format") {
      if (have_format || !h.elements.empty()) refuse("format must be given once, before the elements");
      if (t.size() != 3 || t[2] != "1.0") refuse("expected `format ascii|binary_little_endian|binary_big_endian 1.0`");
      if (t[1] == "ascii") h.format = Format::Ascii;
      else if (t[1] == "binary_little_endian") h.format = Format::BinaryLittle;
      else if (t[1] == "binary_big_endian") h.format = Format::BinaryBig;
      else refuse("unknown format " + quote(t[1]));
      have_format = true;
    } else if (t[0] == "element") {
      if (t.size() != 3) refuse("expected `element <name> <count>`");
      for (const Element& e : h.elements)
        if (e.name == t[1]) refuse("a second element " + quote(t[1]));
      h.elements.push_back({std::string(t[1]), element_count(t[2], refuse), {}, lines.line_number()});
    } else if (t[0] == "property") {
      if (h.elements.empty()) refuse("a property before any element");
      Property p;
      p.list = t.size() == 5 && t[1] == "list";
      if (!p.list && t.size() != 3)
        refuse("expected `property <type> <name>` or `property list <count type> <type> <name>`");
      if (p.list) {
        p.count_type = type(t[2]);
        if (!is_integer(p.count_type)) refuse("a list's count must have an integer type, not " + quote(t[2]));
      }
      p.type = type(t[p.list ? 3 : 1]);
      p.name = std::string(t[p.list ? 4 : 2]);
      std::vector<Property>& properties = h.elements.back().properties;
      for (const Property& q : properties)
        if (q.name == p.name) refuse("a second property " + quote(p.name));
      properties.push_back(p);
    } else {
      refuse("unknown header keyword " + quote(t[0]) + " (is end_header missing?)");
    }
  }
  if (!have_format) fail(name, "the PLY header has no format line");
  h.data_offset = lines.offset();
  h.lines = lines.line_number();
  return h;
}

// Each record takes at least its fixed-size values and its lists' counts (binary), or a value and a
// separator per property (ascii): a count that cannot fit the bytes after the header is refused
// here, before anything is allocated for it.
void check_counts(const Header& h, std::uint64_t available, const std::string& name) {
  if (h.format == Format::Ascii) ++available;  // the last value needs no separator
  std::uint64_t needed = 0;
  for (const Element& e : h.elements) {
    std::uint64_t least = 0;
    for (const Property& p : e.properties) least += h.format == Format::Ascii ? 2 : size_of(p.list ? p.count_type : p.type);
    if (least == 0) continue;
    if (e.count > (available - needed) / least)
      fail(name, "header line " + to_string(e.line) + ": element " + e.name + ": " + to_string(e.count) +
                     " records of at least " + to_string(least) + " bytes cannot fit in the " +
                     to_string(available - needed) + " bytes left (truncated, or a wrong count)");
    needed += e.count * least;
  }
}

// Marks the vertex's x, y, z and the face's corner list, and holds their counts to the limits.
void assign_roles(Header& h, const std::string& name) {
  bool have_vertex = false;
  for (Element& e : h.elements) {
    const auto refuse = [&](const std::string& what) {
      fail(name, "header line " + to_string(e.line) + ": element " + e.name + ": " + what);
    };
    const auto find = [&](std::string_view property) {
      const auto it = std::find_if(e.properties.begin(), e.properties.end(), [&](const Property& p) { return p.name == property; });
      return it == e.properties.end() ? nullptr : &*it;
    };
    if (e.name == "vertex") {
      have_vertex = true;
      for (int axis = 0; axis < 3; ++axis) {
        const char* axis_name[] = {"x", "y", "z"};
        Property* p = find(axis_name[axis]);
        if (!p || p->list) refuse(std::string("needs a (non-list) property ") + axis_name[axis]);
        p->axis = axis;
      }
      if (e.count > k_max_mesh_vertices)
        refuse(to_string(e.count) + " vertices, more than the " + to_string(k_max_mesh_vertices) + " a mesh may have");
      h.vertices = e.count;
    } else if (e.name == "face") {
      Property* p = find("vertex_indices");
      if (!p) p = find("vertex_index");
      if (!p || !p->list || !is_integer(p->type))
        refuse("needs a property `list <count type> <integer type> vertex_indices`");
      p->corners = true;
      if (e.count > k_max_mesh_triangles)
        refuse(to_string(e.count) + " faces, more than the " + to_string(k_max_mesh_triangles) + " triangles a mesh may have");
    }
  }
  if (!have_vertex) fail(name, "the PLY header declares no element vertex");
}

template <class T>
T load(const char* p, bool swap) {
  char b[sizeof(T)];
  std::memcpy(b, p, sizeof(T));
  if (swap) std::reverse(b, b + sizeof(T));
  T value;
  std::memcpy(&value, b, sizeof(T));
  return value;
}

// Binary records: values in the file's byte order, every read checked against the end of the file.
class BinaryIn {
 public:
  BinaryIn(std::string_view bytes, size_t at, bool big_endian, const std::string& name)
      : bytes_(bytes), at_(at), swap_(big_endian != (std::endian::native == std::endian::big)), name_(name) {}

  void begin(const Element& e, std::uint64_t index) {
    element_ = &e;
    index_ = index;
    record_ = at_;
  }
  void end() {}

  double number(Type t) {
    const char* p = take(size_of(t));
    switch (t) {
      case Type::Int8: return load<std::int8_t>(p, swap_);
      case Type::UInt8: return load<std::uint8_t>(p, swap_);
      case Type::Int16: return load<std::int16_t>(p, swap_);
      case Type::UInt16: return load<std::uint16_t>(p, swap_);
      case Type::Int32: return load<std::int32_t>(p, swap_);
      case Type::UInt32: return load<std::uint32_t>(p, swap_);
      case Type::Float32: return load<float>(p, swap_);
      case Type::Float64: return load<double>(p, swap_);
    }
    return 0.0;
  }
  // Exact: every integer type is at most 32 bits.
  std::int64_t integer(Type t) { return std::int64_t(number(t)); }

  // Room for `n` values of type `t`, checked before a loop over them.
  void expect(std::uint64_t n, Type t) {
    if (n > (bytes_.size() - at_) / size_of(t)) truncated();
  }
  void skip(Type t, std::uint64_t n = 1) {
    expect(n, t);
    at_ += n * size_of(t);
  }
  // Only whitespace may follow the last element (a count too small would leave records there).
  void finish() {
    const size_t extra = bytes_.find_first_not_of(" \t\r\n", at_);
    if (extra != std::string_view::npos)
      fail(name_, "byte " + to_string(extra) + ": " + to_string(bytes_.size() - at_) + " bytes after the last element");
  }
  [[noreturn]] void refuse(const std::string& what) const { fail(name_, "byte " + to_string(record_) + ": " + what); }

 private:
  const char* take(size_t n) {
    if (n > bytes_.size() - at_) truncated();
    const char* p = bytes_.data() + at_;
    at_ += n;
    return p;
  }
  [[noreturn]] void truncated() const {
    fail(name_, "byte " + to_string(at_) + ": the file ends inside " + element_->name + " " + to_string(index_) + " of " +
                    to_string(element_->count) + " (truncated)");
  }

  std::string_view bytes_;
  size_t at_;
  bool swap_;
  const std::string& name_;
  const Element* element_ = nullptr;
  std::uint64_t index_ = 0;
  size_t record_ = 0;
};

// Ascii records: one a line, its values separated by spaces or tabs; blank lines are skipped.
class AsciiIn {
 public:
  AsciiIn(std::string_view data, size_t header_lines, const std::string& name)
      : lines_(data), header_lines_(header_lines), name_(name) {}

  void begin(const Element& e, std::uint64_t index) {
    element_ = &e;
    index_ = index;
    std::string_view line;
    do {
      if (!lines_.next(line))
        fail(name_, "the file ends before " + e.name + " " + to_string(index) + " of " + to_string(e.count) + " (truncated)");
      if (!mesh_parse::split(line, tokens_))
        refuse("more than " + std::to_string(mesh_parse::k_max_line_fields) + " values on one line");
    } while (tokens_.empty());
    next_ = 0;
  }
  void end() {
    if (next_ != tokens_.size())
      refuse(element_->name + " " + to_string(index_) + " has more values than its properties (" + quote(tokens_[next_]) + ")");
  }

  double number(Type t) {
    if (is_integer(t)) return double(integer(t));
    const std::string_view token = take();
    const std::optional<double> value = mesh_parse::to_number(token);
    if (!value) refuse(quote(token) + " is not a finite decimal number");
    return *value;
  }
  std::int64_t integer(Type t) {
    const std::string_view token = take();
    const std::optional<std::int64_t> value = mesh_parse::to_integer(token);
    if (!value || !fits(t, *value)) refuse(quote(token) + " is not an integer of type " + name_of(t));
    return *value;
  }

  void expect(std::uint64_t n, Type) {
    if (n > tokens_.size() - next_)
      refuse(element_->name + " " + to_string(index_) + " lists " + to_string(n) + " values, its line has " +
             to_string(tokens_.size() - next_));
  }
  void skip(Type t, std::uint64_t n = 1) {
    expect(n, t);
    for (std::uint64_t i = 0; i < n; ++i) number(t);
  }
  void finish() {
    std::string_view line;
    std::vector<std::string_view> tokens;
    while (lines_.next(line)) {
      if (!mesh_parse::split(line, tokens) || !tokens.empty()) refuse("data after the last element (" + quote(tokens[0]) + ")");
    }
  }
  [[noreturn]] void refuse(const std::string& what) const {
    fail(name_, "line " + to_string(header_lines_ + lines_.line_number()) + ": " + what);
  }

 private:
  std::string_view take() {
    if (next_ >= tokens_.size())
      refuse(element_->name + " " + to_string(index_) + " has fewer values than its properties");
    return tokens_[next_++];
  }

  mesh_parse::LineReader lines_;
  size_t header_lines_;
  const std::string& name_;
  std::vector<std::string_view> tokens_;
  size_t next_ = 0;
  const Element* element_ = nullptr;
  std::uint64_t index_ = 0;
};

// One face's corners, fanned into triangles (0, k - 1, k).
template <class In>
void read_face(In& in, const Property& p, std::int64_t corners, std::uint64_t face, std::uint64_t vertices,
               std::vector<std::uint32_t>& indices) {
  if (corners < 3) in.refuse("face " + to_string(face) + " has " + to_string(corners) + " corners (at least 3)");
  in.expect(std::uint64_t(corners), p.type);
  if (indices.size() / 3 + std::uint64_t(corners - 2) > k_max_mesh_triangles)
    in.refuse("more than the " + to_string(k_max_mesh_triangles) + " triangles a mesh may have");
  std::uint32_t first = 0, previous = 0;
  for (std::int64_t k = 0; k < corners; ++k) {
    const std::int64_t v = in.integer(p.type);
    if (v < 0 || std::uint64_t(v) >= vertices)
      in.refuse("face " + to_string(face) + ": vertex index " + to_string(v) + " is out of range (the file has " +
                to_string(vertices) + " vertices)");
    const auto index = std::uint32_t(v);
    if (k == 0) first = index;
    if (k >= 2) indices.insert(indices.end(), {first, previous, index});
    previous = index;
  }
}

template <class In>
TriangleMesh read_records(const Header& h, In& in) {
  TriangleMesh mesh;
  for (const Element& e : h.elements) {
    if (e.properties.empty()) continue;  // nothing to read, whatever the count
    const bool vertex = e.name == "vertex";
    // The counts fit the file (check_counts) and the limits (assign_roles).
    if (vertex) mesh.vertices.reserve(e.count);
    if (e.name == "face") mesh.indices.reserve(3 * e.count);
    for (std::uint64_t i = 0; i < e.count; ++i) {
      in.begin(e, i);
      double xyz[3] = {0.0, 0.0, 0.0};
      for (const Property& p : e.properties) {
        if (!p.list) {
          if (p.axis >= 0) xyz[p.axis] = in.number(p.type);
          else in.skip(p.type);
          continue;
        }
        const std::int64_t n = in.integer(p.count_type);
        if (p.corners) {
          read_face(in, p, n, i, h.vertices, mesh.indices);
        } else {
          if (n < 0) in.refuse(e.name + " " + to_string(i) + ": list " + p.name + " has " + to_string(n) + " items");
          in.skip(p.type, std::uint64_t(n));
        }
      }
      in.end();
      if (!vertex) continue;
      for (double c : xyz)
        if (const std::string problem = mesh_parse::coordinate_problem(c); !problem.empty())
          in.refuse("vertex " + to_string(i) + ": " + problem);
      mesh.vertices.emplace_back(float(xyz[0]), float(xyz[1]), float(xyz[2]));
    }
  }
  in.finish();
  return mesh;
}

}  // namespace

TriangleMesh read_ply(std::string_view bytes, const std::string& name) {
  Header h = read_header(bytes, name);
  check_counts(h, bytes.size() - h.data_offset, name);
  assign_roles(h, name);
  if (h.format == Format::Ascii) {
    AsciiIn in(bytes.substr(h.data_offset), h.lines, name);
    return read_records(h, in);
  }
  BinaryIn in(bytes, h.data_offset, h.format == Format::BinaryBig, name);
  return read_records(h, in);
}

}  // namespace liquid
