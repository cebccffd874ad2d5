// Any technique on cascades (issue 14): run once a cascade, on that cascade's
// map, G-buffer and light (TechniqueInputs::cascades), and the visibilities
// blended by view depth (CascadeBlendPass). The techniques themselves do not
// know they run on cascades: a cascade's G-buffer marks every pixel outside
// its fitted depth range as "no surface", which a technique leaves lit at
// the cost of one fetch, so a frame costs about one run over the screen plus
// the transition bands.
#pragma once

#include "pass_runners/cascade_blend_pass.h"
#include "frame/technique.h"

namespace pn {

class CascadedTechnique : public Technique {
 public:
  CascadedTechnique(const Technique& inner, const CascadeBlendPass& blend, const QueryDevice& device)
      : inner_(&inner), blend_(&blend), device_(&device) {}

  // Throws Error unless inputs.cascades is set. Stages: the inner technique's, each summed over
  // the cascades, then "cascade blend"; stats: each cascade's, prefixed "c<i> ".
  // inputs.stage reaches every cascade's call.
  TechniqueFrame run(const TechniqueInputs& inputs, bool with_stats) const override;
  bool has_one_call() const override { return inner_->has_one_call(); }

 private:
  const Technique* inner_;
  const CascadeBlendPass* blend_;
  const QueryDevice* device_;
};

}  // namespace pn
