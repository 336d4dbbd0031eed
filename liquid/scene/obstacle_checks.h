// Where the obstacles are, checked once when a scene enters the library (with the list limits,
// liquid/scene/limits.h): a rigid body must start wholly inside the domain (the integrator keeps a
// body inside, so one placed outside would be moved without a word), and a mesh must wind outward
// (the rasterizer's inside test and a body's mass follow the winding, so an inside-out mesh turns
// the liquid into the obstacle and a body's volume negative).
#pragma once

#include "liquid/scene.h"

namespace liquid {

// Throws SceneError naming the scene's source, the obstacle and the bound it breaks:
// "tank.json: obstacles[0]: the dynamic box reaches x = 5.08 m, outside the domain's [0, 0.5] m".
void check_obstacle_placement(const Scene& scene);

}  // namespace liquid
