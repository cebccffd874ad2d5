#include "vk/vulkan_stage_spirv.h"

#include <filesystem>

#include "core/error.h"
#include "shader/export_source.h"
#include "shader/flatten.h"
#include "shader/glslang_compiler.h"
#include "shader/spirv_cross.h"
#include "vk/vulkan_program.h"
#include "vk/vulkan_state.h"

namespace pn::vk {

namespace {

std::vector<std::uint32_t> compile_stage(const VulkanDevice::State& s, const FlatSource& flat, ShaderSource source,
                                         const std::string& pass,
                                         const std::vector<Define>& defines, std::vector<GuardedLoop>* loops) {
  if (loops != nullptr && s.bounds.enabled)
    *loops = guard_loops(s.glslang, source, Target::vulkan, {kGuardBinding, s.bounds.loop_iterations});
  const CompileResult glsl = compile_with_glslang(s.glslang, source, Target::vulkan);
  if (!glsl.ok) throw Error(pass + ": " + first_error(glsl, "glslang could not compile it for Vulkan"), ExitCode::failed);
  if (s.settings.language == PassLanguage::glsl) return glsl.spirv;

  std::string name = std::filesystem::path(pass).stem().string() + ".hlsl";
  std::string hlsl;
  // The copy stands in for the entry of its name (vk/hlsl_root.h); either way, what ran is recorded
  // for the check's report, so a check never falls back to the library's export in silence.
  const std::filesystem::path copy = s.settings.hlsl_root ? *s.settings.hlsl_root / name : std::filesystem::path();
  const bool has_copy = s.settings.hlsl_root && std::filesystem::is_regular_file(copy);  // links followed
  if (source.stage == Stage::compute && has_copy && defines.empty()) {
    const SourceTree root(*s.settings.hlsl_root);  // read as module files are: a regular file, bounded
    const std::filesystem::path canonical = root.locate_in_root(name);
    hlsl = root.read(canonical), name = root.diagnostic_path(canonical);
    if (loops != nullptr)  // the copy's own loops, guarded as the GLSL's are
      // The guard's buffer in the copy's register plan, as the executor finds it (register u63 + the shift).
      *loops = s.bounds.enabled ? guard_hlsl_loops(s.glslang, hlsl, name, source.stage,
                                                   {kGuardBinding + s.settings.registers.u, s.bounds.loop_iterations,
                                                    s.settings.registers.space})
                                : std::vector<GuardedLoop>{};
    s.origins.push_back({pass, name, "", ""});
    s.copies_read.insert(copy.filename().string());
  } else {
    // As `bundle` writes it: shader model 5.0, or 5.1 for a plan's register space.
    const CrossLanguage language = s.settings.registers.space != 0 ? CrossLanguage::hlsl51 : CrossLanguage::hlsl50;
    hlsl = export_code(glsl.spirv, flat, language, s.settings.registers);
    if (s.settings.hlsl_root) {
      const std::string root = s.settings.hlsl_root->string();
      if (source.stage != Stage::compute) {
        s.origins.push_back({pass, "", "vertex and fragment stages (a copy stands in for a compute entry only)", ""});
      } else if (!defines.empty()) {
        std::string set;
        for (const Define& d : defines) set += (set.empty() ? "" : " ") + d.name + (d.value.empty() ? "" : "=" + d.value);
        s.origins.push_back({pass, "",
                             std::string("compiled with defines, which a copy (one fixed text) cannot take") +
                                 (has_copy ? ": its copy in " + root + " not read" : ""),
                             set});
      } else {
        s.origins.push_back({pass, "", "no copy of it in " + root, ""});
      }
    }
  }
  const CompileResult back = compile_hlsl_with_glslang(s.glslang, hlsl, name, source.stage);
  if (!back.ok) throw Error(name + ": " + first_error(back, "glslang could not compile the HLSL"), ExitCode::failed);
  return back.spirv;
}

}  // namespace

std::vector<std::uint32_t> stage_spirv(const VulkanDevice::State& s, const SourceTree& tree, const std::string& pass,
                                       const std::vector<Define>& defines, std::vector<GuardedLoop>* loops) {
  const FlatSource flat = flatten(tree, tree.locate_in_root(pass));
  ShaderSource source = standalone_source(flat, Target::vulkan, defines);
  // A copy's run is recorded each time (origins): never from the cache.
  if (s.settings.hlsl_root) return compile_stage(s, flat, std::move(source), pass, defines, loops);
  // The same text, stage, language and loop guard compile to the same SPIR-V and loops.
  const bool guarded = loops != nullptr && s.bounds.enabled;
  const std::string key = std::to_string(static_cast<int>(source.stage)) + "|" +
                          std::to_string(static_cast<int>(s.settings.language)) + "|" +
                          (guarded ? std::to_string(s.bounds.loop_iterations) : std::string("-")) + "|" +
                          (loops != nullptr ? "loops" : "") + "|" + source.text;
  const auto found = s.compiled.find(key);
  if (found == s.compiled.end()) {
    VulkanDevice::State::CompiledStage stage;
    stage.spirv = compile_stage(s, flat, std::move(source), pass, defines, loops ? &stage.loops : nullptr);
    const auto added = s.compiled.emplace(key, std::move(stage)).first;
    if (loops != nullptr) *loops = added->second.loops;
    return added->second.spirv;
  }
  if (loops != nullptr) *loops = found->second.loops;
  return found->second.spirv;
}

std::string program_name(const VulkanDevice::State& s, const std::string& pass) {
  return s.settings.language == PassLanguage::hlsl ? pass + " (HLSL)" : pass;
}

}  // namespace pn::vk
