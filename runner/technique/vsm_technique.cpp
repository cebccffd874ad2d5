#include "technique/vsm_technique.h"

#include <cmath>
#include <exception>

#include "core/error.h"
#include "frame/setting_value.h"
#include "core/format.h"
#include "frame/fetch_proxy.h"
#include "frame/settings_config.h"

namespace pn {
namespace {

// The pyramid levels the depth-range bound reads: its square's side 2r + 1 at level floor(log2(2r + 1)).
int bound_levels(int radius) {
  int level = 0;
  while ((2 << level) <= 2 * radius + 1) ++level;
  return level;
}

}  // namespace

void VsmTechniqueSettings::validate() const {
  if (!std::isfinite(bias) || bias < 0.0f)
    throw Error("technique '" + name + "': bias " + format_number("%g", bias) + ": expected a finite number >= 0");
  try {
    params.validate();
  } catch (const Error& e) {
    throw Error("technique '" + name + "': " + e.what());
  }
}

std::vector<std::string> vsm_setting_keys() {
  return {"radius", "sigma", "bias", "min-variance", "bleeding", "exponent", "negative-exponent"};
}

void set_vsm_setting(VsmTechniqueSettings& s, const std::string& key, const std::string& value) {
  const auto integer = [&] { return setting_integer(s.name, key, value); };
  const auto real = [&] { return setting_real(s.name, key, value); };
  if (key == "radius") s.params.blur.radius = integer();
  else if (key == "sigma") s.params.blur.sigma = real();
  else if (key == "bias") s.bias = real();
  else if (key == "min-variance") s.params.min_variance = real();
  else if (key == "bleeding") s.params.bleeding_reduction = real();
  else if (key == "exponent") s.params.positive_exponent = real();
  else if (key == "negative-exponent") s.params.negative_exponent = real();
  else throw unknown_setting(s.name, key, vsm_setting_keys());
}

std::unique_ptr<TechniqueConfig> vsm_config(VsmKind kind, const char* name) {
  VsmTechniqueSettings s;
  s.name = name;
  s.params.kind = kind;
  return settings_config<VsmTechniqueSettings>(
      s, {&vsm_setting_keys, &set_vsm_setting,
          [](TechniqueResources& resources, const VsmTechniqueSettings& settings) -> std::unique_ptr<Technique> {
            return std::make_unique<VsmTechnique>(resources.device(), resources.shared<VsmPasses>(), settings);
          }});
}

VsmPasses::VsmPasses(const QueryDevice& device, const SourceTree& tree)
    : moments(device, tree), shade(device, tree), pyramid(device, tree) {}

TechniqueFrame VsmTechnique::run(const TechniqueInputs& inputs, bool with_stats) const {
  if (inputs.shadow_map == nullptr || inputs.gbuffer == nullptr)
    throw Error("technique '" + settings_.name + "': needs a shadow map and a G-buffer");
  const int n = inputs.light.map_size;
  VsmParams params = settings_.params;
  params.near_depth = static_cast<float>(inputs.light.near_plane);
  params.far_depth = static_cast<float>(inputs.light.far_plane);
  const std::unique_ptr<StageTimes> clock = device_->stage_clock();
  clock->start();
  const VsmMoments moments = passes_->moments.moments(*inputs.shadow_map, n, n, params);
  clock->stage("moments");
  const VsmMoments blurred = passes_->moments.blurred(moments, params);
  clock->stage("blur");
  DepthPyramid own;
  const DepthPyramid* pyramid = inputs.pyramid;
  if (pyramid == nullptr) {
    own = passes_->pyramid.build(*inputs.shadow_map, n, n, bound_levels(params.blur.radius));
    pyramid = &own;
    clock->stage("pyramid");
  }
  TechniqueFrame out;
  out.visibility = passes_->shade.run(blurred, *pyramid, *inputs.gbuffer, inputs.screen_size, params, settings_.bias,
                                       inputs.stage);
  clock->stage("shade");
  out.stages = clock->read();
  if (with_stats) out.stats = constant_fetch_stats(kVsmReceiverFetches);
  return out;
}

}  // namespace pn
