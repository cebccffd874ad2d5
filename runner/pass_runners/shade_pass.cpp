#include "pass_runners/shade_pass.h"

#include "core/error.h"

namespace pn {

ShadePass::ShadePass(const QueryDevice& device, const SourceTree& tree, std::string stem, unsigned image_binding)
    : device_(&device), tree_(tree), stem_(std::move(stem)), image_binding_(image_binding),
      compute_(device, tree, stem_ + ".comp") {}

std::unique_ptr<DeviceTexture> ShadePass::run(ShadeStage stage, const std::vector<Define>& defines, int size,
                                              PassResources resources, int fragment_channels) const {
  if (stage == ShadeStage::compute) {
    std::unique_ptr<DeviceTexture> out = device_->make_texture(float_shape(size, size, 1));
    resources.images.push_back({image_binding_, *out});
    device_->run(compute_.get(defines), resources, size, size);
    return out;
  }
  if (fragment_channels != 1 && fragment_channels != 4)
    throw Error(stem_ + ".frag: a target of " + std::to_string(fragment_channels) + " channels: expected 1 or 4");
  std::unique_ptr<QueryProgram>& program = fragment_[define_key(defines) + ";" + std::to_string(fragment_channels)];
  if (!program)
    program = device_->compile_full_screen(tree_, stem_ + ".frag",
                                           fragment_channels == 1 ? TexelFormat::r32f : TexelFormat::rgba32f, defines);
  return device_->draw_full_screen(*program, size, resources);
}

}  // namespace pn
