// A mesh obstacle's winding, checked once when a scene enters the library (with the list limits,
// liquid/scene/limits.h): the rasterizer's inside test and a body's mass follow the winding, so an
// inside-out mesh would turn the liquid into the obstacle and a body's volume negative.
#pragma once

#include "liquid/scene.h"

namespace liquid {

// Throws SceneError naming the scene's source, the obstacle and its file: "pool.json: obstacles[0]:
// boat.obj: is inside out (...)".
void check_mesh_winding(const Scene& scene);

}  // namespace liquid
