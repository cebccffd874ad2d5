// The depth_cache check's motion sequences, callable on their own (the GL
// tests run a broken cache through them): an animated scene's frames through
// a caching shadow-map source, each frame's composed map, mip chain and
// pyramid compared with a full render's and full rebuilds', and Fast PCSS on
// both.
#pragma once

#include <string>
#include <vector>

#include "frame/map_structures.h"
#include "check/module_check.h"

namespace pn {

struct MotionSequence {
  std::string source;  // shadow_map_sources() entry: "two-map", "dirty-rect"
  double k = 0.3;      // the motion function's share of moving triangles
  int frames = 100;
  int map_size = 256;
  SourceOptions options;  // the structures are always kept; dilate_updates as given
};

std::vector<CaseResult> run_motion_sequence(const CheckEnvironment& env, const MotionSequence& sequence);

}  // namespace pn
