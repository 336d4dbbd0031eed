// The header comments every frame file of a cache carries (the particles', the whitewater's and the
// mesh's): the frame number, its simulated time and, when known, the sequence's rate.
#pragma once

#include <cstdio>
#include <string>

namespace liquid {

// "<prefix> frame 12\n<prefix> time_s 0.25\n<prefix> fps 30\n": the doubles printed so they
// round-trip; the fps line only when fps > 0.
inline std::string frame_comments(const char* prefix, int frame, double time_s, double fps) {
  char text[160];
  std::snprintf(text, sizeof text, "%s frame %d\n%s time_s %.17g\n", prefix, frame, prefix, time_s);
  std::string out = text;
  if (fps > 0.0) {
    std::snprintf(text, sizeof text, "%s fps %.17g\n", prefix, fps);
    out += text;
  }
  return out;
}

}  // namespace liquid
