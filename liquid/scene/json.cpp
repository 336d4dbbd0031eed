// Scene files as JSON: reading the file (bounded in size), syntax errors with their line, repeated
// keys (which nlohmann would silently resolve to the last value) and the structural limits of
// scene.h, all reported by path.
#include "liquid/scene.h"
#include "liquid/scene/limits.h"
#include "liquid/scene/reader.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <system_error>
#include <vector>

namespace liquid {
namespace {

using scene_reader::child;
using scene_reader::element;
using scene_reader::Json;

// ---- JSON syntax -------------------------------------------------------------------------------

// 1-based line of byte offset `byte` (nlohmann's 1-based position of the offending character).
int line_of(const std::string& text, size_t byte) {
  const size_t end = std::min(text.size(), byte > 0 ? byte - 1 : 0);
  return 1 + int(std::count(text.begin(), text.begin() + std::ptrdiff_t(end), '\n'));
}

// nlohmann's "[json.exception.parse_error.101] parse error at line 3, column 7: syntax error while
// parsing value - invalid literal; ..." reduced to "while parsing value - invalid literal; ...".
std::string syntax_reason(const std::string& what) {
  std::string reason = what;
  if (reason.rfind("[json.exception", 0) == 0)
    if (const size_t bracket = reason.find("] "); bracket != std::string::npos) reason = reason.substr(bracket + 2);
  if (const size_t column = reason.find("column "); column != std::string::npos)
    if (const size_t colon = reason.find(": ", column); colon != std::string::npos) reason = reason.substr(colon + 2);
  const std::string prefix = "syntax error ";
  if (reason.rfind(prefix, 0) == 0) reason = reason.substr(prefix.size());
  return reason;
}

// Builds the document from nlohmann's SAX events, checking each event as it comes: a repeated
// key, nesting past k_max_scene_nesting, an array past k_max_fluid_blocks elements and more than
// k_max_scene_values values in all are refused at once, by path. Every step costs O(log n) at most,
// so loading is linear in the file's size. (nlohmann's parse callback, used before, rescans the
// whole parent container after each object: 100k fluid blocks took 7 s.)
class DocumentBuilder {
 public:
  DocumentBuilder(const std::string& text, const std::string& source, Json& root)
      : text_(text), source_(source), root_(root) {}

  bool null() { return add(Json(nullptr)); }
  bool boolean(bool value) { return add(Json(value)); }
  bool number_integer(Json::number_integer_t value) { return add(Json(value)); }
  bool number_unsigned(Json::number_unsigned_t value) { return add(Json(value)); }
  bool number_float(Json::number_float_t value, const Json::string_t&) { return add(Json(value)); }
  bool string(Json::string_t& value) { return add(Json(std::move(value))); }
  bool binary(Json::binary_t& value) { return add(Json(std::move(value))); }  // not produced by JSON text
  bool start_object(std::size_t) { return open(Json::object()); }
  bool start_array(std::size_t) { return open(Json::array()); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }

  bool key(Json::string_t& name) {
    Frame& top = frames_.back();
    top.key = name;
    if (top.value->contains(name)) fail(path(), "duplicate key");
    return true;
  }

  [[noreturn]] bool parse_error(std::size_t position, const std::string&, const Json::exception& error) {
    if (dynamic_cast<const Json::parse_error*>(&error))
      throw SceneError(source_ + ": line " + std::to_string(line_of(text_, position)) +
                       ": JSON syntax error: " + syntax_reason(error.what()));
    throw SceneError(source_ + ": JSON error: " + syntax_reason(error.what()));  // e.g. 1e400
  }

 private:
  struct Frame {
    Json* value;      // the open object or array, inside its parent (whose storage is stable
                      // while it is open: only its last member is ever added to)
    std::string key;  // objects: the member being read
  };

  [[noreturn]] void fail(const std::string& at, const std::string& reason) const {
    throw SceneError(source_ + ": " + (at.empty() ? "(document)" : at) + ": " + reason);
  }

  // Places `value` where the parser is and returns it.
  Json* place(Json&& value) {
    if (++values_ > k_max_scene_values)
      fail(path(), "the file holds more than " + format_number(k_max_scene_values) + " JSON values");
    if (frames_.empty()) {
      root_ = std::move(value);
      return &root_;
    }
    Frame& top = frames_.back();
    if (top.value->is_object()) return &((*top.value)[top.key] = std::move(value));
    if (top.value->size() >= size_t(k_max_fluid_blocks))
      fail(path(false), "has more than " + format_number(k_max_fluid_blocks) + " elements, the most any list may hold");
    top.value->push_back(std::move(value));
    return &top.value->back();
  }

  bool add(Json&& value) {
    place(std::move(value));
    return true;
  }

  bool open(Json&& container) {
    if (int(frames_.size()) >= k_max_scene_nesting)
      fail(path(), "nested deeper than " + std::to_string(k_max_scene_nesting) + " levels");
    frames_.push_back({place(std::move(container)), {}});
    return true;
  }

  bool close() {
    frames_.pop_back();
    return true;
  }

  // Where the parser is, built only for a message: with `pending`, the member being read
  // ("fluid_blocks[1].min", "fluid_blocks[2]"), else the innermost open container ("fluid_blocks").
  std::string path(bool pending = true) const {
    std::string text;
    for (size_t i = 0; i < frames_.size(); ++i) {
      const Frame& f = frames_[i];
      const bool last = i + 1 == frames_.size();
      if (last && !pending) break;
      if (f.value->is_object())
        text = child(text, f.key);
      else  // an open child is its parent's last element; a pending one comes next
        text = element(text, last ? f.value->size() : f.value->size() - 1);
    }
    return text;
  }

  const std::string& text_;
  const std::string& source_;
  Json& root_;
  std::vector<Frame> frames_;
  int values_ = 0;
};

}  // namespace

Scene parse_scene(const std::string& json_text, const std::string& source_name) {
  if (json_text.size() > k_max_scene_bytes)
    throw SceneError(source_name + ": " + format_number(double(json_text.size())) + " bytes, larger than the " +
                     format_number(double(k_max_scene_bytes >> 20)) + " MiB a scene file may be");
  Json doc;
  DocumentBuilder builder(json_text, source_name, doc);
  Json::sax_parse(json_text, &builder);
  Scene scene = scene_reader::read_scene(doc, source_name);
  scene.source = source_name;
  check_list_limits(scene);
  check_projection(scene);
  return scene;
}

Scene load_scene(const std::filesystem::path& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error))
    throw SceneError(path.string() + ": is a directory, not a scene file");
  std::ifstream file(path, std::ios::binary);
  if (!file) throw SceneError(path.string() + ": cannot open scene file (" + std::strerror(errno) + ")");
  // Read at most one byte past the limit, so an oversized file (or an endless one such as
  // /dev/zero) is refused without being read whole.
  std::string text(k_max_scene_bytes + 1, '\0');
  file.read(text.data(), std::streamsize(text.size()));
  if (file.bad()) throw SceneError(path.string() + ": cannot read scene file");
  text.resize(size_t(file.gcount()));
  if (text.size() > k_max_scene_bytes)
    throw SceneError(path.string() + ": larger than the " + format_number(double(k_max_scene_bytes >> 20)) +
                     " MiB a scene file may be");
  return parse_scene(text, path.string());
}

}  // namespace liquid
