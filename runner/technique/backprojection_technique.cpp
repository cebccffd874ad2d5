#include "technique/backprojection_technique.h"

#include <cmath>
#include <string>

#include "backprojection.h"
#include "core/format.h"
#include "frame/setting_value.h"
#include "frame/settings_config.h"
#include "gl/std140.h"
#include "pass_runners/minmax_mip_pass.h"
#include "pass_runners/shade_pass.h"
#include "scene/light_block.h"

namespace pn::glsl {
#include "passes/backprojection_shade.h"
PN_STD140_SIZE(PnBackprojectionShadeParams, 48);
PN_STD140_OFFSET(PnBackprojectionShadeParams, bias, 24);
PN_STD140_OFFSET(PnBackprojectionShadeParams, budget, 36);
}  // namespace pn::glsl

namespace pn {
namespace {

struct BackprojectionSettings {
  std::string name;
  float bias = 0.02f;  // light-depth units, as the PCSS family's default
  int samples = PN_BACKPROJECTION_DEFAULT_SIDE * PN_BACKPROJECTION_DEFAULT_SIDE;
  float tolerance = PN_BACKPROJECTION_DEFAULT_TOLERANCE;
  int budget = PN_BACKPROJECTION_DEFAULT_BUDGET;
  float gap = static_cast<float>(PN_BACKPROJECTION_DEFAULT_GAP);
  float thickness = static_cast<float>(PN_BACKPROJECTION_DEFAULT_THICKNESS);
  MapLayer layer = MapLayer::back_faces;  // the second layer its slabs reach down to (first: none)

  int side() const { return static_cast<int>(std::lround(std::sqrt(static_cast<double>(samples)))); }
  // The module's defaults but the bias (pnBackprojectionDefaults): the shade pass then compiles them as
  // constants, the program an engine's shader makes (docs/benchmarks.md).
  bool engine_form() const {
    const BackprojectionSettings d;
    return samples == d.samples && tolerance == d.tolerance && budget == d.budget && gap == d.gap &&
           thickness == d.thickness;
  }
  void validate() const {
    const auto bad = [&](const std::string& what) { return Error("technique '" + name + "': " + what); };
    if (!std::isfinite(bias) || bias < 0.0f) throw bad("bias " + format_number("%g", bias) + ": expected a finite number >= 0");
    if (samples != 16 && samples != 64 && samples != 256)
      throw bad("samples " + std::to_string(samples) + ": expected 16, 64 or 256");
    if (!std::isfinite(tolerance) || tolerance < 0.0f)
      throw bad("tolerance " + format_number("%g", tolerance) + ": expected a finite number >= 0");
    if (!std::isfinite(gap) || gap < 0.0f) throw bad("gap " + format_number("%g", gap) + ": expected a finite number >= 0");
    if (!(thickness >= 0.0f && thickness <= 1.0f))
      throw bad("thickness " + format_number("%g", thickness) + ": expected a number in [0, 1]");
    if (budget < 1 || budget > PN_BACKPROJECTION_MAX_BUDGET)
      throw bad("budget " + std::to_string(budget) + ": expected 1.." + std::to_string(PN_BACKPROJECTION_MAX_BUDGET));
  }
};

std::vector<std::string> backprojection_keys() {
  return {"bias", "samples", "tolerance", "budget", "gap", "thickness", "layer"};
}

// "none", "peeled" or "back-faces" (map_layer_name's names, "none" for the first).
MapLayer parse_layer(const std::string& technique, const std::string& value) {
  if (value == "none") return MapLayer::first;
  for (const MapLayer layer : {MapLayer::peeled, MapLayer::back_faces})
    if (value == map_layer_name(layer)) return layer;
  throw Error("technique '" + technique + "': layer '" + value + "': expected none, peeled or back-faces");
}

// The passes the backprojection techniques of one device share (TechniqueResources::shared).
struct BackprojectionPasses {
  BackprojectionPasses(const QueryDevice& device, const SourceTree& tree)
      : shade(device, tree, "passes/backprojection_shade", PN_BACKPROJECTION_SHADE_VISIBILITY_IMAGE), mip(device, tree) {}
  ShadePass shade;
  MinMaxMipBuilder mip;
};

class BackprojectionTechnique : public Technique {
 public:
  BackprojectionTechnique(const QueryDevice& device, const BackprojectionPasses& passes, BackprojectionSettings s)
      : device_(&device), passes_(&passes), settings_(std::move(s)) {}

