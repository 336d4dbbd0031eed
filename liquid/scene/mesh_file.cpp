#include "liquid/scene/mesh_file.h"

#include "liquid/scene/format.h"
#include "liquid/scene/mesh_check.h"
#include "liquid/scene/mesh_parse.h"
#include "liquid/scene/obj_reader.h"
#include "liquid/scene/ply_reader.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>

namespace liquid {
namespace {

bool starts_with_ply_line(std::string_view bytes) {
  return bytes.starts_with("ply\n") || bytes.starts_with("ply\r\n");
}

std::string lowercase_extension(const std::string& name) {
  std::string extension = std::filesystem::path(name).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return extension;
}

// What a path that is not a regular file is, for the message.
std::string not_regular(mode_t mode) {
  if (S_ISDIR(mode)) return "is a directory, not a mesh file";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "is a device, not a mesh file";
  if (S_ISFIFO(mode)) return "is a FIFO, not a mesh file";
  if (S_ISSOCK(mode)) return "is a socket, not a mesh file";
  return "is not a regular file";
}

// The whole file, after checking what it is on the open descriptor itself (O_NONBLOCK: opening a
// FIFO does not wait for a writer), so a path swapped in between cannot hang or flood the read.
std::string read_file(const std::filesystem::path& path) {
  const auto refuse = [&](const std::string& what) { mesh_parse::fail(path.string(), what); };
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) refuse(errno == ENOENT ? "no such mesh file" : std::string("cannot open the mesh file (") + std::strerror(errno) + ")");
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat info {};
  if (::fstat(fd, &info) != 0) refuse(std::string("cannot read the mesh file (") + std::strerror(errno) + ")");
  if (!S_ISREG(info.st_mode)) refuse(not_regular(info.st_mode));
  if (std::uint64_t(info.st_size) > k_max_mesh_file_bytes)
    refuse(format_number(double(info.st_size)) + " bytes, larger than the 1 GiB a mesh file may be");
  std::string bytes(size_t(info.st_size), '\0');
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::read(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) refuse(std::string("cannot read the mesh file (") + std::strerror(errno) + ")");
    if (n == 0) break;  // shrank while being read: the readers refuse what is cut
    done += size_t(n);
  }
  bytes.resize(done);
  return bytes;
}

}  // namespace

TriangleMesh parse_mesh(std::string_view bytes, const std::string& name) {
  const auto refuse = [&](const std::string& what) { mesh_parse::fail(name, what); };
  const std::string extension = lowercase_extension(name);
  TriangleMesh mesh;
  if (starts_with_ply_line(bytes) || extension == ".ply") mesh = read_ply(bytes, name);
  else if (extension == ".obj") mesh = read_obj(bytes, name);
  else refuse("not a mesh file: neither a PLY file (first line `ply`) nor named *.obj");
  if (mesh.indices.empty()) refuse("has no triangle faces (only points or lines)");
  weld_positions(mesh);
  if (const std::string problem = mesh_problem(mesh); !problem.empty()) refuse(problem);
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const glm::vec3& v : mesh.vertices) {
    lo = glm::min(lo, v);
    hi = glm::max(hi, v);
  }
  const glm::vec3 middle = 0.5f * (lo + hi);
  for (glm::vec3& v : mesh.vertices) v -= middle;
  mesh.file = name;
  return mesh;
}

TriangleMesh load_mesh_file(const std::filesystem::path& path) { return parse_mesh(read_file(path), path.string()); }

}  // namespace liquid
