// Render graph tests with no GPU: the declared order, the barrier plan for each hazard, layout
// transitions, and every misuse error.
#include "engine/graph/render_graph.h"

#include <catch2/catch.hpp>

using namespace engine::graph;
using engine::vk::ImageDesc;
using engine::vk::ImageKind;
using engine::vk::ImageSyncState;

namespace {

ImageDesc color_desc(uint32_t w = 64, uint32_t h = 64) {
  return ImageDesc{ImageKind::Image2D, w, h, 1, VK_FORMAT_R8G8B8A8_UNORM, 0};
}

void no_record(PassContext&) {}

const BarrierPlan* find_barrier(const Plan& plan, const std::string& pass, const std::string& image) {
  for (const auto& p : plan.passes)
    if (p.name == pass)
      for (const auto& b : p.barriers)
        if (b.resource_name == image) return &b;
  return nullptr;
}

}  // namespace

TEST_CASE("graph keeps the declared pass order", "[graph]") {
  RenderGraph graph;
  ImageHandle a = graph.create_image("a", color_desc());
  for (const char* name : {"first", "second", "third"})
    graph.add_pass(name, [&](PassBuilder& b) { a = b.write(a, Access::ColorAttachmentWrite); }, no_record);
  const Plan& plan = graph.compile();
  REQUIRE(plan.passes.size() == 3);
  CHECK(plan.passes[0].name == "first");
  CHECK(plan.passes[1].name == "second");
  CHECK(plan.passes[2].name == "third");
  CHECK(plan.passes[0].width == 64);
  CHECK(plan.passes[0].layers == 1);
}

