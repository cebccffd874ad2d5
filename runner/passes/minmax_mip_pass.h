// Runner side of glsl/passes/minmax_mip_build.comp: the aligned min/max/mean
// mip chain, built only as the baseline of `penumbra bench pyramid`.
#pragma once

#include <cstddef>

#include "gl/compute_program.h"
#include "shader/source_tree.h"

namespace pn {

struct MinMaxMipChain {
  GlObject texture;  // RGBA32F, floor(log2 N) + 1 mip levels
  int map_size = 0;
  int levels = 0;

  static std::size_t memory_bytes(int map_size);  // 16 bytes × texels of every level
};

class MinMaxMipBuilder {
 public:
  MinMaxMipBuilder(const Context& context, const SourceTree& tree);
  MinMaxMipChain allocate(int map_size) const;
  void build_into(const GlObject& shadow_map, const MinMaxMipChain& chain) const;

 private:
  const Context* context_;
  ComputeProgram program_;
};

}  // namespace pn
