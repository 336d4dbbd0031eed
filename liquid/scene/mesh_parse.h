// What the OBJ and PLY readers share: the limits a mesh file is held to, strict number parsing,
// line splitting and the refusal. Internal to liquid/scene/.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace liquid {

// A mesh file is refused past these, before anything is allocated for it (the README's limits).
constexpr std::uint64_t k_max_mesh_file_bytes = std::uint64_t(1) << 30;  // 1 GiB
constexpr std::size_t k_max_mesh_vertices = std::size_t(1) << 25;        // 33,554,432
constexpr std::size_t k_max_mesh_triangles = std::size_t(1) << 25;       // after fan triangulation
// |x|, |y| and |z| of every vertex in the file's own units, before the obstacle's `scale` (at most
// 100): far past any tank, and far from float's range once scaled and placed.
constexpr double k_max_mesh_coordinate = 1e6;

namespace mesh_parse {

// Throws SceneError "<name>: <what>".
[[noreturn]] void fail(const std::string& name, const std::string& what);

// A whole token as a finite decimal number ("-1.5e3", "+2", ".5"); nullopt for anything else: hex
// floats, nan, inf, a result out of double's range, "abc", trailing characters ("1.0x").
std::optional<double> to_number(std::string_view token);

// A whole token as a decimal integer that fits int64 ("-3", "+7"); nullopt otherwise.
std::optional<std::int64_t> to_integer(std::string_view token);

// "" when `x` may be a vertex coordinate (finite, within k_max_mesh_coordinate), else why not.
std::string coordinate_problem(double x);

// A token as a message quotes it: `abc`, control characters escaped, a long one cut.
std::string quote(std::string_view token);

// The most fields one line may hold (a polygon's corners): a single line of a 1 GiB file would
// otherwise become hundreds of millions of tokens before any count is checked.
constexpr std::size_t k_max_line_fields = std::size_t(1) << 20;

// Splits `line` at spaces and tabs into `tokens` (cleared first; views into `line`); false, with
// the first k_max_line_fields tokens, when the line holds more.
[[nodiscard]] bool split(std::string_view line, std::vector<std::string_view>& tokens);

// The lines of a text one at a time, without their "\n" or "\r\n", numbered from 1. Linear in the
// text: a line without its newline at the end of the text is the last one.
class LineReader {
 public:
  explicit LineReader(std::string_view text) : text_(text) {}
  // The next line, false at the end of the text.
  bool next(std::string_view& line);
  std::size_t line_number() const { return line_number_; }  // of the line last returned
  std::size_t offset() const { return at_; }                // bytes consumed, newline included
  bool ended_by_newline() const { return ended_by_newline_; }  // the last line returned had one

 private:
  std::string_view text_;
  std::size_t at_ = 0;
  std::size_t line_number_ = 0;
  bool ended_by_newline_ = false;
};

}  // namespace mesh_parse
}  // namespace liquid
