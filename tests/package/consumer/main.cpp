// Links the host's engine and the liquid; creates a context (on a device if there is one) and
// reports what the library needs of a host's device.
#include "engine/vk/context.h"
#include "engine/vk/device_requirements.h"
#include "liquid/scene.h"

#include <cstdio>

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
  return 0;
}
