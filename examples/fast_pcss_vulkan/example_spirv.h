// The example's shaders as SPIR-V words, compiled by glslangValidator at build time
// (CMakeLists.txt: each `glslangValidator … --vn kName -o name.spv.h`), so the binary runs from anywhere.
#pragma once

#include <cstdint>
#include <iterator>
#include <vector>

namespace example::spirv {

namespace words {
#include "gbuffer_frag.spv.h"
#include "gbuffer_vert.spv.h"
#include "mip_build_glsl.spv.h"
#include "mip_build_hlsl.spv.h"
#include "shade_glsl.spv.h"
#include "shade_hlsl.spv.h"
#include "shadow_depth_frag.spv.h"
#include "shadow_depth_vert.spv.h"
}  // namespace words

#define EX_SPIRV(NAME, WORDS) \
  inline std::vector<uint32_t> NAME() { return {std::begin(words::WORDS), std::end(words::WORDS)}; }
EX_SPIRV(shadow_depth_vert, kShadowDepthVert)
EX_SPIRV(shadow_depth_frag, kShadowDepthFrag)
EX_SPIRV(gbuffer_vert, kGbufferVert)
EX_SPIRV(gbuffer_frag, kGbufferFrag)
EX_SPIRV(mip_build_glsl, kMipBuildGlsl)  // passes/minmax_mip_build.comp, its Vulkan GLSL bundle
EX_SPIRV(mip_build_hlsl, kMipBuildHlsl)  // the same pass's HLSL export
EX_SPIRV(shade_glsl, kShadeGlsl)         // shaders/shade.comp with the GLSL bundle of fast_pcss.glsl
EX_SPIRV(shade_hlsl, kShadeHlsl)         // shaders/shade.hlsl with the HLSL export of fast_pcss.glsl
#undef EX_SPIRV

}  // namespace example::spirv
