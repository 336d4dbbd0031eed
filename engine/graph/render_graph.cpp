#include "engine/graph/render_graph.h"

#include "engine/vk/context.h"
#include "engine/vk/vk_check.h"
#include "engine/vk/vk_helpers.h"

#include <algorithm>
#include <stdexcept>

namespace engine::graph {
namespace {

std::logic_error misuse(const std::string& pass, const std::string& image, const std::string& what) {
  return std::logic_error("render graph: pass '" + pass + "': image '" + image + "': " + what);
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Declaration

RenderGraph::RenderGraph(vk::Context* context) : context_(context) {}

RenderGraph::~RenderGraph() {
  if (context_ && query_pool_) vkDestroyQueryPool(context_->device(), query_pool_, nullptr);
}

ImageHandle RenderGraph::create_image(const std::string& name, const vk::ImageDesc& desc) {
  if (desc.width == 0 || desc.height == 0 || desc.depth_or_layers == 0)
    throw std::logic_error("render graph: image '" + name + "' has a zero extent");
  Resource r;
  r.name = name;
  r.desc = desc;
  r.usage = desc.usage;
  resources_.push_back(std::move(r));
  return {static_cast<uint32_t>(resources_.size() - 1), 0};
}

ImageHandle RenderGraph::import_image(const std::string& name, vk::Image& image) {
  // An image imported again in the same graph is the same resource, at its latest version: its
  // uses chain in declaration order, each barrier from the state the one before leaves. Two
  // resources would each start from the state before the graph, and the later one's barriers
  // would transition from a layout the image is no longer in.
  for (size_t i = 0; i < resources_.size(); ++i)
    if (resources_[i].image == &image) return {static_cast<uint32_t>(i), resources_[i].version};
  Resource r;
  r.name = name;
  r.desc = image.desc();
  r.imported = true;
  r.image = &image;
  r.initial = image.sync_state();
  // Version 1: an imported image holds valid contents, as if written before the graph.
  r.version = 1;
  resources_.push_back(std::move(r));
  return {static_cast<uint32_t>(resources_.size() - 1), 1};
}

ImageHandle RenderGraph::import_image(const std::string& name, const vk::ImageDesc& desc,
                                      const vk::ImageSyncState& state) {
  Resource r;
  r.name = name;
  r.desc = desc;
  r.imported = true;
  r.initial = state;
  r.version = 1;
  resources_.push_back(std::move(r));
  return {static_cast<uint32_t>(resources_.size() - 1), 1};
}

PassBuilder RenderGraph::begin_pass(const std::string& name) {
  if (compiled_) throw std::logic_error("render graph: pass '" + name + "' added after compile()");
  passes_.push_back(Pass{name, {}, {}});
  return PassBuilder(*this, static_cast<uint32_t>(passes_.size() - 1));
}

void RenderGraph::end_pass(std::function<void(PassContext&)> record) {
  passes_.back().record = std::move(record);
}

void RenderGraph::add_pass(const std::string& name, const std::function<void(PassBuilder&)>& setup,
                           std::function<void(PassContext&)> record) {
  PassBuilder builder = begin_pass(name);
  setup(builder);
  end_pass(std::move(record));
}

RenderGraph::Resource& RenderGraph::checked_resource(ImageHandle handle, const std::string& pass,
                                                     const char* verb) {
  if (!handle.valid() || handle.id >= resources_.size())
    throw std::logic_error("render graph: pass '" + pass + "' " + verb + " an unknown image handle");
  Resource& r = resources_[handle.id];
  if (handle.version != r.version) {
    const std::string writer =
        r.writer_pass < passes_.size() ? " (last written by pass '" + passes_[r.writer_pass].name + "')" : "";
    throw misuse(pass, r.name,
                 std::string(verb) + " a stale handle: version " + std::to_string(handle.version) +
                     " but the image is at version " + std::to_string(r.version) + writer +
                     (std::string(verb) == "writes" ? "; two writers of one version have no order" : ""));
  }
  return r;
}

ImageHandle PassBuilder::create(const std::string& name, const vk::ImageDesc& desc) {
  return graph_.create_image(name, desc);
}

void PassBuilder::read(ImageHandle image, Access access) {
  auto& pass = graph_.passes_[pass_];
  const AccessInfo& info = access_info(access);
  if (info.writes) throw misuse(pass.name, "?", std::string("read() with the write access ") + info.name);
  auto& r = graph_.checked_resource(image, pass.name, "reads");
  if (r.version == 0) throw misuse(pass.name, r.name, "read before any pass wrote it");
  for (auto& use : pass.uses)
    if (use.resource == image.id) {
      const AccessInfo& other = access_info(use.access);
      if (other.writes) throw misuse(pass.name, r.name, "read and written by the same pass");
      if (other.layout != info.layout)
        throw misuse(pass.name, r.name, "read in two layouts by the same pass");
      use.extra_stages |= info.stages;
      return;
    }
  r.usage |= info.usage;
  pass.uses.push_back({image.id, access, 0, {}});
}

ImageHandle PassBuilder::write(ImageHandle image, Access access, AttachmentOptions options) {
  auto& pass = graph_.passes_[pass_];
  const AccessInfo& info = access_info(access);
  if (!info.writes) throw misuse(pass.name, "?", std::string("write() with the read access ") + info.name);
  auto& r = graph_.checked_resource(image, pass.name, "writes");
  for (const auto& use : pass.uses)
    if (use.resource == image.id) throw misuse(pass.name, r.name, "used twice by the same pass");
  if (options.load == LoadOp::Load && r.version == 0)
    throw misuse(pass.name, r.name, "loaded before any pass wrote it");
  if (access == Access::ColorAttachmentBlend && options.load == LoadOp::DontCare && r.version == 0)
    throw misuse(pass.name, r.name, "blended into before it was written or cleared");
  if (access == Access::DepthAttachmentWrite && !vk::is_depth_format(r.desc.format))
    throw misuse(pass.name, r.name, "depth attachment with a colour format");
  r.usage |= info.usage;
  pass.uses.push_back({image.id, access, 0, options});
  r.version += 1;
  r.writer_pass = pass_;
  return {image.id, r.version};
}

// ---------------------------------------------------------------------------------------------
// Compile

const Plan& RenderGraph::compile() {
  if (compiled_) throw std::logic_error("render graph: compile() called twice without reset()");
  // Physical images for transients (needs a context; CPU tests plan without them).
  if (context_) allocate_transients();

  // Starting state of every image: its last access before this graph.
  std::vector<vk::ImageSyncState> state(resources_.size());
  for (size_t i = 0; i < resources_.size(); ++i)
    state[i] = resources_[i].image ? resources_[i].image->sync_state() : resources_[i].initial;

  plan_ = Plan{};
  for (const Pass& pass : passes_) {
    PassPlan pp;
    pp.name = pass.name;
    // Attachments first: all must share one extent, layer count and sample count.
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    for (const Use& use : pass.uses) {
      const AccessInfo& info = access_info(use.access);
      if (!info.attachment) continue;
      const Resource& r = resources_[use.resource];
      const uint32_t layers = r.desc.render_layers();
      if (pp.width == 0) {
        pp.width = r.desc.width;
        pp.height = r.desc.height;
        pp.layers = layers;
        samples = r.desc.samples;
      } else if (pp.width != r.desc.width || pp.height != r.desc.height || pp.layers != layers) {
        throw misuse(pass.name, r.name, "attachment extent differs from the pass's other attachments");
      } else if (r.desc.samples != samples) {
        throw misuse(pass.name, r.name, "attachment sample count differs from the pass's other attachments");
      }
      AttachmentPlan ap{use.resource, use.access, use.options.load, use.options.clear};
      if (use.access == Access::DepthAttachmentWrite) {
        if (pp.depth) throw misuse(pass.name, r.name, "second depth attachment");
        pp.depth = ap;
      } else {
        pp.colors.push_back(ap);
      }
    }
    // Barriers: from each image's last access to this use.
    for (const Use& use : pass.uses) {
      const AccessInfo& info = access_info(use.access);
      const VkPipelineStageFlags2 stages = info.stages | use.extra_stages;
      const VkImageLayout layout = access_layout(use.access, resources_[use.resource].desc.format);
      vk::ImageSyncState& s = state[use.resource];
      BarrierPlan b;
      b.resource = use.resource;
      b.resource_name = resources_[use.resource].name;
      b.dst_stages = stages;
      b.dst_access = info.access;
      b.new_layout = layout;
      if (info.writes) {
        // Write after write or after read: wait for both; the old contents survive only if loaded.
        const bool discard = use.options.load != LoadOp::Load && use.access != Access::ColorAttachmentBlend;
        b.src_stages = s.write_stages | s.read_stages;
        b.src_access = s.write_access;
        b.old_layout = discard ? VK_IMAGE_LAYOUT_UNDEFINED : s.layout;
        pp.barriers.push_back(b);
        s = vk::ImageSyncState{layout, stages, info.access, 0, 0, 0};
      } else {
        const bool transition = s.layout != layout;
        const bool needs_visibility = s.write_stages != 0 && (stages & ~s.visible_stages) != 0;
        if (!transition && !needs_visibility) {
          s.read_stages |= stages;
          s.read_access |= info.access;
          continue;
        }
        // A layout transition is itself a write: it must also wait for earlier readers.
        b.src_stages = s.write_stages | (transition ? s.read_stages : 0);
        b.src_access = s.write_access;
        b.old_layout = s.layout;
        pp.barriers.push_back(b);
        if (transition) {
          s = vk::ImageSyncState{layout, stages, 0, stages, info.access, stages};
        } else {
          s.read_stages |= stages;
          s.read_access |= info.access;
          s.visible_stages |= stages;
        }
      }
    }
    plan_.passes.push_back(std::move(pp));
  }
  final_states_ = std::move(state);
  compiled_ = true;
  return plan_;
}

void RenderGraph::allocate_transients() {
  for (auto& r : resources_) {
    if (r.imported) continue;
    vk::ImageDesc desc = r.desc;
    desc.usage = r.usage | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;  // every transient can be read back
    PooledImage* match = nullptr;
    for (auto& pooled : pool_)
      if (!pooled.in_use && pooled.image->desc() == desc && pooled.image->name() == r.name) {
        match = &pooled;
        break;
      }
    if (!match) {
      pool_.push_back({std::make_unique<vk::Image>(*context_, desc, r.name), false});
      match = &pool_.back();
    }
    match->in_use = true;
    r.image = match->image.get();
  }
}

// ---------------------------------------------------------------------------------------------
// Execute

void RenderGraph::ensure_query_pool(uint32_t count) {
  if (count <= query_capacity_) return;
  if (query_pool_) vkDestroyQueryPool(context_->device(), query_pool_, nullptr);
  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = VK_QUERY_TYPE_TIMESTAMP;
  info.queryCount = std::max(count, 64u);
  VK_CHECK(vkCreateQueryPool(context_->device(), &info, nullptr, &query_pool_));
  query_capacity_ = info.queryCount;
  timing_results_ = vk::Buffer(*context_, VkDeviceSize(query_capacity_) * 2 * sizeof(uint64_t),
                               VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryUsage::HostVisible, "graph.timings");
}

// After the last pass: the timestamps and their availability into timing_results_, made visible
// to the host. Availability is cleared first, so a read before the submission completed shows.
void RenderGraph::copy_out_timings(VkCommandBuffer cmd, uint32_t queries) {
  if (queries == 0) return;
  auto* words = static_cast<uint64_t*>(timing_results_.mapped());
  std::fill(words, words + size_t(queries) * 2, uint64_t(0));
  timing_results_.flush();
  vkCmdCopyQueryPoolResults(cmd, query_pool_, 0, queries, timing_results_.handle(), 0, 2 * sizeof(uint64_t),
                            VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WITH_AVAILABILITY_BIT | VK_QUERY_RESULT_WAIT_BIT);
  vk::cmd_copy_to_host_barrier(cmd, timing_results_.handle());
}

void RenderGraph::execute(VkCommandBuffer cmd) {
  if (!context_) throw std::logic_error("render graph: execute() needs a Vulkan context");
  if (!compiled_) throw std::logic_error("render graph: execute() before compile()");
  if (executed_) throw std::logic_error("render graph: execute() twice for one compile()");
  executed_ = true;

  // Timestamps: a pair per pass, reset in the command buffer before the first pass.
  ensure_query_pool(static_cast<uint32_t>(passes_.size() * 2));
  if (!passes_.empty()) vkCmdResetQueryPool(cmd, query_pool_, 0, static_cast<uint32_t>(passes_.size() * 2));
  timed_passes_.clear();

  for (size_t p = 0; p < passes_.size(); ++p) {
    const Pass& pass = passes_[p];
    const PassPlan& pp = plan_.passes[p];
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT, query_pool_, static_cast<uint32_t>(2 * p));
    timed_passes_.push_back(pass.name);

    // Barriers planned by compile(), in one vkCmdPipelineBarrier2.
    std::vector<VkImageMemoryBarrier2> barriers;
    if (pass.name != dropped_pass_)
      for (const BarrierPlan& b : pp.barriers)
        barriers.push_back(vk::image_barrier(*resources_[b.resource].image, b.src_stages, b.src_access, b.old_layout,
                                             b.dst_stages, b.dst_access, b.new_layout));
    if (!barriers.empty()) vk::cmd_image_barriers(cmd, barriers);

    // Dynamic rendering on the declared attachments (layered for 3D images and arrays).
    const bool renders = !pp.colors.empty() || pp.depth.has_value();
    if (renders) {
      auto attachment_info = [&](const AttachmentPlan& a) {
        VkRenderingAttachmentInfo info{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        info.imageView = resources_[a.resource].image->attachment_view();
        info.imageLayout = access_layout(a.access, resources_[a.resource].desc.format);
        info.loadOp = a.load == LoadOp::Clear  ? VK_ATTACHMENT_LOAD_OP_CLEAR
                      : a.load == LoadOp::Load || a.access == Access::ColorAttachmentBlend
                          ? VK_ATTACHMENT_LOAD_OP_LOAD
                          : VK_ATTACHMENT_LOAD_OP_DONT_CARE;
        info.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        info.clearValue = a.clear;
        return info;
      };
      std::vector<VkRenderingAttachmentInfo> colors;
      for (const auto& a : pp.colors) colors.push_back(attachment_info(a));
      VkRenderingAttachmentInfo depth{};
      VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
      rendering.renderArea = {{0, 0}, {pp.width, pp.height}};
      rendering.layerCount = pp.layers;
      rendering.colorAttachmentCount = static_cast<uint32_t>(colors.size());
      rendering.pColorAttachments = colors.data();
      if (pp.depth) {
        depth = attachment_info(*pp.depth);
        rendering.pDepthAttachment = &depth;
      }
      vkCmdBeginRendering(cmd, &rendering);
    }
    PassContext ctx{cmd, context_, this, pp.width, pp.height, pp.layers};
    if (pass.record) pass.record(ctx);
    if (renders) vkCmdEndRendering(cmd);
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT, query_pool_,
                         static_cast<uint32_t>(2 * p + 1));
  }

  copy_out_timings(cmd, static_cast<uint32_t>(passes_.size() * 2));

  // Persistent images remember where this graph left them, for the next graph's barriers.
  for (size_t i = 0; i < resources_.size(); ++i)
    if (resources_[i].image) resources_[i].image->sync_state() = final_states_[i];
}

void RenderGraph::reset() {
  passes_.clear();
  resources_.clear();
  plan_ = Plan{};
  final_states_.clear();
  compiled_ = executed_ = false;
  for (auto& pooled : pool_) pooled.in_use = false;
}

std::vector<PassTiming> RenderGraph::read_timings() const {
  std::vector<PassTiming> timings;
  if (!context_ || timed_passes_.empty()) return timings;
  // The frame's own copy (copy_out_timings): reading it waits for nothing, so a frame slot reads
  // its timings while other frames are in flight. Before the submission completed the copy has not
  // run: a misuse, said so.
  timing_results_.invalidate();
  const auto* words = static_cast<const uint64_t*>(timing_results_.mapped());
  std::vector<uint64_t> stamps(timed_passes_.size() * 2);
  for (size_t q = 0; q < stamps.size(); ++q) {
    if (words[2 * q + 1] == 0)
      throw std::logic_error("render graph: read_timings() before the frame's submission completed (wait for its fence)");
    stamps[q] = words[2 * q];
  }
  const double period_ns = context_->limits().timestampPeriod;
  for (size_t p = 0; p < timed_passes_.size(); ++p)
    timings.push_back({timed_passes_[p], double(stamps[2 * p + 1] - stamps[2 * p]) * period_ns * 1e-6});
  return timings;
}

// ---------------------------------------------------------------------------------------------
// Lookups

const std::string& RenderGraph::image_name(ImageHandle handle) const { return resources_.at(handle.id).name; }

const vk::ImageDesc& RenderGraph::image_desc(ImageHandle handle) const { return resources_.at(handle.id).desc; }

vk::Image& RenderGraph::image(ImageHandle handle) {
  Resource& r = resources_.at(handle.id);
  if (!r.image) throw std::logic_error("render graph: image '" + r.name + "' has no Vulkan image yet");
  return *r.image;
}

ImageHandle RenderGraph::latest(ImageHandle handle) const {
  return {handle.id, resources_.at(handle.id).version};
}

vk::Image& PassContext::image(ImageHandle handle) const { return graph->image(handle); }

// ---------------------------------------------------------------------------------------------
// Text form

std::string Plan::dump() const {
  std::string out;
  for (size_t p = 0; p < passes.size(); ++p) {
    const PassPlan& pp = passes[p];
    out += "pass " + std::to_string(p) + " '" + pp.name + "'";
    if (pp.width)
      out += " render " + std::to_string(pp.width) + "x" + std::to_string(pp.height) + "x" +
             std::to_string(pp.layers);
    out += "\n";
    for (const auto& b : pp.barriers)
      out += "  barrier '" + b.resource_name + "' " + layout_name(b.old_layout) + " -> " +
             layout_name(b.new_layout) + " src " + stage_names(b.src_stages) + " / " +
             access_names(b.src_access) + " dst " + stage_names(b.dst_stages) + " / " +
             access_names(b.dst_access) + "\n";
    for (const auto& a : pp.colors)
      out += "  color #" + std::to_string(a.resource) + " " + access_info(a.access).name +
             (a.load == LoadOp::Clear ? " clear" : a.load == LoadOp::Load ? " load" : "") + "\n";
    if (pp.depth) out += "  depth #" + std::to_string(pp.depth->resource) + "\n";
  }
  return out;
}

}  // namespace engine::graph
