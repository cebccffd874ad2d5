#include "technique/pcf_technique.h"

#include <cmath>

#include "core/format.h"
#include "gl/gpu_timer.h"
#include "frame/setting_value.h"
#include "passes/pcf_pass.h"

namespace pn {
namespace {

class PcfTechnique : public Technique {
 public:
  PcfTechnique(const Context& context, const PcfShadePass& pass, std::string name, float bias)
      : context_(&context), pass_(&pass), name_(std::move(name)), bias_(bias) {}

  TechniqueFrame run(const TechniqueInputs& inputs, bool) const override {
    if (inputs.shadow_map == nullptr || inputs.gbuffer == nullptr)
      throw Error("method '" + name_ + "': needs a shadow map and a G-buffer");
    const int size = inputs.screen_size;
    StageClock clock(*context_);
    clock.start();
    TechniqueFrame out;
    out.visibility = pass_->run(*inputs.shadow_map, *inputs.gbuffer, size, bias_);
    context_->throw_if_gl_error("pcf shade");
    clock.stage("shade");
    out.stages = clock.read();
    return out;
  }

 private:
  const Context* context_;
  const PcfShadePass* pass_;
  std::string name_;
  float bias_;
};

class PcfConfig : public TechniqueConfig {
 public:
  explicit PcfConfig(std::string name) : name_(std::move(name)) {}
  std::string name() const override { return name_; }
  void rename(const std::string& name) override { name_ = name; }
  std::vector<std::string> keys() const override { return {"bias"}; }
  void set(const std::string& key, const std::string& value) override {
    if (key != "bias") throw Error("method '" + name_ + "': unknown setting '" + key + "': expected bias");
    bias_ = setting_real(name_, key, value);
  }
  void validate() const override {
    if (!std::isfinite(bias_) || bias_ < 0.0f)
      throw Error("method '" + name_ + "': bias " + format_number("%g", bias_) + ": expected a finite number >= 0");
  }
  std::unique_ptr<Technique> create(TechniqueResources& resources) const override {
    return std::make_unique<PcfTechnique>(resources.context(), resources.shared<PcfShadePass>(), name_, bias_);
  }
  std::unique_ptr<TechniqueConfig> clone() const override { return std::make_unique<PcfConfig>(*this); }

 private:
  std::string name_;
  float bias_ = 0.02f;
};

}  // namespace

std::unique_ptr<TechniqueConfig> pcf_config(const char* name) { return std::make_unique<PcfConfig>(name); }

}  // namespace pn
