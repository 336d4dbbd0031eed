#include "tools/liquid_viewer/script.h"

#include "tools/liquid_viewer/controls.h"

#include <GLFW/glfw3.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <stdexcept>

namespace viewer {

Script::Script(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": cannot open the script");
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& error) {
    throw std::runtime_error(path.string() + ": not JSON: " + error.what());
  }
  if (!doc.is_array()) throw std::runtime_error(path.string() + ": a script is a list of events");
  // A whole number in [lo, hi], read as written: nlohmann's get<int>() would narrow 4294967296 to 0
  // and 2.9 to 2 without a word.
  const auto integer = [](const nlohmann::json& value, const char* name, std::int64_t lo, std::int64_t hi) {
    if (!value.is_number_integer() || (value.is_number_unsigned() && value.get<std::uint64_t>() > std::uint64_t(hi)) ||
        value.get<std::int64_t>() < lo || value.get<std::int64_t>() > hi)
      throw std::runtime_error(std::string(name) + " must be an integer in [" + std::to_string(lo) + ", " +
                               std::to_string(hi) + "], got " + value.dump());
    return int(value.get<std::int64_t>());
  };
  const auto finite = [](const nlohmann::json& value, const char* name) {
    if (!value.is_number() || !std::isfinite(value.get<double>()) || std::abs(value.get<double>()) > 1e6)
      throw std::runtime_error(std::string(name) + " must be a finite number of at most 1e6, got " + value.dump());
    return value.get<float>();
  };
  glm::vec2 cursor{0.0f};
  for (size_t i = 0; i < doc.size(); ++i) {
    const nlohmann::json& e = doc[i];
    const std::string where = path.string() + ": event " + std::to_string(i) + ": ";
    try {
      ScriptEvent s;
      s.frame = integer(e.at("frame"), "frame", 0, std::numeric_limits<int>::max() - 1);
      const std::string type = e.at("type").get<std::string>();
      InputEvent& ev = s.event;
      if (type == "move") {
        ev.type = InputEvent::Type::Move;
        cursor = {finite(e.at("x"), "x"), finite(e.at("y"), "y")};
      } else if (type == "press" || type == "release") {
        ev.type = type == "press" ? InputEvent::Type::Press : InputEvent::Type::Release;
        const std::string b = e.value("button", "left");
        if (b == "left") ev.button = MouseButton::Left;
        else if (b == "right") ev.button = MouseButton::Right;
        else if (b == "middle") ev.button = MouseButton::Middle;
        else throw std::runtime_error("button must be left, right or middle, got '" + b + "'");
        if (e.value("shift", false)) ev.mods |= GLFW_MOD_SHIFT;
      } else if (type == "scroll") {
        ev.type = InputEvent::Type::Scroll;
        ev.scroll = finite(e.at("delta"), "delta");
        if (e.value("ctrl", false)) ev.mods |= GLFW_MOD_CONTROL;
      } else if (type == "key") {
        ev.type = InputEvent::Type::Key;
        const std::string name = e.at("key").get<std::string>();
        ev.key = key_code(name);
        if (ev.key < 0) throw std::runtime_error("unknown key '" + name + "'");
      } else if (type == "resize") {
        ev.type = InputEvent::Type::Resize;
        const int w = integer(e.at("width"), "width", 0, 8192), h = integer(e.at("height"), "height", 0, 8192);
        ev.width = uint32_t(w);
        ev.height = uint32_t(h);
      } else {
        throw std::runtime_error("type must be move, press, release, scroll, key or resize, got '" + type + "'");
      }
      ev.x = cursor.x;
      ev.y = cursor.y;
      events_.push_back(s);
    } catch (const nlohmann::json::exception& error) {
      throw std::runtime_error(where + error.what());
    } catch (const std::runtime_error& error) {
      throw std::runtime_error(where + error.what());
    }
  }
  std::stable_sort(events_.begin(), events_.end(), [](const ScriptEvent& a, const ScriptEvent& b) { return a.frame < b.frame; });
}

std::vector<InputEvent> Script::events_at(int frame) const {
  std::vector<InputEvent> out;
  for (const ScriptEvent& s : events_)
    if (s.frame == frame) out.push_back(s.event);
  return out;
}

}  // namespace viewer
