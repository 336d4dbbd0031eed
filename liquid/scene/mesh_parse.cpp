#include "liquid/scene/mesh_parse.h"

#include "liquid/scene.h"
#include "liquid/scene/format.h"

#include <charconv>
#include <cmath>

namespace liquid::mesh_parse {
namespace {

// from_chars takes a leading '-' but not '+', which files write too; "+-1" stays refused.
bool drop_plus(std::string_view& token) {
  if (!token.empty() && token[0] == '+') {
    token.remove_prefix(1);
    return !token.empty() && token[0] != '-';
  }
  return !token.empty();
}

}  // namespace

void fail(const std::string& name, const std::string& what) { throw SceneError(name + ": " + what); }

std::optional<double> to_number(std::string_view token) {
  if (!drop_plus(token)) return std::nullopt;
  double value = 0.0;
  const char* end = token.data() + token.size();
  // chars_format::general: no hex (it would stop at the 'x'); nan and inf parse and are refused below.
  const auto [stop, error] = std::from_chars(token.data(), end, value, std::chars_format::general);
  if (error != std::errc() || stop != end || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<std::int64_t> to_integer(std::string_view token) {
  if (!drop_plus(token)) return std::nullopt;
  std::int64_t value = 0;
  const char* end = token.data() + token.size();
  const auto [stop, error] = std::from_chars(token.data(), end, value, 10);
  if (error != std::errc() || stop != end) return std::nullopt;
  return value;
}

std::string coordinate_problem(double x) {
  if (!std::isfinite(x)) return "a coordinate is not finite (" + format_number(x) + ")";
  if (std::abs(x) > k_max_mesh_coordinate)
    return "coordinate " + format_number(x) + " is beyond the " + format_number(k_max_mesh_coordinate) +
           " a mesh file's vertices may reach (in its own units, before scale)";
  return "";
}

std::string quote(std::string_view token) { return "`" + printable(token, 40) + "`"; }

bool split(std::string_view line, std::vector<std::string_view>& tokens) {
  tokens.clear();
  size_t at = 0;
  while (at < line.size()) {
    while (at < line.size() && (line[at] == ' ' || line[at] == '\t')) ++at;
    const size_t start = at;
    while (at < line.size() && line[at] != ' ' && line[at] != '\t') ++at;
    if (at == start) continue;
    if (tokens.size() == k_max_line_fields) return false;
    tokens.push_back(line.substr(start, at - start));
  }
  return true;
}

bool LineReader::next(std::string_view& line) {
  if (at_ >= text_.size()) return false;
  const size_t end = text_.find('\n', at_);
  const size_t stop = end == std::string_view::npos ? text_.size() : end;
  line = text_.substr(at_, stop - at_);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  ended_by_newline_ = end != std::string_view::npos;
  at_ = ended_by_newline_ ? end + 1 : text_.size();
  ++line_number_;
  return true;
}

}  // namespace liquid::mesh_parse
