// Mesa's RADV on its null winsys: AMD's production shader compiler (ACO) with no GPU. A
// Vulkan device for one chip family compiles pipelines and reports, through
// VK_KHR_pipeline_executable_properties, what ACO made of each shader: registers, scratch,
// code size, instructions, its static estimates, and the ISA. It cannot run anything (the
// null device has no memory heaps). docs/isa.md.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "shader/flatten.h"

namespace pn {

// How the process must be set up before RadvNullDevice opens: RADV reads these when the
// instance is made, so `penumbra isa` sets them in a child process of its own per target.
struct RadvTarget {
  std::string family;  // RADV_FORCE_FAMILY: polaris10, vega10, navi10, navi21, gfx1100, …
  int wave = 64;       // 32: RADV_PERFTEST=cswave32,pswave32 (gfx10 and later only)
};

// The radeon ICD's manifest, or empty when the package that has it is not installed.
std::string radeon_icd_manifest();
// Sets this process's environment for `target` (ICD, family, wave size, no shader cache).
// Call only in a process that has not loaded Vulkan yet.
void set_radv_environment(const RadvTarget& target, const std::string& manifest, const std::string& runtime_dir);

// One shader of a compiled pipeline, as the driver reports it.
struct ShaderExecutable {
  Stage stage = Stage::compute;
  std::string name;                                       // the driver's: "compute shader", "fragment shader"
  std::vector<std::pair<std::string, double>> statistics; // the driver's names and values, in its order
  std::string isa;                                        // the disassembly ("" when not reported)
  double statistic(const std::string& name) const;        // -1 when the driver has none of that name
};

class RadvNullDevice {
 public:
  // Throws Error(ExitCode::failed) when no null RADV device comes up (names what was found).
  RadvNullDevice();
  ~RadvNullDevice();
  RadvNullDevice(const RadvNullDevice&) = delete;
  RadvNullDevice& operator=(const RadvNullDevice&) = delete;

  std::string device_name() const;  // "Null hardware (RADV NAVI21)"
  int min_wave() const;             // the least subgroup size: 32 on gfx10 and later, 64 before

  // Compiles a compute pipeline from `spirv`; its compute executable.
  std::vector<ShaderExecutable> compile_compute(const std::vector<std::uint32_t>& spirv, const std::string& name) const;
  // A graphics pipeline (a triangle list into one RGBA32F target with a depth buffer) from a vertex
  // and a fragment shader; both executables.
  std::vector<ShaderExecutable> compile_graphics(const std::vector<std::uint32_t>& vertex,
                                                 const std::vector<std::uint32_t>& fragment, const std::string& name) const;

  struct State;

 private:
  std::unique_ptr<State> s_;
};

}  // namespace pn
