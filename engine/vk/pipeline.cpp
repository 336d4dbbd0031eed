#include "engine/vk/pipeline.h"

#include "engine/vk/context.h"
#include "engine/vk/vk_check.h"

#include <stdexcept>

namespace engine::vk {
namespace {

UniqueHandle<VkShaderModule> create_module(VkDevice device, std::span<const uint32_t> code) {
  VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  info.codeSize = code.size_bytes();
  info.pCode = code.data();
  VkShaderModule module = VK_NULL_HANDLE;
  VK_CHECK(vkCreateShaderModule(device, &info, nullptr, &module));
  return {device, module, vkDestroyShaderModule};
}

VkPipelineColorBlendAttachmentState blend_state(BlendMode mode) {
  VkPipelineColorBlendAttachmentState state{};
  state.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                         VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  if (mode == BlendMode::None) return state;
  state.blendEnable = VK_TRUE;
  state.colorBlendOp = state.alphaBlendOp = VK_BLEND_OP_ADD;
  if (mode == BlendMode::Min) {
    state.colorBlendOp = state.alphaBlendOp = VK_BLEND_OP_MIN;  // the factors are ignored by MIN
    state.srcColorBlendFactor = state.dstColorBlendFactor = VK_BLEND_FACTOR_ONE;
    state.srcAlphaBlendFactor = state.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
  } else if (mode == BlendMode::Additive) {
    state.srcColorBlendFactor = state.dstColorBlendFactor = VK_BLEND_FACTOR_ONE;
    state.srcAlphaBlendFactor = state.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
  } else if (mode == BlendMode::Transmit) {
    state.srcColorBlendFactor = VK_BLEND_FACTOR_ONE;
    state.dstColorBlendFactor = VK_BLEND_FACTOR_SRC1_COLOR;
    state.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
    state.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
  } else {
    state.srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
    state.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    state.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
    state.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
  }
  return state;
}

// A write of one descriptor of `type` at `binding`; the caller points it at the image or buffer.
VkWriteDescriptorSet descriptor_write(uint32_t binding, VkDescriptorType type) {
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.dstBinding = binding;
  write.descriptorCount = 1;
  write.descriptorType = type;
  return write;
}

}  // namespace

GraphicsPipeline::GraphicsPipeline(Context& context, const GraphicsPipelineDesc& desc)
    : context_(&context), push_constant_size_(desc.push_constant_size), name_(desc.name), bindings_(desc.bindings) {
  if (desc.push_constant_size > 128)
    throw std::invalid_argument(desc.name + ": push constants above 128 bytes are not portable");
  for (BlendMode mode : desc.blend)
    if (mode == BlendMode::Transmit && !context.supports_dual_source_blend())
      throw std::invalid_argument(desc.name + ": BlendMode::Transmit needs the device's dualSrcBlend feature");
  const VkDevice device = context.device();
  std::vector<VkDescriptorSetLayoutBinding> bindings;
  for (const auto& b : desc.bindings)
    bindings.push_back({b.binding,
                        b.kind == DescriptorKind::SampledImage ? VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER
                                                               : VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                        1, b.stages, nullptr});
  VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  set_info.flags = VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR;
  set_info.bindingCount = static_cast<uint32_t>(bindings.size());
  set_info.pBindings = bindings.data();
  VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
  VK_CHECK(vkCreateDescriptorSetLayout(device, &set_info, nullptr, &set_layout));
  objects_->set_layout = {device, set_layout, vkDestroyDescriptorSetLayout};

  VkPushConstantRange range{VK_SHADER_STAGE_ALL_GRAPHICS, 0, desc.push_constant_size};
  VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layout_info.setLayoutCount = 1;
  layout_info.pSetLayouts = &set_layout;
  layout_info.pushConstantRangeCount = desc.push_constant_size ? 1 : 0;
  layout_info.pPushConstantRanges = &range;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VK_CHECK(vkCreatePipelineLayout(device, &layout_info, nullptr, &layout));
  objects_->layout = {device, layout, vkDestroyPipelineLayout};

  std::vector<VkSpecializationMapEntry> constants;
  for (uint32_t id = 0; id < desc.specialization.size(); ++id)
    constants.push_back({id, uint32_t(id * sizeof(int32_t)), sizeof(int32_t)});
  const VkSpecializationInfo specialization{uint32_t(constants.size()), constants.data(),
                                            desc.specialization.size() * sizeof(int32_t),
                                            desc.specialization.data()};

  // Modules are needed only until the pipeline exists; they are destroyed at the end of this scope.
  std::vector<UniqueHandle<VkShaderModule>> modules;
  std::vector<VkPipelineShaderStageCreateInfo> stages;
  auto add_stage = [&](VkShaderStageFlagBits stage, std::span<const uint32_t> code) {
    if (code.empty()) return;
    modules.push_back(create_module(device, code));
    VkPipelineShaderStageCreateInfo s{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    s.stage = stage;
    s.module = modules.back().get();
    s.pName = "main";
    s.pSpecializationInfo = constants.empty() ? nullptr : &specialization;
    stages.push_back(s);
  };
  add_stage(VK_SHADER_STAGE_VERTEX_BIT, desc.vertex);
  add_stage(VK_SHADER_STAGE_GEOMETRY_BIT, desc.geometry);
  add_stage(VK_SHADER_STAGE_FRAGMENT_BIT, desc.fragment);

  VkPipelineVertexInputStateCreateInfo vertex_input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = desc.topology;
  VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = VK_CULL_MODE_NONE;
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  raster.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = desc.depth_test;
  depth.depthWriteEnable = desc.depth_write;
  depth.depthCompareOp = desc.depth_compare;
  std::vector<VkPipelineColorBlendAttachmentState> attachments;
  for (size_t i = 0; i < desc.color_formats.size(); ++i)
    attachments.push_back(blend_state(i < desc.blend.size() ? desc.blend[i] : BlendMode::None));
  VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  blend.attachmentCount = static_cast<uint32_t>(attachments.size());
  blend.pAttachments = attachments.data();
  const VkDynamicState dynamic_states[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dynamic.dynamicStateCount = 2;
  dynamic.pDynamicStates = dynamic_states;

  VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
  rendering.colorAttachmentCount = static_cast<uint32_t>(desc.color_formats.size());
  rendering.pColorAttachmentFormats = desc.color_formats.data();
  rendering.depthAttachmentFormat = desc.depth_format;

  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO, &rendering};
  info.stageCount = static_cast<uint32_t>(stages.size());
  info.pStages = stages.data();
  info.pVertexInputState = &vertex_input;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depth;
  info.pColorBlendState = &blend;
  info.pDynamicState = &dynamic;
  info.layout = layout;
  VkPipeline pipeline = VK_NULL_HANDLE;
  VK_CHECK(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
  objects_->pipeline = {device, pipeline, vkDestroyPipeline};
  context.set_name(VK_OBJECT_TYPE_PIPELINE, reinterpret_cast<uint64_t>(pipeline), desc.name);
}

void GraphicsPipeline::bind(VkCommandBuffer cmd, uint32_t width, uint32_t height) const {
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, handle());
  const VkViewport viewport{0.0f, 0.0f, float(width), float(height), 0.0f, 1.0f};
  const VkRect2D scissor{{0, 0}, {width, height}};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
}

void GraphicsPipeline::push_image(VkCommandBuffer cmd, uint32_t binding, VkImageView view,
                                  VkSampler sampler) const {
  VkDescriptorImageInfo image{sampler, view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  VkWriteDescriptorSet write = descriptor_write(binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
  write.pImageInfo = &image;
  context_.get()->cmd_push_descriptor_set(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout(), 0, 1, &write);
}

void GraphicsPipeline::push_uniform(VkCommandBuffer cmd, uint32_t binding, VkBuffer buffer,
                                    VkDeviceSize offset, VkDeviceSize size) const {
  VkDescriptorBufferInfo info{buffer, offset, size};
  VkWriteDescriptorSet write = descriptor_write(binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER);
  write.pBufferInfo = &info;
  context_.get()->cmd_push_descriptor_set(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout(), 0, 1, &write);
}

void GraphicsPipeline::push_constants(VkCommandBuffer cmd, const void* data, uint32_t size) const {
  if (size > push_constant_size_)
    throw std::logic_error(name_ + ": push constants of " + std::to_string(size) +
                           " bytes exceed the declared " + std::to_string(push_constant_size_));
  vkCmdPushConstants(cmd, layout(), VK_SHADER_STAGE_ALL_GRAPHICS, 0, size, data);
}

}  // namespace engine::vk
