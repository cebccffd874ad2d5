// The variance shadow maps behind the technique seam (registry entries `vsm`
// and `evsm`): on the ordinary shadow map, the moments (vsm_moments.comp),
// blurred (blur.glsl over 2 or 4 channels, radius a setting), and per screen
// pixel the Chebyshev bound with the bleeding reduction and the depth-range
// bound (vsm_shade.comp over vsm.glsl). EVSM's depth range is the light's
// near and far planes; VSM reads empty texels (+Inf) as the far plane.
#pragma once

#include <memory>
#include <string>

#include "pass_runners/vsm_pass.h"
#include "frame/technique.h"

namespace pn {

struct VsmTechniqueSettings {
  std::string name;
  VsmParams params;   // kind, blur (radius, sigma), min variance, reduction, exponents; the range comes from the light
  float bias = 0.02f;  // world units of light depth, as the PCSS family's default

  void validate() const;  // throws Error naming the technique, the setting and its range
};

// The override keys: radius, sigma, bias, min-variance, bleeding, exponent, negative-exponent.
std::vector<std::string> vsm_setting_keys();
void set_vsm_setting(VsmTechniqueSettings& s, const std::string& key, const std::string& value);

// The registry's entries: VSM, and EVSM with 4 components (c+ 40, c- 5).
std::unique_ptr<TechniqueConfig> vsm_config(VsmKind kind, const char* name);

// The passes the vsm techniques of one device share (TechniqueResources::shared).
struct VsmPasses {
  VsmPasses(const QueryDevice& device, const SourceTree& tree);
  VsmMomentsPass moments;
  VsmShadePass shade;
  DepthPyramidBuilder pyramid;
};

class VsmTechnique : public Technique {
 public:
  VsmTechnique(const QueryDevice& device, const VsmPasses& passes, VsmTechniqueSettings settings)
      : device_(&device), passes_(&passes), settings_(std::move(settings)) {}
  // Stages: moments, blur, pyramid (when the source keeps none), shade. No stats.
  TechniqueFrame run(const TechniqueInputs& inputs, bool with_stats) const override;

 private:
  const QueryDevice* device_;
  const VsmPasses* passes_;
  VsmTechniqueSettings settings_;
};

}  // namespace pn
