// The scene's lists against what the solver's uniform block and shaders hold (the limits of
// shaders/liquid/shared.h): checked once, when a scene enters the library, by the reader for a file
// and by make_setup() for a scene built in code. The later stages (uniforms, specialization) trust
// a scene that passed.
#pragma once

#include "liquid/scene.h"

namespace liquid {

// Throws SceneError naming the scene's source and the list: "dam.json: obstacles: at most 8 are
// supported, got 9".
void check_list_limits(const Scene& scene);

// The pressure projection's keys against what its passes need (the splat-adjoint pressure, two
// iterations at least), checked at the same two places: a scene built in code that asks for the
// projection under the chapter's pressure would otherwise reach the solver without its images.
void check_projection(const Scene& scene);

}  // namespace liquid
