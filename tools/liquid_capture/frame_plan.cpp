#include "tools/liquid_capture/frame_plan.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

namespace capture {

bool has_frame_field(const std::string& name) { return hash_form(name).find('#') != std::string::npos; }

std::string hash_form(const std::string& name) {
  std::string out;
  for (size_t i = 0; i < name.size();) {
    size_t digits = 0;
    if (name[i] == '%') {  // printf: %d, %4d, %04d
      size_t j = i + 1;
      while (j < name.size() && std::isdigit(static_cast<unsigned char>(name[j]))) ++j;
      if (j < name.size() && name[j] == 'd' && j - i - 1 <= 2) {  // a width of at most two digits
        digits = j > i + 1 ? size_t(std::stoi(name.substr(i + 1, j - i - 1))) : 1;
        if (digits >= 1 && digits <= 16) {
          out.append(digits, '#');
          i = j + 1;
          continue;
        }
      }
    } else if (name.compare(i, 2, "$F") == 0) {  // Houdini: $F, $F4
      size_t j = i + 2;
      while (j < name.size() && std::isdigit(static_cast<unsigned char>(name[j]))) ++j;
      digits = j == i + 2 ? 1 : j - i - 2 <= 2 ? size_t(std::stoi(name.substr(i + 2, j - i - 2))) : 0;
      if (digits >= 1 && digits <= 16) {
        out.append(digits, '#');
        i = j;
        continue;
      }
    }
    out += name[i++];
  }
  return out;
}

NamePattern NamePattern::parse(const std::string& given, const std::string& flag, const std::string& extension) {
  const auto fail = [&](const std::string& why) { return std::invalid_argument(flag + " " + given + ": " + why); };
  if (given.find('/') != std::string::npos) throw fail("a file name inside the output folder, not a path");
  const std::string text = hash_form(given);
  const size_t first = text.find('#');
  if (first == std::string::npos)
    throw fail("needs a frame number field: a run of '#', %04d or $F4 (e.g. liquid_####" + extension + ")");
  const size_t last = text.find_last_of('#');
  if (text.find_first_not_of('#', first) < last) throw fail("only one run of '#' is allowed");
  const bool ends = text.size() > extension.size() &&
                    text.compare(text.size() - extension.size(), extension.size(), extension) == 0;
  if (!ends || last >= text.size() - extension.size()) throw fail("must end in " + extension + " after the '#'s");
  NamePattern p;
  p.text_ = text;
  p.prefix_ = text.substr(0, first);
  p.suffix_ = text.substr(last + 1);
  p.width_ = int(last - first + 1);
  return p;
}

std::string NamePattern::name(int frame) const {
  std::string digits = std::to_string(frame);
  if (int(digits.size()) < width_) digits.insert(0, size_t(width_) - digits.size(), '0');
  return prefix_ + digits + suffix_;
}

bool NamePattern::matches(const std::string& file_name, bool or_partial) const {
  std::string name = file_name;
  const std::string partial = ".partial";
  if (or_partial && name.size() > partial.size() && name.compare(name.size() - partial.size(), partial.size(), partial) == 0)
    name.resize(name.size() - partial.size());
  if (name.size() < prefix_.size() + suffix_.size() + size_t(width_)) return false;
  if (name.compare(0, prefix_.size(), prefix_) != 0) return false;
  if (name.compare(name.size() - suffix_.size(), suffix_.size(), suffix_) != 0) return false;
  const std::string digits = name.substr(prefix_.size(), name.size() - prefix_.size() - suffix_.size());
  return digits.find_first_not_of("0123456789") == std::string::npos;
}

int steps_per_frame(int steps_flag, double fps, double time_step, int substeps, int max_steps) {
  if (steps_flag > 0) return steps_flag;
  if (fps <= 0.0) return substeps;
  const double steps = std::ceil(1.0 / (fps * time_step) * (1.0 - 1e-9));  // ceil, past rounding noise
  if (steps > max_steps)
    throw std::invalid_argument("--fps " + std::to_string(fps) + " needs " + std::to_string(steps) + " steps of " +
                                std::to_string(time_step) + " s per frame, more than " + std::to_string(max_steps));
  return std::max(1, int(steps));
}

}  // namespace capture
