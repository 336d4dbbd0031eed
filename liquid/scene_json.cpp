// Scene files as JSON: reading the file, syntax errors with their line, and repeated keys (which
// nlohmann would silently resolve to the last value) reported by path.
#include "liquid/scene.h"
#include "liquid/scene_reader.h"

#include <fstream>
#include <set>
#include <vector>

namespace liquid {
namespace {

using scene_reader::child;
using scene_reader::element;
using scene_reader::Json;

// ---- JSON syntax -------------------------------------------------------------------------------

// Tracks where the parser is ("fluid_blocks[1].min") so a repeated key, which nlohmann would
// silently resolve to its last value, is reported by path.
class DuplicateKeyCheck {
 public:
  explicit DuplicateKeyCheck(std::string source) : source_(std::move(source)) {}

  bool operator()(int, Json::parse_event_t event, Json& parsed) {
    using Event = Json::parse_event_t;
    switch (event) {
      case Event::object_start:
      case Event::array_start:
        count_element();
        frames_.push_back({event == Event::array_start, -1, {}, {}});
        break;
      case Event::object_end:
      case Event::array_end:
        frames_.pop_back();
        break;
      case Event::key: {
        Frame& top = frames_.back();
        top.key = parsed.get<std::string>();
        if (!top.keys.insert(top.key).second) throw SceneError(source_ + ": " + path() + ": duplicate key");
        break;
      }
      case Event::value:
        count_element();
        break;
    }
    return true;
  }

 private:
  struct Frame {
    bool array;
    int index;
    std::string key;
    std::set<std::string> keys;
  };

  void count_element() {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
  }

  std::string path() const {
    std::string text;
    for (const Frame& f : frames_)
      text = f.array ? element(text, size_t(std::max(f.index, 0))) : child(text, f.key);
    return text;
  }

  std::string source_;
  std::vector<Frame> frames_;
};

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

}  // namespace

Scene parse_scene(const std::string& json_text, const std::string& source_name) {
  Json doc;
  try {
    doc = Json::parse(json_text, DuplicateKeyCheck(source_name));
  } catch (const Json::parse_error& e) {
    throw SceneError(source_name + ": line " + std::to_string(line_of(json_text, e.byte)) +
                     ": JSON syntax error: " + syntax_reason(e.what()));
  } catch (const Json::exception& e) {  // e.g. a number literal too large for a double
    throw SceneError(source_name + ": JSON error: " + syntax_reason(e.what()));
  }
  return scene_reader::read_scene(doc, source_name);
}

Scene load_scene(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw SceneError(path.string() + ": cannot open scene file");
  std::ostringstream text;
  text << file.rdbuf();
  if (file.bad()) throw SceneError(path.string() + ": cannot read scene file");
  return parse_scene(text.str(), path.string());
}

}  // namespace liquid
