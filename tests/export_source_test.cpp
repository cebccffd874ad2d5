// The HLSL and MSL exports as an engine takes them (issue 53): register plans parsed as documented,
// the modules' named constants and the GLSL's constant arrays under their own names, with the
// values of the C++ headers and of the Poisson generator (independent of the export's code).
#include <catch2/catch.hpp>

#include <cstdlib>
#include <regex>
#include <string>

#include "core/error.h"
#include "pcss_regions.h"
#include "poisson_pcss.h"
#include "sampling/poisson_disk.h"
#include "shader/export_source.h"
#include "shader/glslang_compiler.h"
#include "shader/register_plan.h"
#include "shader/source_tree.h"
#include "traversal.h"

TEST_CASE("register plans: each kind's shift and the space, as --register-shift and --register-space take them") {
  const pn::RegisterPlan plan = pn::parse_register_plan("u=32,t=16,b=48", 2);
  CHECK(plan.t == 16);
  CHECK(plan.s == 0);
  CHECK(plan.u == 32);
  CHECK(plan.b == 48);
  CHECK(plan.space == 2);
  CHECK(plan.describe() == "t+16 s+0 u+32 b+48, space 2");
  CHECK(pn::parse_register_plan("", 0).identity());
  CHECK(plan.register_kind(pn::DescriptorKind::storage_buffer, true) == 't');
  CHECK(plan.register_kind(pn::DescriptorKind::storage_buffer, false) == 'u');
  CHECK(plan.register_kind(pn::DescriptorKind::combined_image_sampler, false) == 't');
  for (const char* bad : {"t=1,t=2", "x=1", "t=", "t=4097", "t=1,", "=1", "t1", "t=-1", "t=1 "})
    CHECK_THROWS_AS(pn::parse_register_plan(bad, 0), pn::Error);
  CHECK_THROWS_AS(pn::parse_register_plan("", 32), pn::Error);
  CHECK_THROWS_AS(pn::parse_register_plan("", -1), pn::Error);
}

TEST_CASE("poisson_pcss's HLSL export: named constants, named disks, registers in the plan") {
  const pn::GlslangProcess process;
  const pn::SourceTree tree(PENUMBRA_GLSL_DIR);
  const std::string hlsl =
      pn::export_source(process, tree, "poisson_pcss.glsl", pn::CrossLanguage::hlsl51, "", pn::parse_register_plan("t=16,u=32,b=48", 2));
  // The headers' values, as C++ reads them.
  CHECK(hlsl.find("static const int PN_REGION_EXACT = " + std::to_string(PN_REGION_EXACT) + ";") != std::string::npos);
  CHECK(hlsl.find("static const int PN_POISSON_BLOCKER_SAMPLES = " + std::to_string(PN_POISSON_BLOCKER_SAMPLES) + ";") !=
        std::string::npos);
  CHECK(hlsl.find("static const float PN_REGION_LIT = -1.0f;") != std::string::npos);
  // The disks under their names, each value the generator's.
  const std::pair<const char*, pn::PoissonDisk> disks[] = {
      {"PN_EXPORT_BLOCKER_DISK", pn::poisson_disk(PN_POISSON_BLOCKER_SAMPLES, pn::kPoissonBlockerDiskSeed)},
      {"PN_EXPORT_FILTER_DISK", pn::poisson_disk(PN_POISSON_PCF_SAMPLES, pn::kPoissonFilterDiskSeed)}};
  for (const auto& [name, disk] : disks) {
    const std::string head = std::string("static const float2 ") + name + "[" + std::to_string(disk.points.size()) + "] = {";
    const std::size_t at = hlsl.find(head);
    REQUIRE(at != std::string::npos);
    const std::string line = hlsl.substr(at, hlsl.find('\n', at) - at);
    const std::regex point(R"(float2\(([-0-9.e+]+)f, ([-0-9.e+]+)f\))");
    std::size_t k = 0;
    for (auto m = std::sregex_iterator(line.begin(), line.end(), point); m != std::sregex_iterator(); ++m, ++k) {
      REQUIRE(k < disk.points.size());
      CHECK(std::strtof((*m)[1].str().c_str(), nullptr) == static_cast<float>(disk.points[k].x));
      CHECK(std::strtof((*m)[2].str().c_str(), nullptr) == static_cast<float>(disk.points[k].y));
    }
    CHECK(k == disk.points.size());
  }
  CHECK(hlsl.find("cbuffer PnPoissonPcssExport : register(b52, space2)") != std::string::npos);  // binding 4 + 48
  CHECK(hlsl.find("Texture2D<float4> pnDepthMap : register(t19, space2);") != std::string::npos);  // binding 3 + 16
  CHECK(hlsl.find("RWTexture2D<float> pnVisibility : register(u32, space2);") != std::string::npos);
  CHECK(hlsl.find("poisson_pcss.glsl's own comment") != std::string::npos);
  // Shader model 5.0 has no spaces.
  CHECK_THROWS_AS(pn::export_source(process, tree, "poisson_pcss.glsl", pn::CrossLanguage::hlsl50, "",
                                    pn::parse_register_plan("", 1)),
                  pn::Error);
}

TEST_CASE("fast_pcss's MSL export: the named constants as MSL constants after its includes") {
  const pn::GlslangProcess process;
  const pn::SourceTree tree(PENUMBRA_GLSL_DIR);
  const std::string msl = pn::export_source(process, tree, "fast_pcss.glsl", pn::CrossLanguage::msl, "");
  const std::size_t quad = msl.find("constant int PN_LEAF_QUAD = " + std::to_string(PN_LEAF_QUAD) + ";");
  REQUIRE(quad != std::string::npos);
  CHECK(quad > msl.find("using namespace metal;"));
}
