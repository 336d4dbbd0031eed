// libFuzzer target for the scene parser: any bytes must either load or be refused with a
// SceneError (one line naming the file and the field). Anything else (another exception, a crash,
// a sanitizer report, a hang past libFuzzer's -timeout) is a finding. Built by the "fuzz" preset
// (clang); tests/fuzz/CMakeLists.txt runs it from the shipped scenes.
#include "liquid/scene.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    liquid::parse_scene(text, "fuzz.json");
  } catch (const liquid::SceneError&) {
    // A refusal is the expected answer to most inputs.
  }
  return 0;
}