TEST_CASE("read after write: colour output made visible to the fragment shader", "[graph]") {
  RenderGraph graph;
  ImageHandle target = graph.create_image("target", color_desc());
  graph.add_pass("draw", [&](PassBuilder& b) { target = b.write(target, Access::ColorAttachmentWrite); }, no_record);
  ImageHandle out = graph.create_image("out", color_desc());
  graph.add_pass("post", [&](PassBuilder& b) {
    b.read(target, Access::FragmentSampled);
    out = b.write(out, Access::ColorAttachmentWrite);
  }, no_record);
  const Plan& plan = graph.compile();
  const BarrierPlan* b = find_barrier(plan, "post", "target");
  REQUIRE(b);
  CHECK(b->src_stages == VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT);
  CHECK(b->src_access == VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
  CHECK(b->dst_stages == VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
  CHECK(b->dst_access == VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
  CHECK(b->old_layout == VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
  CHECK(b->new_layout == VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  // The first write of a transient discards: UNDEFINED -> COLOR_ATTACHMENT_OPTIMAL, nothing to wait on.
  const BarrierPlan* first = find_barrier(plan, "draw", "target");
  REQUIRE(first);
  CHECK(first->old_layout == VK_IMAGE_LAYOUT_UNDEFINED);
  CHECK(first->new_layout == VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
  CHECK(first->src_stages == 0);
}

TEST_CASE("write after read waits for the readers' stages", "[graph]") {
  RenderGraph graph;
  ImageSyncState written{VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                         VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, 0, 0, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT};
  ImageHandle state = graph.import_image("state", color_desc(), written);
  ImageHandle out = graph.create_image("out", color_desc());
  graph.add_pass("reader", [&](PassBuilder& b) {
    b.read(state, Access::VertexSampled);
    out = b.write(out, Access::ColorAttachmentWrite);
  }, no_record);
  graph.add_pass("writer", [&](PassBuilder& b) { state = b.write(state, Access::ColorAttachmentWrite); }, no_record);
  const Plan& plan = graph.compile();
  const BarrierPlan* b = find_barrier(plan, "writer", "state");
  REQUIRE(b);
  CHECK((b->src_stages & VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT) != 0);
  CHECK(b->dst_stages == VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT);
  CHECK(b->old_layout == VK_IMAGE_LAYOUT_UNDEFINED);  // overwritten: old contents discarded
  CHECK(b->new_layout == VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
}

TEST_CASE("write after write with blending keeps the contents and orders the writes", "[graph]") {
  RenderGraph graph;
  ImageHandle grid = graph.create_image("grid", color_desc());
  graph.add_pass("clear", [&](PassBuilder& b) {
    grid = b.write(grid, Access::ColorAttachmentWrite, clear_to(0, 0, 0, 0));
  }, no_record);
  graph.add_pass("accumulate", [&](PassBuilder& b) { grid = b.write(grid, Access::ColorAttachmentBlend); }, no_record);
  const Plan& plan = graph.compile();
  const BarrierPlan* b = find_barrier(plan, "accumulate", "grid");
  REQUIRE(b);
  CHECK(b->src_stages == VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT);
  CHECK(b->src_access == VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
  CHECK((b->dst_access & VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT) != 0);
  CHECK(b->old_layout == VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);  // blended: contents kept
  CHECK(plan.passes[0].colors.at(0).load == LoadOp::Clear);
}

TEST_CASE("a second read in the same layout and stage needs no barrier", "[graph]") {
  RenderGraph graph;
  ImageHandle src = graph.create_image("src", color_desc());
  graph.add_pass("make", [&](PassBuilder& b) { src = b.write(src, Access::ColorAttachmentWrite); }, no_record);
  for (const char* name : {"read1", "read2"}) {
    ImageHandle out = graph.create_image(std::string(name) + ".out", color_desc());
    graph.add_pass(name, [&](PassBuilder& b) {
      b.read(src, Access::FragmentSampled);
      b.write(out, Access::ColorAttachmentWrite);
    }, no_record);
  }
  const Plan& plan = graph.compile();
  CHECK(find_barrier(plan, "read1", "src") != nullptr);
  CHECK(find_barrier(plan, "read2", "src") == nullptr);
}

TEST_CASE("a read in a new stage after a read gets its own visibility barrier", "[graph]") {
  RenderGraph graph;
  ImageHandle src = graph.create_image("src", color_desc());
  graph.add_pass("make", [&](PassBuilder& b) { src = b.write(src, Access::ColorAttachmentWrite); }, no_record);
  ImageHandle o1 = graph.create_image("o1", color_desc()), o2 = graph.create_image("o2", color_desc());
  graph.add_pass("fragment_read", [&](PassBuilder& b) {
    b.read(src, Access::FragmentSampled);
    b.write(o1, Access::ColorAttachmentWrite);
  }, no_record);
  graph.add_pass("vertex_read", [&](PassBuilder& b) {
    b.read(src, Access::VertexSampled);
    b.write(o2, Access::ColorAttachmentWrite);
  }, no_record);
  const BarrierPlan* b = find_barrier(graph.compile(), "vertex_read", "src");
  REQUIRE(b);
  CHECK(b->dst_stages == VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT);
  CHECK(b->old_layout == b->new_layout);
}

TEST_CASE("transfer source after sampling transitions the layout and waits for the samplers", "[graph]") {
  RenderGraph graph;
  ImageSyncState sampled{VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, 0, 0, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                         VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, 0};
  ImageHandle img = graph.import_image("img", color_desc(), sampled);
  graph.add_pass("copy", [&](PassBuilder& b) { b.read(img, Access::TransferSource); }, no_record);
  const BarrierPlan* b = find_barrier(graph.compile(), "copy", "img");
  REQUIRE(b);
  CHECK(b->old_layout == VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  CHECK(b->new_layout == VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
  CHECK(b->src_stages == VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
  CHECK(b->dst_stages == VK_PIPELINE_STAGE_2_COPY_BIT);
}

TEST_CASE("a depth attachment with a stencil takes the combined layout, so the stencil is kept", "[graph]") {
  for (const auto& [format, layout] :
       {std::pair{VK_FORMAT_D32_SFLOAT, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL},
        std::pair{VK_FORMAT_D24_UNORM_S8_UINT, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL},
        std::pair{VK_FORMAT_D32_SFLOAT_S8_UINT, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL}}) {
    INFO("format " << int(format));
    RenderGraph graph;
    const ImageSyncState host_wrote = ImageSyncState::after_write(
        VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
    ImageHandle depth = graph.import_image("depth", ImageDesc{ImageKind::Image2D, 64, 64, 1, format, 0}, host_wrote);
    graph.add_pass("test", [&](PassBuilder& b) { depth = b.write(depth, Access::DepthAttachmentWrite, {LoadOp::Load, {}}); },
                   no_record);
    const BarrierPlan* b = find_barrier(graph.compile(), "test", "depth");
    REQUIRE(b);
    CHECK(b->old_layout == VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);  // loaded: contents kept
    CHECK(b->new_layout == layout);
    CHECK(access_layout(Access::DepthAttachmentWrite, format) == layout);
  }
}

TEST_CASE("attachments of different sample counts in one pass are refused", "[graph]") {
  RenderGraph graph;
  ImageDesc multisampled = color_desc();
  multisampled.samples = VK_SAMPLE_COUNT_4_BIT;
  ImageHandle single = graph.create_image("single", color_desc());
  ImageHandle msaa = graph.create_image("msaa", multisampled);
  graph.add_pass("mixed", [&](PassBuilder& b) {
    single = b.write(single, Access::ColorAttachmentWrite);
    msaa = b.write(msaa, Access::ColorAttachmentWrite);
  }, no_record);
  CHECK_THROWS_WITH(graph.compile(), Catch::Contains("mixed") && Catch::Contains("msaa") && Catch::Contains("sample count"));
}

TEST_CASE("3D images render into all their slices as layers", "[graph]") {
  RenderGraph graph;
  ImageHandle volume = graph.create_image("volume", ImageDesc{ImageKind::Image3D, 16, 8, 12, VK_FORMAT_R32G32B32A32_SFLOAT, 0});
  graph.add_pass("fill", [&](PassBuilder& b) { volume = b.write(volume, Access::ColorAttachmentWrite); }, no_record);
  const Plan& plan = graph.compile();
  CHECK(plan.passes[0].width == 16);
  CHECK(plan.passes[0].height == 8);
  CHECK(plan.passes[0].layers == 12);
}

TEST_CASE("the plan dumps as text", "[graph]") {
  RenderGraph graph;
  ImageHandle a = graph.create_image("scene", color_desc());
  graph.add_pass("draw", [&](PassBuilder& b) { a = b.write(a, Access::ColorAttachmentWrite, clear_to(0, 0, 0, 1)); }, no_record);
  ImageHandle out = graph.create_image("final", color_desc());
  graph.add_pass("post", [&](PassBuilder& b) {
    b.read(a, Access::FragmentSampled);
    b.write(out, Access::ColorAttachmentWrite);
  }, no_record);
  const std::string text = graph.compile().dump();
  CHECK_THAT(text, Catch::Contains("pass 0 'draw' render 64x64x1"));
  CHECK_THAT(text, Catch::Contains("barrier 'scene' COLOR_ATTACHMENT_OPTIMAL -> SHADER_READ_ONLY_OPTIMAL"));
  CHECK_THAT(text, Catch::Contains("src COLOR_ATTACHMENT_OUTPUT / COLOR_ATTACHMENT_WRITE dst FRAGMENT_SHADER / SHADER_SAMPLED_READ"));
}

TEST_CASE("misuse is rejected with the pass and the image named", "[graph]") {
  RenderGraph graph;
  ImageHandle fresh = graph.create_image("fresh", color_desc());
  ImageHandle out = graph.create_image("out", color_desc());

  SECTION("reading an image nothing wrote") {
    REQUIRE_THROWS_WITH(graph.add_pass("p", [&](PassBuilder& b) { b.read(fresh, Access::FragmentSampled); }, no_record),
                        Catch::Contains("pass 'p'") && Catch::Contains("'fresh'") && Catch::Contains("before any pass wrote it"));
  }
  SECTION("reading a stale version") {
    ImageHandle v1;
    graph.add_pass("w1", [&](PassBuilder& b) { v1 = b.write(fresh, Access::ColorAttachmentWrite); }, no_record);
    graph.add_pass("w2", [&](PassBuilder& b) { b.write(v1, Access::ColorAttachmentWrite); }, no_record);
    REQUIRE_THROWS_WITH(graph.add_pass("late", [&](PassBuilder& b) { b.read(v1, Access::FragmentSampled); }, no_record),
                        Catch::Contains("pass 'late'") && Catch::Contains("stale handle") && Catch::Contains("'w2'"));
  }
  SECTION("two writers of the same version") {
    graph.add_pass("w1", [&](PassBuilder& b) { b.write(fresh, Access::ColorAttachmentWrite); }, no_record);
    REQUIRE_THROWS_WITH(graph.add_pass("w2", [&](PassBuilder& b) { b.write(fresh, Access::ColorAttachmentWrite); }, no_record),
                        Catch::Contains("pass 'w2'") && Catch::Contains("two writers"));
  }
  SECTION("reading and writing one image in one pass") {
    ImageHandle v1;
    graph.add_pass("w", [&](PassBuilder& b) { v1 = b.write(fresh, Access::ColorAttachmentWrite); }, no_record);
    REQUIRE_THROWS_WITH(graph.add_pass("loop", [&](PassBuilder& b) {
      b.read(v1, Access::FragmentSampled);
      b.write(v1, Access::ColorAttachmentWrite);
    }, no_record), Catch::Contains("pass 'loop'") && Catch::Contains("used twice"));
  }
  SECTION("blending into an image never cleared") {
    REQUIRE_THROWS_WITH(graph.add_pass("blend", [&](PassBuilder& b) { b.write(fresh, Access::ColorAttachmentBlend); }, no_record),
                        Catch::Contains("pass 'blend'") && Catch::Contains("'fresh'"));
  }
  SECTION("attachments of different sizes") {
    ImageHandle small = graph.create_image("small", color_desc(32, 32));
    graph.add_pass("mixed", [&](PassBuilder& b) {
      b.write(fresh, Access::ColorAttachmentWrite);
      b.write(small, Access::ColorAttachmentWrite);
    }, no_record);
    REQUIRE_THROWS_WITH(graph.compile(), Catch::Contains("pass 'mixed'") && Catch::Contains("'small'") &&
                                             Catch::Contains("extent"));
  }
  SECTION("an unknown handle") {
    REQUIRE_THROWS_AS(graph.add_pass("p", [&](PassBuilder& b) { b.read(ImageHandle{}, Access::FragmentSampled); }, no_record),
                      std::logic_error);
  }
  SECTION("a write access passed to read()") {
    REQUIRE_THROWS_AS(graph.add_pass("p", [&](PassBuilder& b) { b.read(out, Access::ColorAttachmentWrite); }, no_record),
                      std::logic_error);
  }
  SECTION("execute without a device") {
    graph.compile();
    REQUIRE_THROWS_WITH(graph.execute(VK_NULL_HANDLE), Catch::Contains("needs a Vulkan context"));
  }
}

TEST_CASE("reset forgets passes so the next frame can be declared", "[graph]") {
  RenderGraph graph;
  ImageHandle a = graph.create_image("a", color_desc());
  graph.add_pass("p", [&](PassBuilder& b) { b.write(a, Access::ColorAttachmentWrite); }, no_record);
  graph.compile();
  REQUIRE_THROWS_AS(graph.compile(), std::logic_error);
  graph.reset();
  ImageHandle b2 = graph.create_image("a", color_desc());
  graph.add_pass("p", [&](PassBuilder& b) { b.write(b2, Access::ColorAttachmentWrite); }, no_record);
  CHECK(graph.compile().passes.size() == 1);
}
