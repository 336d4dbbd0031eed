#include "tools/liquid_capture/checkpoint.h"

#include "engine/io/atomic_file.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <type_traits>

namespace capture {
namespace {

// 02: the node's next time step follows its clock (adaptive steps). 03: a checksum of the content
// closes the file. 06: the secondary particles' textures (whitewater) follow the bodies'. 07: the
// pressure projection's solution follows the whitewater.
constexpr char k_magic[8] = {'L', 'Q', 'C', 'K', 'P', 'T', '0', '7'};

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

std::string read_sized_file(const std::filesystem::path& path, std::uintmax_t max_bytes, const std::string& kind) {
  std::error_code error;
  const bool regular = std::filesystem::is_regular_file(path, error);
  const std::uintmax_t size = regular ? std::filesystem::file_size(path, error) : 0;
  if (!regular || error || size > max_bytes)
    throw std::runtime_error(path.string() + ": not a " + kind + " (not a regular file of at most " +
                             std::to_string(max_bytes >> 20) + " MiB)");
  std::ifstream file(path, std::ios::binary);
  std::string bytes(size_t(size), '\0');
  file.read(bytes.data(), std::streamsize(bytes.size()));
  if (!file) throw std::runtime_error(path.string() + ": cannot read the " + kind);
  return bytes;
}

uint64_t fingerprint(std::string_view text) {
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
  w.put_vector(c.node.affine);
  w.put_vector(c.node.bodies);
  w.put_vector(c.node.whitewater);
  w.put_vector(c.node.pressure);
  w.put_vector(std::vector<char>(c.stats_csv.begin(), c.stats_csv.end()));
  w.put(fingerprint(w.bytes_));  // over everything before it
  engine::io::write_file_atomically(path, w.bytes_);
}

CaptureCheckpoint load_checkpoint(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::exists(path, error))
    throw std::runtime_error(path.string() + ": no checkpoint to resume from (was --checkpoint-every given?)");
  // No larger than its particle textures at the largest the solver takes, plus the table.
  const std::string bytes = read_sized_file(path, k_max_checkpoint_bytes, "checkpoint");
  Reader r(bytes, path.string());
  char magic[8];
  for (char& m : magic) m = r.get<char>();
  if (std::memcmp(magic, k_magic, sizeof magic - 2) == 0 && std::memcmp(magic, k_magic, sizeof magic) != 0)
    throw std::runtime_error(path.string() + ": a checkpoint of another format version (" + std::string(magic + 6, 2) +
                             ", this build reads " + std::string(k_magic + 6, 2) + "); start the capture afresh");
  if (std::memcmp(magic, k_magic, sizeof magic) != 0) throw std::runtime_error(path.string() + ": not a checkpoint");
  uint64_t stored = 0;
  if (bytes.size() < sizeof magic + sizeof stored) r.fail();
  std::memcpy(&stored, bytes.data() + bytes.size() - sizeof stored, sizeof stored);
  if (stored != fingerprint(std::string_view(bytes).substr(0, bytes.size() - sizeof stored)))
    throw std::runtime_error(path.string() + ": damaged checkpoint (its checksum does not match its content); " +
                             "resume from an intact copy or start the capture afresh");
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
  c.node.affine = r.get_vector<glm::vec4>();
  c.node.bodies = r.get_vector<glm::vec4>();
  c.node.whitewater = r.get_vector<glm::vec4>();
  c.node.pressure = r.get_vector<float>();
  const std::vector<char> stats = r.get_vector<char>();
  c.stats_csv.assign(stats.begin(), stats.end());
  r.get<uint64_t>();  // the checksum, checked above
  if (!r.at_end()) r.fail();
  return c;
}

void check_against_plan(const CaptureCheckpoint& c, const FramePlan& plan, const std::string& source) {
  const auto refuse = [&](const std::string& what) {
    throw std::runtime_error(source + ": " + what + "; it does not belong to the run in capture.json");
  };
  if (c.frame < 0 || c.frame > plan.end)
    refuse("frame " + std::to_string(c.frame) + " is outside the run's frames 0 to " + std::to_string(plan.end));
  // Every frame ends on its time (frame * frame_seconds), with adaptive steps too.
  const double expected = c.frame * plan.frame_seconds();
  if (!(std::abs(c.node.time - expected) <= 1e-6 * std::max(1.0, expected)))
    refuse("its clock reads " + std::to_string(c.node.time) + " s, not frame " + std::to_string(c.frame) + "'s " +
           std::to_string(expected) + " s");
  if (c.node.step < 0 || (c.frame > 0 && c.node.step < c.frame)) refuse("its step count is " + std::to_string(c.node.step));
  const int written = std::max(0, c.frame - plan.start + 1);
  const auto lines = std::count(c.stats_csv.begin(), c.stats_csv.end(), '\n');
  if (lines != (written > 0 ? written + 1 : 0) && !(written == 0 && lines <= 1))
    refuse("its table has " + std::to_string(std::max<long>(0, long(lines) - 1)) + " rows for " + std::to_string(written) +
           " frames written");
}

}  // namespace capture
