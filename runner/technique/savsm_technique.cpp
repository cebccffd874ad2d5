#include "technique/savsm_technique.h"

#include <cmath>

#include "core/error.h"
#include "frame/fetch_proxy.h"
#include "frame/settings_config.h"
#include "frame/setting_value.h"

namespace pn {

void SavsmTechniqueSettings::validate() const {
  try {
    savsm.validate();
  } catch (const Error& e) {
    throw Error("technique '" + name + "': " + e.what());
  }
}

std::vector<std::string> savsm_setting_keys() {
  return {"bias", "scale", "min-variance", "bleeding", "blocker", "bound", "table"};
}

void set_savsm_setting(SavsmTechniqueSettings& s, const std::string& key, const std::string& value) {
  const auto real = [&] { return setting_real(s.name, key, value); };
  const auto choice = [&](const char* a, const char* b) {
    if (value == a) return true;
    if (value == b) return false;
    throw bad_setting_value(s.name, key, value, (std::string(a) + " or " + b).c_str());
  };
  if (key == "bias") s.savsm.bias = real();
  else if (key == "scale") s.savsm.filter_scale = real();
  else if (key == "min-variance") s.savsm.min_variance = real();
  else if (key == "bleeding") s.savsm.bleeding_reduction = real();
  else if (key == "blocker") s.savsm.blocker = choice("table", "min") ? SavsmBlocker::table : SavsmBlocker::min;
  else if (key == "bound") s.savsm.bound = choice("on", "off");
  else if (key == "table") s.table = choice("fixed", "float") ? MomentsTableKind::fixed : MomentsTableKind::floating;
  else throw unknown_setting(s.name, key, savsm_setting_keys());
}

std::unique_ptr<TechniqueConfig> savsm_config(const char* name,
                                              const std::vector<std::pair<std::string, std::string>>& overrides) {
  SavsmTechniqueSettings s;
  s.name = name;
  for (const auto& [key, value] : overrides) set_savsm_setting(s, key, value);
  return settings_config<SavsmTechniqueSettings>(
      s, {&savsm_setting_keys, &set_savsm_setting,
          [](TechniqueResources& resources, const SavsmTechniqueSettings& settings) -> std::unique_ptr<Technique> {
            return std::make_unique<SavsmTechnique>(resources.device(), resources.shared<SavsmPasses>(), settings);
          }});
}

SavsmPasses::SavsmPasses(const QueryDevice& device, const SourceTree& tree)
    : table(device, tree), shade(device, tree), mip(device, tree), no_mip(device.make_texture(float_shape(1, 1, 4))) {
  const float zero[4] = {0, 0, 0, 0};
  device.clear_texture(*no_mip, zero);
}

TechniqueFrame SavsmTechnique::run(const TechniqueInputs& inputs, bool with_stats) const {
  if (inputs.shadow_map == nullptr || inputs.gbuffer == nullptr)
    throw Error("technique '" + settings_.name + "': needs a shadow map and a G-buffer");
  const int n = inputs.light.map_size;
  const std::unique_ptr<StageTimes> clock = device_->stage_clock();
  clock->start();
  const MomentsTable table = passes_->table.build(*inputs.shadow_map, n, n, settings_.table,
                                                  unit_range(inputs.light.near_plane, inputs.light.far_plane));
  clock->stage("table");
  MinMaxMipChain own;
  const DeviceTexture* mip = passes_->no_mip.get();
  if (settings_.savsm.reads_mip()) {
    if (inputs.mip != nullptr && inputs.mip->map_size == n) {
      mip = inputs.mip->texture.get();
    } else {
      own = passes_->mip.build(*inputs.shadow_map, n);
      mip = own.texture.get();
      clock->stage("mip chain");
    }
  }
  TechniqueFrame out;
  out.visibility = passes_->shade.shade(table, *mip, *inputs.gbuffer, inputs.screen_size, inputs.light,
                                        settings_.savsm, inputs.stage);
  clock->stage("shade");
  out.stages = clock->read();
  if (with_stats) out.stats = constant_fetch_stats(kSavsmMaxReceiverFetches);
  return out;
}

}  // namespace pn
