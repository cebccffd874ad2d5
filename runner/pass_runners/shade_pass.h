// The last pass of a technique as an engine runs it: per screen pixel, the
// G-buffer's receiver handed to the technique's one call, in the stage the
// caller picks — a compute pass (the runner's default) or a fragment shader
// over a full-screen triangle, as a deferred lighting pass runs it (the
// fragment-stage checks). Both programs come from one stem: `<stem>.comp`
// writes its result to an r32f image, `<stem>.frag` (with
// passes/full_screen.vert) to the colour target; both include the body that
// calls the technique. Runs on any executor (device/query_device.h).
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "device/program_variants.h"
#include "device/query_device.h"
#include "shader/source_tree.h"

namespace pn {

enum class ShadeStage {
  compute,   // a compute pass, one invocation a pixel
  fragment,  // a fragment shader, one fragment a pixel (gl_FragCoord)
};

class ShadePass {
 public:
  // `stem`: e.g. "passes/pcf_shade"; `image_binding`: the compute pass's r32f output image.
  ShadePass(const QueryDevice& device, const SourceTree& tree, std::string stem, unsigned image_binding);

  // A new size² texture of the pass's values, computed in `stage` with the programs of `defines`
  // (compiled on first use); `resources` holds every resource the pass reads (and any further
  // image the compute pass writes). The compute pass's output is R32F; the fragment shader's
  // target has `fragment_channels` channels, 1 or 4 (what it writes beyond the visibility, for a check).
  std::unique_ptr<DeviceTexture> run(ShadeStage stage, const std::vector<Define>& defines, int size,
                                     PassResources resources, int fragment_channels = 1) const;

 private:
  const QueryDevice* device_;
  SourceTree tree_;
  std::string stem_;
  unsigned image_binding_;
  ProgramVariants compute_;
  mutable std::map<std::string, std::unique_ptr<QueryProgram>> fragment_;  // by define_key and channels
};

}  // namespace pn
