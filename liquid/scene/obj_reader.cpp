#include "liquid/scene/obj_reader.h"

#include "liquid/scene/mesh_parse.h"

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace liquid {
namespace {

using mesh_parse::quote;
using std::to_string;

class ObjReader {
 public:
  ObjReader(std::string_view bytes, const std::string& name) : lines_(bytes), name_(name) {}

  TriangleMesh read() {
    std::string_view line;
    while (lines_.next(line)) {
      line = line.substr(0, line.find('#'));
      if (!mesh_parse::split(line, tokens_))
        refuse("more than " + std::to_string(mesh_parse::k_max_line_fields) + " fields on one line");
      if (tokens_.empty()) continue;
      const std::string_view keyword = tokens_[0];
      if (keyword == "v") vertex();
      else if (keyword == "f") face();
      else if (keyword == "vt") texcoords_ += numbers(1, 3);
      else if (keyword == "vn") normals_ += numbers(3, 3);
      else if (keyword == "vp") numbers(1, 3);
      // Lines and points have no volume; group, object, smoothing and material names do not
      // change the shape.
      else if (keyword == "l" || keyword == "p" || keyword == "o" || keyword == "g" || keyword == "s" ||
               keyword == "usemtl" || keyword == "mtllib") continue;
      else refuse("unsupported OBJ statement " + quote(keyword) + " (only polygons are read)");
    }
    return std::move(mesh_);
  }

 private:
  [[noreturn]] void refuse(const std::string& what) const {
    mesh_parse::fail(name_, "line " + to_string(lines_.line_number()) + ": " + what);
  }

  // Checks that the statement holds `least` to `most` finite numbers; returns 1 (one more of its kind).
  size_t numbers(size_t least, size_t most) {
    const size_t count = tokens_.size() - 1;
    if (count < least || count > most)
      refuse(quote(tokens_[0]) + " takes " + to_string(least) + (least == most ? "" : " to " + to_string(most)) +
             " numbers, got " + to_string(count));
    for (size_t i = 1; i < tokens_.size(); ++i)
      if (!mesh_parse::to_number(tokens_[i])) refuse(quote(tokens_[i]) + " is not a finite decimal number");
    return 1;
  }

  void vertex() {
    // x y z, x y z w, or x y z r g b (the colour extension some exporters write).
    if (tokens_.size() != 7) numbers(3, 4);
    else numbers(6, 6);
    if (mesh_.vertices.size() >= k_max_mesh_vertices)
      refuse("more than the " + to_string(k_max_mesh_vertices) + " vertices a mesh may have");
    double xyz[3];
    for (int a = 0; a < 3; ++a) {
      xyz[a] = *mesh_parse::to_number(tokens_[1 + a]);
      if (const std::string problem = mesh_parse::coordinate_problem(xyz[a]); !problem.empty())
        refuse("vertex " + to_string(mesh_.vertices.size() + 1) + ": " + problem);
    }
    mesh_.vertices.emplace_back(float(xyz[0]), float(xyz[1]), float(xyz[2]));
  }

  // An index into `count` items so far: 1-based, or negative counting back from the latest.
  std::uint32_t resolve(std::string_view token, size_t count, const char* what) {
    const std::optional<std::int64_t> i = mesh_parse::to_integer(token);
    if (!i || *i == 0) refuse(quote(token) + " is not a " + what + " index (a nonzero integer)");
    const std::int64_t zero_based = *i > 0 ? *i - 1 : std::int64_t(count) + *i;
    if (zero_based < 0 || zero_based >= std::int64_t(count))
      refuse(std::string(what) + " index " + to_string(*i) + " is out of range (the file has " + to_string(count) + " so far)");
    return std::uint32_t(zero_based);
  }

  // One corner: v, v/vt, v/vt/vn or v//vn. The texture and normal indices are checked, not kept.
  std::uint32_t corner(std::string_view token) {
    std::string_view parts[3];
    size_t count = 0;
    for (size_t start = 0;;) {
      const size_t slash = token.find('/', start);
      if (count == 3) refuse(quote(token) + " has more than three parts");
      parts[count++] = token.substr(start, slash == std::string_view::npos ? std::string_view::npos : slash - start);
      if (slash == std::string_view::npos) break;
      start = slash + 1;
    }
    const std::uint32_t v = resolve(parts[0], mesh_.vertices.size(), "vertex");
    if (count >= 2 && !(parts[1].empty() && count == 3)) resolve(parts[1], texcoords_, "texture coordinate");
    if (count == 3) resolve(parts[2], normals_, "normal");
    return v;
  }

  void face() {
    const size_t corners = tokens_.size() - 1;
    if (corners < 3) refuse("a face has " + to_string(corners) + " corners (at least 3)");
    if (mesh_.indices.size() / 3 + corners - 2 > k_max_mesh_triangles)
      refuse("more than the " + to_string(k_max_mesh_triangles) + " triangles a mesh may have");
    const std::uint32_t first = corner(tokens_[1]);
    std::uint32_t previous = corner(tokens_[2]);
    for (size_t k = 3; k <= corners; ++k) {
      const std::uint32_t next = corner(tokens_[k]);
      mesh_.indices.insert(mesh_.indices.end(), {first, previous, next});
      previous = next;
    }
  }

  mesh_parse::LineReader lines_;
  const std::string& name_;
  std::vector<std::string_view> tokens_;
  TriangleMesh mesh_;
  size_t texcoords_ = 0;
  size_t normals_ = 0;
};

}  // namespace

TriangleMesh read_obj(std::string_view bytes, const std::string& name) { return ObjReader(bytes, name).read(); }

}  // namespace liquid
