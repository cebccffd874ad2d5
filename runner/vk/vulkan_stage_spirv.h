// What a pass is compiled from on the Vulkan executor: the vulkan target's SPIR-V, its HLSL export
// compiled back (--api hlsl), or the user's copy of that export (--hlsl-root), loop guard and all.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "shader/loop_guard.h"
#include "shader/source_tree.h"
#include "shader/target.h"
#include "vk/vulkan_device.h"

namespace pn::vk {

// One stage of a pass as the device runs it: the vulkan target's SPIR-V, or (--api hlsl) its HLSL
// export compiled back — or the user's copy of that export (--hlsl-root, a pass without extra
// defines). `loops`: the loop guard's loops, put in under the dispatch bounds (compute passes):
// into the GLSL, which the library's HLSL export is made from, or into the user's copy.
std::vector<std::uint32_t> stage_spirv(const VulkanDevice::State& s, const SourceTree& tree, const std::string& pass,
                                       const std::vector<Define>& defines, std::vector<GuardedLoop>* loops);

// The name a program compiled from `pass` goes by in errors: "(HLSL)" after it under --api hlsl.
std::string program_name(const VulkanDevice::State& s, const std::string& pass);

}  // namespace pn::vk
