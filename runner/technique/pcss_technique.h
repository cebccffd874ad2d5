// The PCSS family behind the technique seam: exact PCSS, Poisson PCSS,
// HQEPCSS, Fast PCSS and its ablations are PcssSettings over the same passes
// (PcssPipeline), each a registry entry (technique/technique_registry.cpp).
#pragma once

#include <memory>
#include <string>

#include "pipeline/pcss_pipeline.h"
#include "frame/technique.h"

namespace pn {

class PcssTechnique : public Technique {
 public:
  PcssTechnique(const PcssPipeline& pipeline, PcssSettings settings) : pipeline_(&pipeline), settings_(std::move(settings)) {}
  // Stats: "representatives" (computed / regions, Steps 4 and 5) and "work/px"
  // (traversal nodes, scanned texels or Poisson samples per receiver).
  // In ShadeStage::fragment: the one call in a fragment shader, no stats.
  TechniqueFrame run(const TechniqueInputs& inputs, bool with_stats) const override;
  bool has_one_call() const override { return one_call(settings_).has_value(); }

 private:
  const PcssPipeline* pipeline_;
  PcssSettings settings_;
};

// A registry entry's settings: `settings` with the PCSS override keys (pcss_setting_keys()).
std::unique_ptr<TechniqueConfig> pcss_config(PcssSettings settings);

// fast_pcss() (`fast:receiver-plane=off`) with one setting changed, named `name`: an ablation switches one thing.
std::unique_ptr<TechniqueConfig> pcss_ablation(const char* name, const char* key, const char* value);

}  // namespace pn
