#include "technique/pcf_technique.h"

#include <cmath>

#include "core/format.h"
#include "frame/fetch_proxy.h"
#include "frame/settings_config.h"
#include "frame/setting_value.h"
#include "modules/pcf_face.h"
#include "pass_runners/pcf_pass.h"

namespace pn {
namespace {

// What the pcf entry takes: its name, bias and receiver plane.
struct PcfTechniqueSettings {
  std::string name;
  float bias = 0.02f;
  float receiver_plane_tan = 0.0f;  // 0: none; else the plane's slope clamp (gbuffer_receiver_plane.glsl)

  void validate() const {
    if (!std::isfinite(bias) || bias < 0.0f)
      throw Error("technique '" + name + "': bias " + format_number("%g", bias) + ": expected a finite number >= 0");
  }
};

class PcfTechnique : public Technique {
 public:
  PcfTechnique(const QueryDevice& device, const PcfShadePass& pass, PcfTechniqueSettings settings)
      : device_(&device), pass_(&pass), settings_(std::move(settings)) {}

  TechniqueFrame run(const TechniqueInputs& inputs, bool with_stats) const override {
    if (inputs.shadow_map == nullptr || inputs.gbuffer == nullptr)
      throw Error("technique '" + settings_.name + "': needs a shadow map and a G-buffer");
    const int size = inputs.screen_size;
    const std::unique_ptr<StageTimes> clock = device_->stage_clock();
    clock->start();
    TechniqueFrame out;
    out.visibility = pass_->run(*inputs.shadow_map, *inputs.gbuffer, size, inputs.light, settings_.bias,
                                settings_.receiver_plane_tan, inputs.stage);
    clock->stage("shade");
    out.stages = clock->read();
    if (with_stats) out.stats = constant_fetch_stats(kPcfReceiverFetches);
    return out;
  }

 private:
  const QueryDevice* device_;
  const PcfShadePass* pass_;
  PcfTechniqueSettings settings_;
};

}  // namespace

std::unique_ptr<TechniqueConfig> pcf_config(const char* name) {
  PcfTechniqueSettings s;
  s.name = name;
  return settings_config<PcfTechniqueSettings>(
      s, {[]() -> std::vector<std::string> { return {"bias", "receiver-plane"}; },
          [](PcfTechniqueSettings& settings, const std::string& key, const std::string& value) {
            if (key == "bias") settings.bias = setting_real(settings.name, key, value);
            else if (key == "receiver-plane") settings.receiver_plane_tan = setting_receiver_plane(settings.name, key, value);
            else throw unknown_setting(settings.name, key, {"bias", "receiver-plane"});
          },
          [](TechniqueResources& resources, const PcfTechniqueSettings& settings) -> std::unique_ptr<Technique> {
            return std::make_unique<PcfTechnique>(resources.device(), resources.shared<PcfShadePass>(), settings);
          }});
}

}  // namespace pn
