// libFuzzer target for the mesh readers (PLY when the bytes begin with "ply", else OBJ): any bytes
// must either load as a closed mesh or be refused with a SceneError (one line naming the file and
// the fault). Anything else (another exception, a crash, a sanitizer report, a hang past libFuzzer's
// -timeout, memory past -rss_limit_mb) is a finding. Built by the "fuzz" preset (clang);
// tests/fuzz/CMakeLists.txt runs it from tests/fuzz/mesh_seeds and the shipped meshes.
#include "liquid/scene.h"
#include "liquid/scene/mesh_file.h"

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    liquid::parse_mesh(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.obj");
  } catch (const liquid::SceneError&) {
    // A refusal is the expected answer to most inputs.
  }
  return 0;
}
