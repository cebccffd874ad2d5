#include "technique/technique_registry.h"

#include "core/error.h"
#include "core/named.h"
#include "technique/backprojection_technique.h"
#include "technique/pcss_technique.h"
#include "technique/pcf_technique.h"
#include "technique/savsm_technique.h"
#include "technique/vsm_technique.h"

namespace pn {

const std::vector<TechniqueEntry>& technique_registry() {
  using Made = std::unique_ptr<TechniqueConfig>;
  static const std::vector<TechniqueEntry> entries{
      {.name = "exact", .summary = "exact PCSS: brute-force blocker search and PCF over the whole regions (pcf.glsl)",
       .make = []() -> Made { return pcss_config(exact_pcss()); }},
      {.name = kPoissonTechnique, .summary = "Poisson PCSS: 36 blocker / 64 PCF Poisson-disk samples in one pass, as engines ship it (pnPoissonPcss)",
       .make = []() -> Made { return pcss_config(poisson_pcss()); },
       .frontier = {":blocker-samples=8:filter-samples=8", ":blocker-samples=16:filter-samples=16",
                     ":blocker-samples=32:filter-samples=32", ":blocker-samples=64:filter-samples=64", ""}},
      {.name = "hqepcss", .summary = "HQEPCSS: refined search, min-estimated traversal leaves for blockers, brute-force PCF",
       .make = []() -> Made { return pcss_config(hqepcss()); }},
      {.name = "fast-paper", .summary = "Fast PCSS (seed 000) with the paper's settings: decreased pyramid, power-of-two windows, leaf 8, reuse, blur",
       .make = []() -> Made { return pcss_config(fast_paper_pcss()); }, .family = "fast", .frontier = {}},
      {.name = "fast", .summary = "Fast PCSS as shipped, one pass (pnFastPcss): exact regions over the aligned mip chain, refined search, "
                "leaf 16, leaves of at least the region's side / 12 of 4 samples each (the work budget), the receiver-plane depth bias (slopes to tan 1; the staged passes need receiver-plane=off)",
       .make = []() -> Made { return pcss_config(shipped_fast_pcss()); },
       .frontier = {"", ":receiver-plane=off", ":grid=4", ":grid=2", ":leaf=4", ":leaf=8", ":leaf=32",
                     ":leaf-divisor=0:leaf-mode=sampled", ":leaf-divisor=16"}},
      {.name = "fast-no-refine", .summary = "Fast PCSS without Step 3's refinement", .make = []() -> Made { return pcss_ablation("fast-no-refine", "refine", "0"); },
       .family = "fast", .rendered = false, .frontier = {}},
      {.name = "fast-leaf-1", .summary = "Fast PCSS with leaf side 1 (no sampled leaves; counts exact)",
       .make = []() -> Made { return pcss_ablation("fast-leaf-1", "leaf", "1"); },
       .family = "fast", .rendered = false, .frontier = {}},
      {.name = "fast-leaf-8", .summary = "Fast PCSS with the paper's leaf side 8", .make = []() -> Made { return pcss_ablation("fast-leaf-8", "leaf", "8"); },
       .family = "fast", .rendered = false, .frontier = {}},
      {.name = "fast-table-sums", .summary = "Fast PCSS with exact blocker sums from the summed-area table (summed_area.glsl)",
       .make = []() -> Made { return pcss_ablation("fast-table-sums", "depth-sums", "table"); },
       .family = "fast", .rendered = false, .frontier = {}},
      {.name = "fast-pyramid", .summary = "Fast PCSS over the paper's decreased pyramid instead of the aligned mip chain",
       .make = []() -> Made { return pcss_ablation("fast-pyramid", "structure", "pyramid"); },
       .family = "fast", .rendered = false, .frontier = {}},
      {.name = "fast-window-region", .summary = "Fast PCSS over the paper's power-of-two windows instead of exact regions",
       .make = []() -> Made { return pcss_ablation("fast-window-region", "region", "window"); },
       .family = "fast", .rendered = false, .frontier = {}},
      {.name = "fast-centred-region", .summary = "Fast PCSS with centred power-of-two windows",
       .make = []() -> Made { return pcss_ablation("fast-centred-region", "region", "centred"); },
       .family = "fast", .rendered = false, .frontier = {}},
      {.name = "fast-reuse", .summary = "Fast PCSS with the paper's reuse (k = 4 for Step 4, 2 for Step 5)",
       .make = []() -> Made { return pcss_ablation("fast-reuse", "reuse", "on"); },
       .family = "fast", .rendered = false, .frontier = {}},
      {.name = "fast-branch", .summary = "Fast PCSS, lit pixels branch out instead of a compacted list",
       .make = []() -> Made { return pcss_ablation("fast-branch", "skip", "branch"); },
       .family = "fast", .rendered = false, .frontier = {}},
      {.name = "fast-blur", .summary = "Fast PCSS with Step 6's depth-aware blur, its radius following the filter size",
       .make = []() -> Made { return pcss_ablation("fast-blur", "blur", "on"); },
       .family = "fast", .rendered = false, .frontier = {}},
      {.name = "vogel", .summary = "Vogel PCSS: 16 blocker / 32 PCF golden-angle samples rotated per pixel by interleaved gradient "
                "noise, in one pass, as three.js, Godot and bgfx ship it (pnVogelPcss)",
       .make = []() -> Made { return pcss_config(vogel_pcss()); },
       .rendered = false, .frontier = {":blocker-samples=8:filter-samples=8",
                     ":blocker-samples=16:filter-samples=16", ":blocker-samples=32:filter-samples=32",
                     ":blocker-samples=64:filter-samples=64", ":blocker-samples=128:filter-samples=128", "",
                     ":receiver-plane=1"}},
      {.name = "pcf", .summary = "hard shadow, 2x2 bilinear PCF (pcf.glsl): what a hardware shadow sampler gives, seed 003's baseline",
       .make = []() -> Made { return pcf_config("pcf"); }, .rendered = false},
      {.name = "vsm", .summary = "variance shadow map (seed 003): blurred moments, Chebyshev bound, linstep(0.2) reduction, depth-range bound (vsm.glsl)",
       .make = []() -> Made { return vsm_config(VsmKind::vsm, "vsm"); }, .rendered = false},
      {.name = "evsm", .summary = "exponential VSM, 4 components (c+ 40, c- 5) over the light's near..far, same blur and bounds (vsm.glsl)",
       .make = []() -> Made { return vsm_config(VsmKind::evsm4, "evsm"); }, .family = "vsm", .rendered = false},
      {.name = "evsm2", .summary = "exponential VSM, 2 components (c+ 40): the positive warp only, half the memory of evsm (vsm.glsl)",
       .make = []() -> Made { return vsm_config(VsmKind::evsm2, "evsm2"); },
       .family = "vsm", .rendered = false, .frontier = {}},
      {.name = "savsm", .summary = "summed-area variance soft shadows (seed 004): fixed-point moments table, the search square's min as the blocker, linstep(0.2), depth-range bound (savsm.glsl)",
       .make = []() -> Made { return savsm_config("savsm", {}); }},
      {.name = "savsm-table", .summary = "savsm with the seed's Chebyshev blocker estimate from the table (mu - s2 / (t - mu)) instead of the min",
       .make = []() -> Made { return savsm_config("savsm-table", {{"blocker", "table"}}); },
       .family = "savsm", .rendered = false, .frontier = {}},
      {.name = "savsm-float", .summary = "savsm on a float moments table of centred depths (Lauritzen's fp32 table): the precision ablation",
       .make = []() -> Made { return savsm_config("savsm-float", {{"table", "float"}}); },
       .family = "savsm", .rendered = false, .frontier = {}},
      {.name = "savsm-raw", .summary = "savsm without light-bleeding reduction (bleeding=0)",
       .make = []() -> Made { return savsm_config("savsm-raw", {{"bleeding", "0"}}); },
       .family = "savsm", .rendered = false, .frontier = {}},
      {.name = "backprojection", .summary = "back-projection over the min/max mip chain (issues 28, 42): the fraction of 256 light "
                         "samples that the map's texels, slabs down to its back-face layer, leave visible, a "
                         "bitmask (backprojection.glsl; layer=none: the map's surface alone)",
       .make = []() -> Made { return backprojection_config("backprojection"); },
       .frontier = {":samples=64", "", ":tolerance=0.2", ":layer=none"}},
      {.name = kStagedPoissonTechnique, .summary = "Poisson PCSS through the staged passes (a map copy, a pass a step): the same output, "
                                "the bench's baseline before issue 24",
       .make = []() -> Made {
         PcssSettings s = poisson_pcss();
         s.name = kStagedPoissonTechnique;
         s.staged = true;
         return pcss_config(s);
       }, .family = kPoissonTechnique, .rendered = false, .frontier = {}},
      {.name = "fast-all-off", .summary = "Fast PCSS with every improvement off: must equal exact PCSS (the wiring check)",
       .make = []() -> Made { return pcss_config(fast_pcss_all_off()); },
       .family = "fast", .rendered = false, .benched = false, .frontier = {}},
  };
  return entries;
}

namespace {

const TechniqueEntry& entry_of(const std::string& technique) {
  const std::string name = technique.substr(0, technique.find(':'));
  return find_named(technique_registry(), name, "unknown technique '" + name + "'");
}

}  // namespace

std::unique_ptr<TechniqueConfig> parse_technique(const std::string& technique) {
  size_t colon = technique.find(':');
  std::unique_ptr<TechniqueConfig> config = entry_of(technique).make();
  config->rename(technique);
  while (colon != std::string::npos) {
    const size_t next = technique.find(':', colon + 1);
    const std::string item = technique.substr(colon + 1, next == std::string::npos ? std::string::npos : next - colon - 1);
    const size_t equals = item.find('=');
    if (equals == std::string::npos) throw Error("technique '" + technique + "': '" + item + "': expected key=value");
    config->set(item.substr(0, equals), item.substr(equals + 1));
    colon = next;
  }
  config->validate();
  return config;
}

std::vector<const TechniqueConfig*> chosen_or_default_techniques(
    const std::vector<std::shared_ptr<const TechniqueConfig>>& chosen, const std::vector<std::string>& defaults,
    std::vector<std::unique_ptr<TechniqueConfig>>& parsed) {
  std::vector<const TechniqueConfig*> out;
  for (const auto& c : chosen) out.push_back(c.get());
  if (!out.empty()) return out;
  for (const std::string& technique : defaults) parsed.push_back(parse_technique(technique));
  for (const auto& c : parsed) out.push_back(c.get());
  return out;
}

std::string technique_family(const std::string& technique) {
  return entry_of(technique).family_name();
}

std::vector<std::string> render_techniques() {
  std::vector<std::string> out;
  for (const TechniqueEntry& e : technique_registry())
    if (e.rendered) out.push_back(e.name);
  return out;
}

std::vector<std::string> frontier_techniques() {
  std::vector<std::string> out;
  for (const TechniqueEntry& e : technique_registry())
    for (const char* variant : e.frontier) out.push_back(std::string(e.name) + variant);
  return out;
}

std::vector<std::string> bench_techniques() {
  std::vector<std::string> out;
  for (const TechniqueEntry& e : technique_registry())
    if (e.benched) out.push_back(e.name);
  return out;
}

}  // namespace pn