  TechniqueFrame run(const TechniqueInputs& inputs, bool) const override {
    if (inputs.shadow_map == nullptr || inputs.gbuffer == nullptr)
      throw Error("technique '" + settings_.name + "': needs a shadow map and a G-buffer");
    const int n = inputs.light.map_size;
    const std::unique_ptr<StageTimes> clock = device_->stage_clock();
    clock->start();
    MinMaxMipChain own;
    const MinMaxMipChain* mip = inputs.mip;
    if (mip == nullptr || mip->map_size != n) {
      own = passes_->mip.build(*inputs.shadow_map, n);
      mip = &own;
      clock->stage("mip chain");
    }
    glsl::PnBackprojectionShadeParams block{};
    set_light_fields(block, inputs.light);
    block.bias = settings_.bias;
    block.side = settings_.side();
    block.tolerance = settings_.tolerance;
    block.budget = settings_.budget;
    block.gap = settings_.gap;
    block.thickness = settings_.thickness;
    PassResources resources;
    resources.block = query_block(block);
    resources.add_textures({{PN_BACKPROJECTION_SHADE_MIP_BINDING, *mip->texture},
                            {PN_BACKPROJECTION_SHADE_MAP_BINDING, mip->built_map()},
                            {PN_BACKPROJECTION_SHADE_GBUFFER_BINDING, *inputs.gbuffer}});
    std::vector<Define> defines;
    if (settings_.engine_form()) defines.push_back({"PN_BACKPROJECTION_ENGINE_FORM", "1"});
    MinMaxMipChain second_mip;
    if (settings_.layer != MapLayer::first) {
      const DeviceTexture* layer = inputs.second_layers.at(settings_.layer);
      if (layer == nullptr)
        throw Error("technique '" + settings_.name + "': needs the map's " + map_layer_name(settings_.layer) +
                    " layer, which the frame did not draw");
      second_mip = passes_->mip.build(*layer, n);
      clock->stage("second layer's chain");
      resources.add_textures({{PN_BACKPROJECTION_SHADE_LAYER_BINDING, *second_mip.texture},
                              {PN_BACKPROJECTION_SHADE_LAYER_MAP_BINDING, second_mip.built_map()}});
      defines.push_back({"PN_BACKPROJECTION_SHADE_SLABS", "1"});
    }
    TechniqueFrame out;
    out.visibility = passes_->shade.run(inputs.stage, defines, inputs.screen_size, resources);
    clock->stage("shade");
    out.stages = clock->read();
    return out;
  }

 private:
  const QueryDevice* device_;
  const BackprojectionPasses* passes_;
  BackprojectionSettings settings_;
};

}  // namespace

std::unique_ptr<TechniqueConfig> backprojection_config(const char* name) {
  BackprojectionSettings s;
  s.name = name;
  return settings_config<BackprojectionSettings>(
      s, {&backprojection_keys,
          [](BackprojectionSettings& settings, const std::string& key, const std::string& value) {
            if (key == "bias") settings.bias = setting_real(settings.name, key, value);
            else if (key == "samples") settings.samples = setting_integer(settings.name, key, value);
            else if (key == "tolerance") settings.tolerance = setting_real(settings.name, key, value);
            else if (key == "budget") settings.budget = setting_integer(settings.name, key, value);
            else if (key == "gap") settings.gap = setting_real(settings.name, key, value);
            else if (key == "thickness") settings.thickness = setting_real(settings.name, key, value);
            else if (key == "layer") settings.layer = parse_layer(settings.name, value);
            else throw unknown_setting(settings.name, key, backprojection_keys());
          },
          [](TechniqueResources& resources, const BackprojectionSettings& settings) -> std::unique_ptr<Technique> {
            return std::make_unique<BackprojectionTechnique>(resources.device(),
                                                             resources.shared<BackprojectionPasses>(), settings);
          },
          [](const BackprojectionSettings& settings) -> std::optional<MapLayer> {
            if (settings.layer == MapLayer::first) return std::nullopt;
            return settings.layer;
          }});
}

}  // namespace pn
