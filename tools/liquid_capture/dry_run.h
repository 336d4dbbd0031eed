// --dry-run: what a capture would do, without writing anything: the resolved scene, the frame plan
// and the files, and an estimate of the time from a short probe on this machine (simulated and
// written frames, timed after a warm-up frame of each), not from figures of another machine. The
// estimate counts the startup too: the time from `process_start` to the probe.
#pragma once

#include "liquid/node.h"
#include "liquid/renderer.h"
#include "tools/common/frame_loop.h"
#include "tools/liquid_capture/options.h"

#include <chrono>

namespace engine::vk {
class Context;
}

namespace capture {

void dry_run(const RunSettings& settings, engine::vk::Context& context, liquid::LiquidNode& node,
             liquid::LiquidRenderer& renderer, const liquid::CameraView& camera, tools::FrameLoop& loop,
             std::chrono::steady_clock::time_point process_start);

}  // namespace capture
