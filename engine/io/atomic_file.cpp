#include "engine/io/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

namespace engine::io {

void write_file_atomically(const std::filesystem::path& path, std::string_view bytes) {
  std::filesystem::path temporary = path;
  temporary += ".partial";
  {
    std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
    if (!file) throw std::runtime_error(path.string() + ": cannot write (is the folder there and writable?)");
    file.write(bytes.data(), std::streamsize(bytes.size()));
    file.close();
    if (!file) {
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      throw std::runtime_error(path.string() + ": write failed (disk full?)");
    }
  }
  // Make the bytes durable before the rename, so a crash cannot leave an empty file in place.
  if (const int fd = ::open(temporary.c_str(), O_RDONLY); fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    const std::string reason = error.message();
    std::filesystem::remove(temporary, error);
    throw std::runtime_error(path.string() + ": cannot rename into place (" + reason + ")");
  }
}

void ensure_writable_folder(const std::filesystem::path& folder) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) throw std::runtime_error(folder.string() + ": cannot create the output folder (" + error.message() + ")");
  if (!folder_is_writable(folder)) throw std::runtime_error(folder.string() + ": the output folder is not writable");
}

bool folder_is_writable(const std::filesystem::path& folder) {
  std::string probe = (folder / ".write_probe_XXXXXX").string();
  const int fd = ::mkstemp(probe.data());  // a new name, created exclusively
  if (fd < 0) return false;
  ::close(fd);
  ::unlink(probe.c_str());
  return true;
}

}  // namespace engine::io
