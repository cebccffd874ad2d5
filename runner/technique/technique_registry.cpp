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
      {"exact", "exact PCSS: brute-force blocker search and PCF over the whole regions (pcf.glsl)",
       []() -> Made { return pcss_config(exact_pcss()); }},
      {kPoissonTechnique, "Poisson PCSS: 36 blocker / 64 PCF Poisson-disk samples in one pass, as engines ship it (pnPoissonPcss)",
       []() -> Made { return pcss_config(poisson_pcss()); }},
      {"hqepcss", "HQEPCSS: refined search, min-estimated traversal leaves for blockers, brute-force PCF",
       []() -> Made { return pcss_config(hqepcss()); }},
      {"fast", "Fast PCSS as shipped, one pass (pnFastPcss): exact regions over the aligned mip chain, refined search, leaf 16",
       []() -> Made { return pcss_config(fast_pcss()); }},
      {"fast-paper", "Fast PCSS (seed 000) with the paper's settings: decreased pyramid, power-of-two windows, leaf 8, reuse, blur",
       []() -> Made { return pcss_config(fast_paper_pcss()); }},
      {"fast-no-refine", "Fast PCSS without Step 3's refinement", []() -> Made { return pcss_ablation("fast-no-refine", "refine", "0"); }},
      {"fast-leaf-1", "Fast PCSS with leaf side 1 (no sampled leaves; counts exact)",
       []() -> Made { return pcss_ablation("fast-leaf-1", "leaf", "1"); }},
      {"fast-leaf-8", "Fast PCSS with the paper's leaf side 8", []() -> Made { return pcss_ablation("fast-leaf-8", "leaf", "8"); }},
      {"fast-table-sums", "Fast PCSS with exact blocker sums from the summed-area table (summed_area.glsl)",
       []() -> Made { return pcss_ablation("fast-table-sums", "depth-sums", "table"); }},
      {"fast-pyramid", "Fast PCSS over the paper's decreased pyramid instead of the aligned mip chain",
       []() -> Made { return pcss_ablation("fast-pyramid", "structure", "pyramid"); }},
      {"fast-window-region", "Fast PCSS over the paper's power-of-two windows instead of exact regions",
       []() -> Made { return pcss_ablation("fast-window-region", "region", "window"); }},
      {"fast-centred-region", "Fast PCSS with centred power-of-two windows",
       []() -> Made { return pcss_ablation("fast-centred-region", "region", "centred"); }},
      {"fast-reuse", "Fast PCSS with the paper's reuse (k = 4 for Step 4, 2 for Step 5)",
       []() -> Made { return pcss_ablation("fast-reuse", "reuse", "on"); }},
      {"fast-branch", "Fast PCSS, lit pixels branch out instead of a compacted list",
       []() -> Made { return pcss_ablation("fast-branch", "skip", "branch"); }},
      {"fast-blur", "Fast PCSS with Step 6's depth-aware blur, its radius following the filter size",
       []() -> Made { return pcss_ablation("fast-blur", "blur", "on"); }},
      {"vogel", "Vogel PCSS: 16 blocker / 32 PCF golden-angle samples rotated per pixel by interleaved gradient "
                "noise, in one pass, as three.js, Godot and bgfx ship it (pnVogelPcss)",
       []() -> Made { return pcss_config(vogel_pcss()); }},
      {"pcf", "hard shadow, 2x2 bilinear PCF (pcf.glsl): what a hardware shadow sampler gives, seed 003's baseline",
       []() -> Made { return pcf_config("pcf"); }},
      {"vsm", "variance shadow map (seed 003): blurred moments, Chebyshev bound, linstep(0.2) reduction, depth-range bound (vsm.glsl)",
       []() -> Made { return vsm_config(VsmKind::vsm, "vsm"); }},
      {"evsm", "exponential VSM, 4 components (c+ 40, c- 5) over the light's near..far, same blur and bounds (vsm.glsl)",
       []() -> Made { return vsm_config(VsmKind::evsm4, "evsm"); }},
      {"evsm2", "exponential VSM, 2 components (c+ 40): the positive warp only, half the memory of evsm (vsm.glsl)",
       []() -> Made { return vsm_config(VsmKind::evsm2, "evsm2"); }},
      {"savsm", "summed-area variance soft shadows (seed 004): fixed-point moments table, the search square's min as the blocker, linstep(0.2), depth-range bound (savsm.glsl)",
       []() -> Made { return savsm_config("savsm", {}); }},
      {"savsm-table", "savsm with the seed's Chebyshev blocker estimate from the table (mu - s2 / (t - mu)) instead of the min",
       []() -> Made { return savsm_config("savsm-table", {{"blocker", "table"}}); }},
      {"savsm-float", "savsm on a float moments table of centred depths (Lauritzen's fp32 table): the precision ablation",
       []() -> Made { return savsm_config("savsm-float", {{"table", "float"}}); }},
      {"savsm-raw", "savsm without light-bleeding reduction (bleeding=0)",
       []() -> Made { return savsm_config("savsm-raw", {{"bleeding", "0"}}); }},
      {"backprojection", "back-projection over the min/max mip chain (issue 28): the fraction of 64 light samples "
                         "the map's surface leaves visible (patches, walls within 3 texel widths), a bitmask "
                         "(backprojection.glsl)",
       []() -> Made { return backprojection_config("backprojection"); }},
      {kStagedPoissonTechnique, "Poisson PCSS through the staged passes (a map copy, a pass a step): the same output, "
                                "the bench's baseline before issue 24",
       []() -> Made {
         PcssSettings s = poisson_pcss();
         s.name = kStagedPoissonTechnique;
         s.staged = true;
         return pcss_config(s);
       }},
      {"fast-all-off", "Fast PCSS with every improvement off: must equal exact PCSS (the wiring check)",
       []() -> Made { return pcss_config(fast_pcss_all_off()); }, false},
  };
  return entries;
}

std::unique_ptr<TechniqueConfig> parse_technique(const std::string& technique) {
  size_t colon = technique.find(':');
  const std::string name = technique.substr(0, colon);
  std::unique_ptr<TechniqueConfig> config =
      find_named(technique_registry(), name, "unknown technique '" + name + "'").make();
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

std::vector<std::string> render_techniques() {
  return {"exact", "poisson", "hqepcss", "fast-paper", "fast", "savsm", "backprojection"};
}

std::vector<std::string> bench_techniques() {
  std::vector<std::string> out;
  for (const TechniqueEntry& e : technique_registry())
    if (e.benched) out.push_back(e.name);
  return out;
}

}  // namespace pn
