// One recorded frame: the node's steps, the renderer (and FXAA) into a graph image, the present
// pass into the imported swapchain image, then after the graph the panel or overlay, the screenshot copy and the
// transition to PRESENT_SRC, from the state the graph left the image in.
#include "tools/liquid_viewer/viewer.h"

#include "engine/vk/vk_check.h"
#include "liquid/solver/simulation.h"

#include <cmath>
#include <map>
#include <stdexcept>

namespace viewer {

int Viewer::steps_for_frame(double wall_seconds) {
  if (settings_.paused) {
    const int steps = settings_.step_once ? 1 : 0;
    settings_.step_once = false;
    clock_.reset();
    return steps;
  }
  if (settings_.pacing == Pacing::FixedSteps) return settings_.steps_per_frame;
  const int steps = clock_.steps(wall_seconds, simulation_of(session_->node()).setup().time_step, settings_.max_steps_per_frame);
  stats_.lag = clock_.lag();
  return steps;
}

void Viewer::apply_mouse(int steps) {
  liquid::LiquidNode& node = session_->node();
  const float dt = simulation_of(node).setup().time_step;
  const float frame_seconds = float(steps) * dt;
  const Interaction in = mouse_.frame(session_->mapping(), frame_seconds);
  node.set_brushes(in.brushes);
  if (!in.brushes.empty()) last_brush_ = in.brushes.front().position;
  const std::vector<liquid::ObstaclePose> poses = node.obstacle_poses(node.time());
  const auto dynamic = [&](size_t index) { return index < poses.size() && node.scene().obstacles[index].dynamic; };
  if (in.obstacle && dynamic(in.obstacle->index)) {
    // A dynamic body is pulled, not placed: a critically damped spring of k_drag_hz toward the
    // cursor that also carries its weight, from its state as last read back (latest_bodies()).
    constexpr float k_drag_hz = 2.0f;
    const float omega = 2.0f * float(M_PI) * k_drag_hz;
    for (const liquid::BodyState& b : node.latest_bodies())
      if (size_t(b.obstacle) == in.obstacle->index)
        node.set_body_force(in.obstacle->index, b.mass * (omega * omega * (in.obstacle->target - b.pose.center) -
                                                          2.0f * omega * b.pose.velocity -
                                                          node.runtime_parameters().gravity));
  } else if (in.obstacle && in.obstacle->index < poses.size()) {
    const glm::vec3 center = poses[in.obstacle->index].center;
    glm::vec3 velocity(0.0f);
    if (frame_seconds > 0.0f) velocity = (in.obstacle->target - center) / frame_seconds;
    // At most half a cell per step, so the obstacle pushes the liquid instead of jumping through it.
    const float cap = 0.5f * simulation_of(node).setup().cell_size / dt;
    if (glm::length(velocity) > cap) velocity *= cap / glm::length(velocity);
    node.set_obstacle_pose(in.obstacle->index, center, velocity);
  }
  if (in.released_obstacle && dynamic(*in.released_obstacle))
    node.set_body_force(*in.released_obstacle, glm::vec3(0.0f));
  else if (in.released_obstacle && *in.released_obstacle < poses.size())
    node.set_obstacle_pose(*in.released_obstacle, poses[*in.released_obstacle].center, glm::vec3(0.0f));
}

void Viewer::read_timings(FrameSlot& slot) {
  if (!slot.submitted) return;
  std::map<std::string, double> by_name;
  std::vector<std::string> order;
  for (const auto& t : slot.graph.read_timings()) {
    if (!by_name.count(t.name)) order.push_back(t.name);
    by_name[t.name] += t.milliseconds;
  }
  stats_.passes.clear();
  for (const auto& name : order) stats_.passes.push_back({name, by_name[name]});
}

bool Viewer::draw_frame(FrameSlot& slot, int steps, double) {
  const VkDevice device = context_->device();
  uint32_t index = 0;
  const VkResult acquired =
      vkAcquireNextImageKHR(device, swapchain_->handle(), UINT64_MAX, slot.acquired, VK_NULL_HANDLE, &index);
  if (acquired == VK_ERROR_OUT_OF_DATE_KHR) {
    if (imgui_frame_) imgui_->skip();
    return false;
  }
  if (acquired != VK_SUCCESS && acquired != VK_SUBOPTIMAL_KHR) VK_CHECK(acquired);
  if (acquired == VK_SUBOPTIMAL_KHR) recreate_ = true;  // after this frame

  apply_mouse(steps);
  stats_.steps_this_frame = steps;
  stats_.width = swapchain_->extent().width;
  stats_.height = swapchain_->extent().height;

  VkCommandBuffer cmd = slot.begin();
  engine::vk::Image& target = swapchain_->image(index);
  // Just acquired: contents undefined; the graph's first barrier waits on the acquire semaphore's
  // stage (the submission waits for it at ALL_COMMANDS).
  target.sync_state() =
      engine::vk::ImageSyncState::after_read(VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, 0);
  engine::graph::RenderGraph& graph = slot.graph;
  graph.reset();
  const engine::graph::ImageHandle swap = graph.import_image(target.name(), target);
  liquid::LiquidImages images = session_->node().add_to(graph, steps);
  // The node's grids are filled by its steps: a node that has not stepped yet (a reset, reload or
  // scene opened while paused) would show an empty tank, so its state is splatted without a step.
  if (steps == 0 && session_->node().step_count() == 0) images = session_->node().add_grids_to(graph, images);
  const liquid::RenderOutputs out = session_->renderer().add_to(graph, images, session_->camera_view());
  present_->add_to(graph, out.final, swap);  // RGBA8 -> the swapchain's format (BGRA8 on lavapipe)
  graph.compile();
  graph.execute(cmd);
  slot.submitted = true;

  // After the graph: the image is where its sync state says (the present pass's colour attachment).
  if (imgui_frame_) {
    transition(cmd, target, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
               VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, true);
    imgui_->record(cmd, index);
    target.sync_state() = engine::vk::ImageSyncState::after_write(VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                                                  VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                                                                  VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
  }
  const bool last = options_.frames > 0 && frame_ + 1 >= options_.frames;
  const std::filesystem::path path =
      shot_requested_ ? next_screenshot_path() : last ? options_.screenshot : std::filesystem::path();
  shot_requested_ = false;
  if (!path.empty()) {
    transition(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
               VK_ACCESS_2_TRANSFER_READ_BIT, false);
    slot.shot = copy_to_buffer(*context_, cmd, target, swapchain_->bgra(), path);
    stats_.status = "screenshot: " + path.string();
  }
  transition(cmd, target, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_PIPELINE_STAGE_2_NONE, 0, false);
  VK_CHECK(vkEndCommandBuffer(cmd));

  const VkSemaphore rendered = swapchain_->rendered(index);
  const VkPipelineStageFlags wait_stage = VK_PIPELINE_STAGE_ALL_COMMANDS_BIT;
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.waitSemaphoreCount = 1;
  submit.pWaitSemaphores = &slot.acquired;
  submit.pWaitDstStageMask = &wait_stage;
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  submit.signalSemaphoreCount = 1;
  submit.pSignalSemaphores = &rendered;
  VK_CHECK(vkQueueSubmit(context_->queue(), 1, &submit, slot.fence));

  VkPresentInfoKHR present{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  present.waitSemaphoreCount = 1;
  present.pWaitSemaphores = &rendered;
  const VkSwapchainKHR handle = swapchain_->handle();
  present.swapchainCount = 1;
  present.pSwapchains = &handle;
  present.pImageIndices = &index;
  const VkResult presented = vkQueuePresentKHR(context_->queue(), &present);
  if (presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR) recreate_ = true;
  else VK_CHECK(presented);
  return true;
}

}  // namespace viewer
