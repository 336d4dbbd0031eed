// Mesh obstacle files as users send them: valid files that must load (binary PLY whose data begins
// with a newline byte, big-endian PLY with properties and elements to skip, OBJ quads with negative
// indices) and broken or hostile ones that must be refused in one line naming the file and the
// fault, never crash, hang or allocate what the file cannot hold.
#include "liquid/scene.h"
#include "liquid/scene/mesh_file.h"
#include "tests/support/meshes.h"

#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

namespace {

namespace fs = std::filesystem;
using liquid::TriangleMesh;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("rasterliquids_mesh_files_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

fs::path write(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

template <class T>
void put(std::string& out, T value, bool big_endian = false) {
  char b[sizeof(T)];
  std::memcpy(b, &value, sizeof(T));
  if (big_endian) std::reverse(b, b + sizeof(T));
  out.append(b, sizeof(T));
}

// The mesh as a binary little-endian PLY: float x y z, faces `list <count_type> int vertex_indices`
// (count_type uchar or int).
std::string binary_ply(const TriangleMesh& mesh, const std::string& count_type = "uchar") {
  std::string out = "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(mesh.vertices.size()) +
                    "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
                    std::to_string(mesh.indices.size() / 3) + "\nproperty list " + count_type +
                    " int vertex_indices\nend_header\n";
  for (const glm::vec3& v : mesh.vertices)
    for (int a = 0; a < 3; ++a) put<float>(out, v[a]);
  for (size_t t = 0; t < mesh.indices.size(); t += 3) {
    if (count_type == "int") put<std::int32_t>(out, 3);
    else put<std::uint8_t>(out, 3);
    for (int k = 0; k < 3; ++k) put<std::int32_t>(out, std::int32_t(mesh.indices[t + k]));
  }
  return out;
}

// Where the first face's corner count lies in binary_ply()'s bytes.
size_t first_face_offset(const std::string& ply, const TriangleMesh& mesh) {
  return ply.find("end_header\n") + 11 + 12 * mesh.vertices.size();
}

std::string ascii_ply(const TriangleMesh& mesh) {
  std::string out = "ply\nformat ascii 1.0\nelement vertex " + std::to_string(mesh.vertices.size()) +
                    "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
                    std::to_string(mesh.indices.size() / 3) + "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const glm::vec3& v : mesh.vertices)
    out += std::to_string(v.x) + " " + std::to_string(v.y) + " " + std::to_string(v.z) + "\n";
  for (size_t t = 0; t < mesh.indices.size(); t += 3)
    out += "3 " + std::to_string(mesh.indices[t]) + " " + std::to_string(mesh.indices[t + 1]) + " " +
           std::to_string(mesh.indices[t + 2]) + "\n";
  return out;
}

std::string obj(const TriangleMesh& mesh) {
  std::string out;
  for (const glm::vec3& v : mesh.vertices)
    out += "v " + std::to_string(v.x) + " " + std::to_string(v.y) + " " + std::to_string(v.z) + "\n";
  for (size_t t = 0; t < mesh.indices.size(); t += 3)
    out += "f " + std::to_string(mesh.indices[t] + 1) + " " + std::to_string(mesh.indices[t + 1] + 1) + " " +
           std::to_string(mesh.indices[t + 2] + 1) + "\n";
  return out;
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

// The message load_mesh_file() refuses `path` with, "" when it loads.
std::string refusal(const fs::path& path) {
  try {
    liquid::load_mesh_file(path);
  } catch (const liquid::SceneError& e) {
    return e.what();
  }
  return "";
}

// Refused in one line that begins with the path and contains `reason`.
void check_refused(const fs::path& path, const std::string& reason) {
  const std::string message = refusal(path);
  INFO(path.filename().string() << ": " << message);
  CHECK(message.find(path.string() + ": ") == 0);
  CHECK(message.find('\n') == std::string::npos);
  CHECK(message.find(reason) != std::string::npos);
}

const TriangleMesh k_cube = test::box_mesh(glm::vec3(0.04f));  // 8 cm wide, corner 0 at -0.04

glm::vec3 extent(const TriangleMesh& mesh) {
  glm::vec3 lo(1e9f), hi(-1e9f);
  for (const glm::vec3& v : mesh.vertices) {
    lo = glm::min(lo, v);
    hi = glm::max(hi, v);
  }
  return hi - lo;
}

}  // namespace

TEST_CASE("mesh files: a binary PLY cube whose vertex data begins with the byte 0x0a loads", "[mesh][mesh_file]") {
  const fs::path dir = scratch("newline_byte");
  const std::string ply = binary_ply(k_cube);
  REQUIRE(ply[ply.find("end_header\n") + 11] == '\x0a');  // -0.04f is 0a d7 23 bd
  const TriangleMesh mesh = liquid::load_mesh_file(write(dir / "cube.ply", ply));
  CHECK(mesh.vertices.size() == 8);
  CHECK(mesh.indices.size() == 36);
  CHECK(extent(mesh).x == Approx(0.08f));
}

TEST_CASE("mesh files: a big-endian PLY with properties and elements to skip loads", "[mesh][mesh_file]") {
  const fs::path dir = scratch("big_endian");
  // The tetrahedron: x double, y float, z short, then a colour; faces with texture coordinates; an
  // element of the exporter's own between them.
  std::string ply =
      "ply\nformat binary_big_endian 1.0\ncomment made by hand\nobj_info test\nelement vertex 4\n"
      "property double x\nproperty float y\nproperty short z\nproperty uchar red\n"
      "element material 2\nproperty int id\nproperty list ushort double weights\n"
      "element face 4\nproperty list uchar float texcoord\nproperty list uint int vertex_index\nend_header\n";
  const int corners[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (const auto& c : corners) {
    put<double>(ply, c[0], true);
    put<float>(ply, float(c[1]), true);
    put<std::int16_t>(ply, std::int16_t(c[2]), true);
    put<std::uint8_t>(ply, 200);
  }
  for (int m = 0; m < 2; ++m) {
    put<std::int32_t>(ply, m, true);
    put<std::uint16_t>(ply, 2, true);
    put<double>(ply, 0.5, true);
    put<double>(ply, 0.25, true);
  }
  const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  for (const auto& f : faces) {
    put<std::uint8_t>(ply, 2);
    put<float>(ply, 0.5f, true);
    put<float>(ply, 0.5f, true);
    put<std::uint32_t>(ply, 3, true);
    for (int k : f) put<std::int32_t>(ply, k, true);
  }
  const TriangleMesh mesh = liquid::load_mesh_file(write(dir / "tetra_be.ply", ply));
  REQUIRE(mesh.vertices.size() == 4);
  CHECK(mesh.indices.size() == 12);
  CHECK(extent(mesh) == glm::vec3(1.0f));
  CHECK(mesh.vertices[1] - mesh.vertices[0] == glm::vec3(1, 0, 0));
  CHECK(mesh.vertices[3] - mesh.vertices[0] == glm::vec3(0, 0, 1));
}

TEST_CASE("mesh files: an OBJ of quads with negative indices, texture and normal indices and ignored statements loads",
          "[mesh][mesh_file]") {
  const fs::path dir = scratch("obj_quads");
  std::string text = "# a cube of quads\nmtllib cube.mtl\no cube\ng side\ns off\nusemtl grey\n";
  for (int i = 0; i < 8; ++i)
    text += "v " + std::to_string(i & 1 ? 1 : -1) + " " + std::to_string(i & 2 ? 1 : -1) + " " +
            std::to_string(i & 4 ? 1 : -1) + (i == 0 ? " 1.0" : "") + "\n";
  text += "vt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\n";
  // Corner i is -8 + i counted back from the last vertex; each quad counter-clockwise from outside.
  const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  const char* forms[4] = {"%d", "%d/-1", "%d//-1", "%d/-2/-1"};
  for (int q = 0; q < 6; ++q) {
    text += "f";
    for (int k = 0; k < 4; ++k) {
      char corner[32];
      std::snprintf(corner, sizeof corner, forms[(q + k) % 4], quads[q][k] - 8);
      text += std::string(" ") + corner;
    }
    text += "   # quad\n";
  }
  text += "l -1 -2\np -3\n";
  const TriangleMesh mesh = liquid::load_mesh_file(write(dir / "cube.obj", text));
  CHECK(mesh.vertices.size() == 8);
  CHECK(mesh.indices.size() == 36);
  CHECK(extent(mesh) == glm::vec3(2.0f));
}

TEST_CASE("mesh files: PLY files cut in their vertex or face data are refused as truncated", "[mesh][mesh_file]") {
  const fs::path dir = scratch("truncated");
  const std::string ply = binary_ply(k_cube);
  const size_t faces = first_face_offset(ply, k_cube);
  check_refused(write(dir / "vertices.ply", ply.substr(0, faces - 20)), "truncated");
  check_refused(write(dir / "faces.ply", ply.substr(0, faces + 7 * 13 + 5)), "truncated");
  const std::string ascii = ascii_ply(k_cube);
  check_refused(write(dir / "ascii_faces.ply", ascii.substr(0, ascii.size() - 12)), "truncated");
}

TEST_CASE("mesh files: a PLY header without end_header, or cut inside, is refused without hanging", "[mesh][mesh_file]") {
  const fs::path dir = scratch("header");
  check_refused(write(dir / "no_end.ply", replaced(ascii_ply(k_cube), "end_header\n", "")), "end_header");
  check_refused(write(dir / "no_end_binary.ply", replaced(binary_ply(k_cube), "end_header\n", "")), "end_header");
  const std::string ply = binary_ply(k_cube);
  check_refused(write(dir / "cut.ply", ply.substr(0, ply.find("property float y") + 11)), "ends inside the PLY header");
}

TEST_CASE("mesh files: a PLY face with fewer than three corners, or a count of -1, is refused", "[mesh][mesh_file]") {
  const fs::path dir = scratch("corners");
  std::string ply = binary_ply(k_cube);
  ply[first_face_offset(ply, k_cube) + 13] = 0;  // the second face
  check_refused(write(dir / "zero.ply", ply), "face 1 has 0 corners");
  std::string wide = binary_ply(k_cube, "int");
  wide.replace(first_face_offset(wide, k_cube), 4, "\xff\xff\xff\xff");
  check_refused(write(dir / "minus_one.ply", wide), "face 0 has -1 corners");
  check_refused(write(dir / "two.ply", replaced(ascii_ply(k_cube), "\n3 ", "\n2 ")), "face 0 has 2 corners");
}

TEST_CASE("mesh files: NaN and huge vertex coordinates are refused in OBJ, ascii PLY and binary PLY", "[mesh][mesh_file]") {
  const fs::path dir = scratch("nan");
  const std::string first = std::to_string(k_cube.vertices[0].x);  // "-0.040000"
  check_refused(write(dir / "nan.obj", replaced(obj(k_cube), first, "nan")), "`nan` is not a finite decimal number");
  check_refused(write(dir / "nan.ply", replaced(ascii_ply(k_cube), first, "NaN")), "`NaN` is not a finite decimal number");
  check_refused(write(dir / "inf.obj", replaced(obj(k_cube), first, "-inf")), "`-inf` is not a finite decimal number");
  std::string binary = binary_ply(k_cube);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  binary.replace(first_face_offset(binary, k_cube) - 4, 4, reinterpret_cast<const char*>(&nan), 4);
  check_refused(write(dir / "nan_binary.ply", binary), "vertex 7: a coordinate is not finite");
  check_refused(write(dir / "huge.obj", replaced(obj(k_cube), first, "1e30")), "coordinate 1e+30 is beyond the 1000000");
  check_refused(write(dir / "huge.ply", replaced(ascii_ply(k_cube), first, "-1e30")), "coordinate -1e+30 is beyond");
}

TEST_CASE("mesh files: numbers are parsed whole and in decimal: hex floats, `abc` and trailing characters are refused",
          "[mesh][mesh_file]") {
  const fs::path dir = scratch("numbers");
  const std::string first = std::to_string(k_cube.vertices[0].x);
  check_refused(write(dir / "hex.obj", replaced(obj(k_cube), first, "-0x1.47ae14p-5")), "`-0x1.47ae14p-5` is not a finite decimal number");
  check_refused(write(dir / "hex.ply", replaced(ascii_ply(k_cube), first, "0x1p-4")), "`0x1p-4` is not a finite decimal number");
  check_refused(write(dir / "abc.obj", replaced(obj(k_cube), first, "abc")), "line 1: `abc` is not a finite decimal number");
  check_refused(write(dir / "abc.ply", replaced(ascii_ply(k_cube), first, "abc")), "line 10: `abc` is not a finite decimal number");
  check_refused(write(dir / "trailing.obj", replaced(obj(k_cube), first, first + "x")), "is not a finite decimal number");
  check_refused(write(dir / "index.obj", replaced(obj(k_cube), "f 1 ", "f 1x ")), "`1x` is not a vertex index");
}

TEST_CASE("mesh files: PLY element counts past 32 bits, past 64 bits, or past the file's size are refused by count",
          "[mesh][mesh_file]") {
  const fs::path dir = scratch("counts");
  check_refused(write(dir / "wrap.ply", replaced(ascii_ply(k_cube), "vertex 8\n", "vertex 4294967304\n")), "4294967304");
  check_refused(write(dir / "huge.ply", replaced(ascii_ply(k_cube), "vertex 8\n", "vertex 18446744073709551616\n")),
                "element count `18446744073709551616` is too large");
  check_refused(write(dir / "negative.ply", replaced(ascii_ply(k_cube), "face 12\n", "face -1\n")),
                "element count `-1` is negative");
  check_refused(write(dir / "two_billion.ply", replaced(binary_ply(k_cube), "vertex 8\n", "vertex 2147483648\n")),
                "2147483648 records of at least 12 bytes cannot fit");
}

TEST_CASE("mesh files: a face index past the vertices is refused naming the face", "[mesh][mesh_file]") {
  const fs::path dir = scratch("index");
  check_refused(write(dir / "index.ply", replaced(ascii_ply(k_cube), "\n3 0 ", "\n3 8 ")),
                "face 0: vertex index 8 is out of range (the file has 8 vertices)");
  check_refused(write(dir / "index.obj", replaced(obj(k_cube), "f 1 ", "f -9 ")), "vertex index -9 is out of range");
}

TEST_CASE("mesh files: an OBJ of only vertices or only lines has no triangle faces", "[mesh][mesh_file]") {
  const fs::path dir = scratch("no_faces");
  const std::string vertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
  check_refused(write(dir / "points.obj", vertices), "has no triangle faces (only points or lines)");
  check_refused(write(dir / "lines.obj", vertices + "l 1 2 3 4 1\nl 2 4\n"), "has no triangle faces (only points or lines)");
  check_refused(write(dir / "points.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                                          "property float z\nend_header\n0 0 0\n"),
                "has no triangle faces (only points or lines)");
}

TEST_CASE("mesh files: a directory, a device, a FIFO or a symlink to a device is refused as what it is", "[mesh][mesh_file]") {
  const fs::path dir = scratch("special");
  fs::create_directory(dir / "folder.obj");
  check_refused(dir / "folder.obj", "is a directory, not a mesh file");
  check_refused("/dev/null", "is a device, not a mesh file");
  REQUIRE(::mkfifo((dir / "pipe.obj").c_str(), 0600) == 0);
  check_refused(dir / "pipe.obj", "is a FIFO, not a mesh file");
  fs::create_symlink("/dev/zero", dir / "zero.ply");
  check_refused(dir / "zero.ply", "is a device, not a mesh file");
  check_refused(dir / "missing.obj", "no such mesh file");
}

TEST_CASE("mesh files: a mesh file over 1 GiB is refused before it is read", "[mesh][mesh_file]") {
  const fs::path dir = scratch("large");
  write(dir / "large.obj", obj(k_cube));
  fs::resize_file(dir / "large.obj", (std::uintmax_t(1) << 30) + 1);  // sparse: no disk used
  check_refused(dir / "large.obj", "larger than the 1 GiB a mesh file may be");
}

TEST_CASE("mesh files: a line of more fields than a polygon may have is refused before it is split whole",
          "[mesh][mesh_file]") {
  // 2^20 + 1 corners on one face line (8 MB): the split stops at the limit instead of making a
  // token of every field of a line that could be the whole 1 GiB file.
  const fs::path dir = scratch("long_line");
  std::string face = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf";
  for (size_t i = 0; i <= (size_t(1) << 20); ++i) face += " 1";
  check_refused(write(dir / "long.obj", face + "\n"), "more than 1048576 fields on one line");
  std::string values = "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                       "property float z\nend_header\n0";
  for (size_t i = 0; i <= (size_t(1) << 20); ++i) values += " 0";
  check_refused(write(dir / "long.ply", values + "\n"), "more than 1048576 values on one line");
}
