#include "technique/pcss_technique.h"

#include "frame/settings_config.h"

namespace pn {
TechniqueFrame PcssTechnique::run(const TechniqueInputs& inputs, bool with_stats) const {
  if (inputs.stage == ShadeStage::fragment) {
    TechniqueFrame out;
    out.visibility = pipeline_->run_fragment(inputs, settings_, 1);
    return out;
  }
  PcssFrame frame = pipeline_->run(inputs, settings_, with_stats);
  TechniqueFrame out;
  out.stages = frame.stages;
  if (with_stats) {
    const PcssStats stats = pipeline_->stats(frame);
    out.stats = {{"representatives", stats.representative_fraction()},
                 {"work/px", stats.work_per_receiver()},
                 {kFetchStat, stats.fetches.per_receiver},
                 {kFetchTileMaxStat, stats.fetches.tile_max}};
  }
  out.visibility = frame.take_soft_shadow();
  return out;
}

std::unique_ptr<TechniqueConfig> pcss_config(PcssSettings settings) {
  return settings_config<PcssSettings>(
      std::move(settings), {[] { return pcss_setting_keys(); }, &set_pcss_setting,
                            [](TechniqueResources& resources, const PcssSettings& s) -> std::unique_ptr<Technique> {
                              return std::make_unique<PcssTechnique>(resources.shared<PcssPipeline>(), s);
                            }});
}

std::unique_ptr<TechniqueConfig> pcss_ablation(const char* name, const char* key, const char* value) {
  // One switch away from fast_pcss(), `fast:receiver-plane=off`: several ablations run the staged
  // passes, which take no plane (pcss_settings.h, shipped_fast_pcss).
  PcssSettings s = fast_pcss();
  s.name = name;
  set_pcss_setting(s, key, value);
  return pcss_config(s);
}

}  // namespace pn
