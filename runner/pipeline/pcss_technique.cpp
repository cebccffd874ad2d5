#include "pipeline/pcss_technique.h"

namespace pn {
namespace {

class PcssConfig : public TechniqueConfig {
 public:
  explicit PcssConfig(PcssSettings settings) : settings_(std::move(settings)) {}
  std::string name() const override { return settings_.name; }
  void rename(const std::string& name) override { settings_.name = name; }
  std::vector<std::string> keys() const override { return pcss_setting_keys(); }
  void set(const std::string& key, const std::string& value) override { set_pcss_setting(settings_, key, value); }
  void validate() const override { settings_.validate(); }
  std::unique_ptr<Technique> create(TechniqueResources& resources) const override {
    return std::make_unique<PcssTechnique>(resources.shared<PcssPipeline>(), settings_);
  }
  std::unique_ptr<TechniqueConfig> clone() const override { return std::make_unique<PcssConfig>(settings_); }

 private:
  PcssSettings settings_;
};

}  // namespace

TechniqueFrame PcssTechnique::run(const TechniqueInputs& inputs, bool with_stats) const {
  PcssFrame frame = pipeline_->run(inputs, settings_);
  TechniqueFrame out;
  out.stages = frame.stages;
  if (with_stats) {
    const PcssStats stats = pipeline_->stats(frame);
    out.stats = {{"representatives", stats.representative_fraction()}, {"work/px", stats.work_per_receiver()}};
  }
  out.visibility = std::move(settings_.blur ? frame.blurred : frame.visibility);
  return out;
}

std::unique_ptr<TechniqueConfig> pcss_config(PcssSettings settings) {
  return std::make_unique<PcssConfig>(std::move(settings));
}

std::unique_ptr<TechniqueConfig> pcss_ablation(const char* name, const char* key, const char* value) {
  PcssSettings s = fast_pcss();  // one switch away from the shipped defaults
  s.name = name;
  set_pcss_setting(s, key, value);
  return pcss_config(s);
}

}  // namespace pn
