// The PIC/FLIP blend (section 5.1) as a rate. Each step, u_p' = r u'(x_p) + (1 - r)(u_p + u' - u):
// the particle's own deviation from the grid velocity decays by (1 - r) per step. With r fixed
// per step (the chapter) the damping per simulated second grows with the number of steps, so a
// longer step makes the liquid livelier (the collapsing column's front ran 10 % further at 8 times
// the step; docs/physics.md). Given the step dt_ref that r is meant for, a step dt blends by
//   r(dt) = 1 - (1 - r)^(dt / dt_ref),
// the same decay per second whatever the step.
#pragma once

namespace liquid {

// r for a step of `dt` seconds; `reference_step` <= 0 means r per step (returned as it is).
double pic_blend_for_step(double pic_ratio, double reference_step, double dt);

}  // namespace liquid
