#include "tools/liquid_capture/checkpoint.h"

#include "engine/io/atomic_file.h"

#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <type_traits>

namespace capture {
namespace {

// 02: the node's next time step follows its clock (adaptive steps).
constexpr char k_magic[8] = {'L', 'Q', 'C', 'K', 'P', 'T', '0', '2'};

class Writer {
 public:
  template <class T>
  void put(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes_.append(reinterpret_cast<const char*>(&value), sizeof(T));
  }
  template <class T>
  void put_vector(const std::vector<T>& values) {
    put(uint64_t(values.size()));
    bytes_.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
  }
  std::string bytes_;
};

class Reader {
 public:
  Reader(std::string bytes, std::string source) : bytes_(std::move(bytes)), source_(std::move(source)) {}
  template <class T>
  T get() {
    T value;
    take(&value, sizeof(T));
    return value;
  }
  template <class T>
  std::vector<T> get_vector() {
    const uint64_t count = get<uint64_t>();
    if (count > (bytes_.size() - at_) / sizeof(T)) fail();
    std::vector<T> values(count);
    take(values.data(), count * sizeof(T));
    return values;
  }
  bool at_end() const { return at_ == bytes_.size(); }
  [[noreturn]] void fail() const { throw std::runtime_error(source_ + ": truncated or damaged checkpoint"); }

 private:
  void take(void* out, size_t size) {
    if (size > bytes_.size() - at_) fail();
    if (size == 0) return;  // an empty vector's data() may be null, which memcpy must not get
    std::memcpy(out, bytes_.data() + at_, size);
    at_ += size;
  }
  std::string bytes_, source_;
  size_t at_ = 0;
};

}  // namespace

uint64_t fingerprint(const std::string& text) {
  uint64_t hash = 14695981039346656037ull;
  for (const unsigned char c : text) hash = (hash ^ c) * 1099511628211ull;
  return hash;
}

void save_checkpoint(const std::filesystem::path& path, const CaptureCheckpoint& c) {
  Writer w;
  w.bytes_.append(k_magic, sizeof k_magic);
  w.put(c.settings_hash);
  w.put(int32_t(c.frame));
  w.put(int32_t(c.node.step));
  w.put(c.node.time);
  w.put(c.node.time_step);
  w.put(int32_t(c.node.active));
  w.put_vector(c.node.emitted);
  w.put(uint64_t(c.node.poses.size()));
  for (const auto& p : c.node.poses) {
    w.put(uint8_t(p.overridden));
    w.put(p.center);
    w.put(p.velocity);
    w.put(p.since);
  }
  w.put_vector(c.node.positions);
  w.put_vector(c.node.velocities);
  w.put_vector(std::vector<char>(c.stats_csv.begin(), c.stats_csv.end()));
  engine::io::write_file_atomically(path, w.bytes_);
}

CaptureCheckpoint load_checkpoint(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw std::runtime_error(path.string() + ": no checkpoint to resume from (was --checkpoint-every given?)");
  Reader r(std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()), path.string());
  char magic[8];
  for (char& m : magic) m = r.get<char>();
  if (std::memcmp(magic, k_magic, sizeof magic - 2) == 0 && std::memcmp(magic, k_magic, sizeof magic) != 0)
    throw std::runtime_error(path.string() + ": a checkpoint of another format version (" + std::string(magic + 6, 2) +
                             ", this build reads " + std::string(k_magic + 6, 2) + "); start the capture afresh");
  if (std::memcmp(magic, k_magic, sizeof magic) != 0) throw std::runtime_error(path.string() + ": not a checkpoint");
  CaptureCheckpoint c;
  c.settings_hash = r.get<uint64_t>();
  c.frame = r.get<int32_t>();
  c.node.step = r.get<int32_t>();
  c.node.time = r.get<double>();
  c.node.time_step = r.get<double>();
  c.node.active = r.get<int32_t>();
  c.node.emitted = r.get_vector<int>();
  const uint64_t poses = r.get<uint64_t>();
  if (poses > 1024) r.fail();
  for (uint64_t i = 0; i < poses; ++i) {
    liquid::LiquidNode::Checkpoint::Pose p;
    p.overridden = r.get<uint8_t>() != 0;
    p.center = r.get<glm::vec3>();
    p.velocity = r.get<glm::vec3>();
    p.since = r.get<double>();
    c.node.poses.push_back(p);
  }
  c.node.positions = r.get_vector<glm::vec4>();
  c.node.velocities = r.get_vector<glm::vec4>();
  const std::vector<char> stats = r.get_vector<char>();
  c.stats_csv.assign(stats.begin(), stats.end());
  if (!r.at_end()) r.fail();
  return c;
}

}  // namespace capture
