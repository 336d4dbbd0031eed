// A binary little-endian PLY point cloud read back as a generic reader (Blender's, Houdini's) reads
// it: from the header's element and property lines alone, each value decoded by its declared type.
// For the tests of the exported caches, so a file is checked by what it says, not by what its
// writer meant.
#pragma once

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace test {

struct PlyPoints {
  std::string format;                                           // "binary_little_endian 1.0"
  std::vector<std::string> comments;                            // without "comment "
  std::vector<std::pair<std::string, std::string>> properties;  // the vertex's, in order: (type, name)
  std::vector<std::map<std::string, double>> vertices;          // each value widened to double
};

// Throws std::runtime_error naming the path when the file is not a binary PLY of one vertex
// element whose properties are uchar, int, uint or float, or its size is not the header's count.
inline PlyPoints read_ply_points(const std::filesystem::path& path) {
  const auto fail = [&](const std::string& what) { throw std::runtime_error(path.string() + ": " + what); };
  std::ifstream file(path, std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
  const std::string end = "end_header\n";
  const size_t body = bytes.find(end);
  if (bytes.rfind("ply\n", 0) != 0 || body == std::string::npos) fail("not a PLY file");
  PlyPoints ply;
  size_t count = 0;
  std::istringstream header(bytes.substr(0, body));
  std::string line;
  while (std::getline(header, line)) {
    std::istringstream words(line);
    std::string word, type, name;
    words >> word;
    if (word == "format") {
      ply.format = line.substr(7);
    } else if (word == "comment") {
      ply.comments.push_back(line.substr(8));
    } else if (word == "element") {
      words >> name >> count;
      if (name != "vertex") fail("an element other than vertex: " + name);
    } else if (word == "property") {
      words >> type >> name;
      ply.properties.emplace_back(type, name);
    }
  }
  const std::map<std::string, size_t> sizes{{"uchar", 1}, {"int", 4}, {"uint", 4}, {"float", 4}};
  size_t vertex_bytes = 0;
  for (const auto& [type, name] : ply.properties) {
    if (!sizes.count(type)) fail("property " + name + " of type " + type);
    vertex_bytes += sizes.at(type);
  }
  const char* at = bytes.data() + body + end.size();
  if (ply.format != "binary_little_endian 1.0" || size_t(bytes.data() + bytes.size() - at) != count * vertex_bytes)
    fail("not " + std::to_string(count) + " binary little-endian vertices of " + std::to_string(vertex_bytes) + " bytes");
  for (size_t v = 0; v < count; ++v) {
    std::map<std::string, double>& values = ply.vertices.emplace_back();
    for (const auto& [type, name] : ply.properties) {
      if (type == "uchar") {
        values[name] = uint8_t(*at);
      } else {
        uint32_t bits;
        std::memcpy(&bits, at, 4);
        float f;
        std::memcpy(&f, at, 4);
        values[name] = type == "float" ? double(f) : type == "int" ? double(int32_t(bits)) : double(bits);
      }
      at += sizes.at(type);
    }
  }
  return ply;
}

}  // namespace test
