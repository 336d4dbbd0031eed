// Links the host's engine and the liquid; creates a context (on a device if there is one) and
// reports what the library needs of a host's device.
#include "engine/vk/context.h"
#include "engine/vk/device_requirements.h"
#include "liquid/scene.h"
#if RASTERLIQUIDS_HAVE_OPENVDB
#include "liquid/export/vdb.h"
#endif

#include <cstdio>
#include <filesystem>

int host_engine_version();

int main() {
  std::printf("host engine %d; the liquid needs:", host_engine_version());
  for (const char* extension : engine::vk::required_device_extensions()) std::printf(" %s", extension);
  std::printf("\n");
  try {
    engine::vk::Context context;
    std::printf("device: %s\n", context.device_name().c_str());
  } catch (const engine::vk::NoDeviceError& error) {
    std::printf("no device: %s\n", error.what());
  }
#if RASTERLIQUIDS_HAVE_OPENVDB
  // RasterLiquids::vdb links: a 2x2 volume of still liquid.
  liquid::VolumeFrame volume;
  volume.cells = {2, 2, 1};
  volume.cell_size = 0.1f;
  volume.density.assign(4, 1.0f);
  volume.velocity.assign(4, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "rasterliquids_consumer.vdb";
  liquid::write_vdb(path, volume, {});
  std::printf("wrote %s\n", path.string().c_str());
#endif
  return 0;
}
