// --dry-run: what a capture would do, without writing anything: the resolved scene, the frame plan
// and the files, and an estimate of the time from a short probe on this machine (a simulated
// frame and a written frame, timed after one warm-up frame), not from figures of another machine.
#pragma once

#include "liquid/node.h"
#include "liquid/renderer.h"
#include "tools/common/frame_loop.h"
#include "tools/liquid_capture/options.h"

namespace engine::vk {
class Context;
}

namespace capture {

void dry_run(const RunSettings& settings, engine::vk::Context& context, liquid::LiquidNode& node,
             liquid::LiquidRenderer& renderer, const liquid::CameraView& camera, tools::FrameLoop& loop);

}  // namespace capture
