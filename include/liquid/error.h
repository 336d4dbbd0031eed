// The library's errors. Everything the liquid library throws for what a caller gave it, or for what
// the device cannot do, is a liquid::Error: a std::runtime_error whose what() is one line naming
// the problem ("liquid: obstacle 7 does not exist", "scenes/x.json: fluid_blocks[1].min: must lie
// inside the domain"). Catch liquid::Error for all of them, or one kind where a caller must tell
// them apart:
//   SceneError       a scene the library cannot run: the file, a field, a mesh (names the file and field)
//   ArgumentError    a call's argument outside what it takes: an obstacle index, a non-finite force,
//                    a checkpoint of another scene, too many steps for the node's uniform space
//   UsageError       a call out of order or against how the object was made: a compositing renderer
//                    asked for a frame of its own, FXAA on a host panel, a fifth view in one frame
//   DeviceError      the device cannot run the scene as asked: an image past its limits, a 3D path
//                    or a blendable format it lacks
//   SimulationError  the run became unstable (a non-finite value, or kinetic energy past its bound)
// Two others are not the library's to name: engine::vk::NoDeviceError (no usable Vulkan device at
// all) and engine::vk::VulkanError (a Vulkan call failed), the engine's. A std::logic_error from the
// library means a broken invariant inside it: a bug to report.
#pragma once

#include <stdexcept>

namespace liquid {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class SceneError : public Error {
 public:
  using Error::Error;
};

class ArgumentError : public Error {
 public:
  using Error::Error;
};

class UsageError : public Error {
 public:
  using Error::Error;
};

class DeviceError : public Error {
 public:
  using Error::Error;
};

class SimulationError : public Error {
 public:
  using Error::Error;
};

}  // namespace liquid
