#version 450
// Body force pass: writes the point's force and torque, blended (added) into the body's texel.
#extension GL_GOOGLE_include_directive : require
#include "liquid/shared.h"

layout(location = 0) flat in vec3 v_force;
layout(location = 1) flat in vec3 v_torque;
layout(location = LIQUID_BODY_TARGET_FORCE) out vec4 out_force;
layout(location = LIQUID_BODY_TARGET_TORQUE) out vec4 out_torque;

void main() {
  out_force = vec4(v_force, 0.0);
  out_torque = vec4(v_torque, 0.0);
}
