// A small render graph (after Filament's FrameGraph and kajiya): passes declare what they read and
// write with one Access value per use; compile() keeps the declared order and derives every barrier
// and layout transition from each resource's last access; execute() records it with dynamic
// rendering and a GPU timestamp pair per pass. The graph knows nothing of FXAA or liquids.
#pragma once

#include "engine/graph/access.h"
#include "engine/graph/plan.h"
#include "engine/vk/buffer.h"
#include "engine/vk/image.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace engine::vk {
class Context;
}

namespace engine::graph {

// A versioned reference to a graph image: every write returns a new version, so a pass that reads
// or writes an older one (a stale handle) is rejected when it is declared.
struct ImageHandle {
  uint32_t id = UINT32_MAX;
  uint32_t version = 0;
  bool valid() const { return id != UINT32_MAX; }
  bool operator==(const ImageHandle&) const = default;
};

struct AttachmentOptions {
  LoadOp load = LoadOp::DontCare;
  VkClearValue clear{};
};

inline AttachmentOptions clear_to(float r, float g, float b, float a) {
  AttachmentOptions options{LoadOp::Clear, {}};
  options.clear.color = {{r, g, b, a}};
  return options;
}
inline AttachmentOptions clear_depth(float depth) {
  AttachmentOptions options{LoadOp::Clear, {}};
  options.clear.depthStencil = {depth, 0};
  return options;
}

class RenderGraph;

// Handed to a pass's setup function to declare its uses.
class PassBuilder {
 public:
  // A transient image owned by the graph (usage derived from its accesses).
  ImageHandle create(const std::string& name, const vk::ImageDesc& desc);
  // A read of the current version; a second read of the same image in the same pass adds stages.
  void read(ImageHandle image, Access access);
  // A write (attachment or transfer destination) of the current version; returns the new version.
  ImageHandle write(ImageHandle image, Access access, AttachmentOptions options = {});

 private:
  friend class RenderGraph;
  PassBuilder(RenderGraph& graph, uint32_t pass) : graph_(graph), pass_(pass) {}
  RenderGraph& graph_;
  uint32_t pass_;
};

// Handed to a pass's record function.
struct PassContext {
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  vk::Context* context = nullptr;
  RenderGraph* graph = nullptr;
  uint32_t width = 0, height = 0, layers = 0;  // render area of the pass's attachments
  vk::Image& image(ImageHandle handle) const;
};

struct PassTiming {
  std::string name;
  double milliseconds = 0.0;
};

class RenderGraph {
 public:
  // With no context the graph can declare and compile (CPU tests) but not execute.
  explicit RenderGraph(vk::Context* context = nullptr);
  ~RenderGraph();
  RenderGraph(const RenderGraph&) = delete;
  RenderGraph& operator=(const RenderGraph&) = delete;

  // A transient image: contents undefined until a pass writes it; reused across reset().
  ImageHandle create_image(const std::string& name, const vk::ImageDesc& desc);
  // A persistent image owned elsewhere (simulation state, a host's target). Its contents are valid
  // and its last access is taken from image.sync_state(); execute() updates that state. Imported
  // again in the same graph it is the same resource, at its latest version.
  ImageHandle import_image(const std::string& name, vk::Image& image);
  // CPU-only import for tests: a description and a starting state, no Vulkan object.
  ImageHandle import_image(const std::string& name, const vk::ImageDesc& desc,
                           const vk::ImageSyncState& state);

  // Declares a pass: `setup(builder, data)` runs now and declares the uses; `record(ctx, data)`
  // runs in execute(). Returns the data the setup filled (typically the output handles).
  template <class Data, class Setup, class Record>
  const Data& add_pass(const std::string& name, Setup&& setup, Record&& record) {
    auto data = std::make_shared<Data>();
    PassBuilder builder = begin_pass(name);
    setup(builder, *data);
    end_pass([data, record = std::forward<Record>(record)](PassContext& ctx) { record(ctx, *data); });
    return *data;
  }
  // The same without a data block.
  void add_pass(const std::string& name, const std::function<void(PassBuilder&)>& setup,
                std::function<void(PassContext&)> record);

  // Validates attachments and computes the barrier plan; allocates transient images when the
  // graph has a context. Misuse throws std::logic_error naming the pass and the image.
  const Plan& compile();
  // Records the compiled plan into `cmd` (which must be recording); once per compile().
  void execute(VkCommandBuffer cmd);
  // Forgets passes and handles for the next frame; keeps transient images for reuse.
  void reset();

  // GPU time of each pass of the last execute(); call after its submission has completed (its
  // fence waited on; before that it throws std::logic_error). It waits for nothing, so a frame slot
  // reads its own timings while other frames are in flight.
  std::vector<PassTiming> read_timings() const;

  const Plan& plan() const { return plan_; }
  vk::Context* context() const { return context_; }
  const std::string& image_name(ImageHandle handle) const;
  const vk::ImageDesc& image_desc(ImageHandle handle) const;
  vk::Image& image(ImageHandle handle);
  // Current (latest) version of an image, e.g. to hand a result to the next frame's code.
  ImageHandle latest(ImageHandle handle) const;

  // Tests only: execute() skips the barriers planned for this pass, to prove that a missing
  // barrier is caught by synchronization validation.
  void debug_drop_barriers_of(const std::string& pass_name) { dropped_pass_ = pass_name; }

 private:
  friend class PassBuilder;
  struct Use {
    uint32_t resource;
    Access access;
    VkPipelineStageFlags2 extra_stages = 0;  // other shader stages reading it in the same pass
    AttachmentOptions options;
  };
  struct Pass {
    std::string name;
    std::vector<Use> uses;
    std::function<void(PassContext&)> record;
  };
  struct Resource {
    std::string name;
    vk::ImageDesc desc;
    bool imported = false;
    uint32_t version = 0;
    uint32_t writer_pass = UINT32_MAX;  // last pass that wrote it, for messages
    VkImageUsageFlags usage = 0;        // union of every access (transient allocation)
    vk::Image* image = nullptr;         // imported image, or the transient one after compile()
    vk::ImageSyncState initial;         // state before this graph runs
  };

  PassBuilder begin_pass(const std::string& name);
  void end_pass(std::function<void(PassContext&)> record);
  Resource& checked_resource(ImageHandle handle, const std::string& pass, const char* verb);
  void allocate_transients();
  void ensure_query_pool(uint32_t count);

  vk::Context* context_ = nullptr;
  std::vector<Pass> passes_;
  std::vector<Resource> resources_;
  Plan plan_;
  std::vector<vk::ImageSyncState> final_states_;
  bool compiled_ = false;
  bool executed_ = false;
  std::string dropped_pass_;

  struct PooledImage {
    std::unique_ptr<vk::Image> image;
    bool in_use = false;
  };
  std::vector<PooledImage> pool_;
  void copy_out_timings(VkCommandBuffer cmd, uint32_t queries);
  VkQueryPool query_pool_ = VK_NULL_HANDLE;
  uint32_t query_capacity_ = 0;
  // The timestamps copied out by the frame's own command buffer (value, availability per query),
  // so read_timings() reads memory instead of asking the driver, which on lavapipe waits for the
  // whole queue.
  vk::Buffer timing_results_;
  std::vector<std::string> timed_passes_;
};

}  // namespace engine::graph
