// Summed-area variance soft shadows behind the technique seam (registry
// entries `savsm`, `savsm-table`, `savsm-float`, `savsm-raw`): on the
// ordinary shadow map, the moments table (summed_area.glsl, fixed point or
// float), the min/max mip chain when the bound or the min blocker reads it,
// and per screen pixel savsm.glsl's estimate (passes/savsm_shade.comp). The
// table's unit depth spans the light's near and far planes.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "pass_runners/minmax_mip_pass.h"
#include "pass_runners/savsm_pass.h"
#include "pass_runners/summed_area_pass.h"
#include "frame/technique.h"

namespace pn {

struct SavsmTechniqueSettings {
  std::string name;
  SavsmSettings savsm;
  MomentsTableKind table = MomentsTableKind::fixed;

  void validate() const;  // throws Error naming the technique, the setting and its range
};

// The override keys: bias, scale, min-variance, bleeding, blocker (table|min), bound (on|off),
// table (fixed|float).
std::vector<std::string> savsm_setting_keys();
void set_savsm_setting(SavsmTechniqueSettings& s, const std::string& key, const std::string& value);

// A registry entry: `savsm` with the given overrides applied ({} for the defaults).
std::unique_ptr<TechniqueConfig> savsm_config(const char* name,
                                              const std::vector<std::pair<std::string, std::string>>& overrides);

// The passes the savsm techniques of one device share (TechniqueResources::shared).
struct SavsmPasses {
  SavsmPasses(const QueryDevice& device, const SourceTree& tree);
  SummedAreaMomentsPass table;
  SavsmPass shade;
  MinMaxMipBuilder mip;
  std::unique_ptr<DeviceTexture> no_mip;  // bound where the settings read no chain
};

class SavsmTechnique : public Technique {
 public:
  SavsmTechnique(const QueryDevice& device, const SavsmPasses& passes, SavsmTechniqueSettings settings)
      : device_(&device), passes_(&passes), settings_(std::move(settings)) {}
  // Stages: table, mip chain (when read and the source keeps none), shade. No stats.
  TechniqueFrame run(const TechniqueInputs& inputs, bool with_stats) const override;

 private:
  const QueryDevice* device_;
  const SavsmPasses* passes_;
  SavsmTechniqueSettings settings_;
};

}  // namespace pn
