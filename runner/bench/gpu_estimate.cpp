#include "bench/gpu_estimate.h"

#include <algorithm>
#include <iomanip>
#include <map>

#include "core/error.h"
#include "isa/isa_cost.h"
#include "isa/isa_run.h"
#include "shader/flatten.h"
#include "shader/glslang_compiler.h"
#include "shader/target.h"

namespace pn {
namespace {

// The census buffer's binding in the Vulkan compile: above every pass's own.
constexpr unsigned kCensusBinding = 63;
// ACO's assumed latency of a vector memory load (aco_statistics.cpp, get_wait_counter_info).
constexpr double kLoadLatency = 320.0;

std::string variant_key(const LoopCensusRecord& r) { return r.pass + "|" + define_key(r.defines); }

std::string loop_where(const CensusLoop& l) { return l.file + ":" + std::to_string(l.line); }

}  // namespace

std::optional<GpuEstimateSetup> parse_gpu_estimate(const std::string& value) {
  if (value == "off") return std::nullopt;
  GpuEstimateSetup s;
  const std::size_t slash = value.find('/');
  s.family = value.substr(0, slash);
  if (slash != std::string::npos) {
    const std::string wave = value.substr(slash + 1);
    if (wave != "32" && wave != "64")
      throw Error("--estimate '" + value + "': expected FAMILY, FAMILY/32, FAMILY/64 or off");
    s.wave = std::stoi(wave);
  }
  reference_card(s.family);  // a family it knows
  if (s.wave == 32 && !supports_wave(s.family, 32))
    throw Error("--estimate '" + value + "': " + s.family + " runs wave64 only");
  return s;
}

std::string gpu_estimate_label(const GpuEstimateSetup& setup) {
  return setup.family + " wave" + std::to_string(setup.wave);
}

ReferenceCard reference_card(const std::string& family) {
  // Each family's largest consumer card of its launch: SIMDs (GCN: 4 a CU; RDNA: 2 SIMD32 a CU)
  // and boost clock, from AMD's product pages.
  static const std::map<std::string, ReferenceCard> cards = {
      {"polaris10", {"Radeon RX 480 (36 CUs)", 144, 1.266}},
      {"vega10", {"Radeon RX Vega 64 (64 CUs)", 256, 1.546}},
      {"navi10", {"Radeon RX 5700 XT (40 CUs)", 80, 1.905}},
      {"navi21", {"Radeon RX 6900 XT (80 CUs)", 160, 2.25}},
      {"gfx1100", {"Radeon RX 7900 XTX (96 CUs)", 192, 2.5}}};
  const auto it = cards.find(family);
  if (it == cards.end()) throw Error("estimate family '" + family + "': expected polaris10, vega10, navi10, navi21 or gfx1100");
  return it->second;
}

struct GpuEstimator::Compiled {
  std::string error;  // "" when it compiled
  std::size_t loops = 0;
  IsaFigures figures;
  IsaCostModel cost;
};

GpuEstimator::GpuEstimator(const SourceTree& tree, const GpuEstimateSetup& setup) : tree_(tree), setup_(setup) {
  reference_card(setup.family);  // throws for a family it does not know
}

std::vector<GpuEstimate> GpuEstimator::estimate(const std::vector<const LoopCensus*>& censuses) {
  std::vector<GpuEstimate> out(censuses.size());
  // The passes this call brings: compiled with the same counts the GL run had, all in one child.
  std::vector<IsaProgram> programs;
  std::vector<std::string> keys;
  std::vector<std::size_t> loop_counts;
  std::string failed;  // a reason every new pass shares: no ICD, a target that did not run
  {
    const GlslangProcess glslang;
    for (const LoopCensus* census : censuses)
      for (const LoopCensusRecord& r : census->records) {
        const std::string key = variant_key(r);
        if (compiled_.count(key) || std::find(keys.begin(), keys.end(), key) != keys.end()) continue;
        auto own = std::make_shared<Compiled>();
        try {
          ShaderSource source = standalone_source(flatten(tree_, tree_.locate_in_root(r.pass)), Target::vulkan, r.defines);
          const std::vector<CensusLoop> loops = census_loops(glslang, source, Target::vulkan, kCensusBinding);
          if (loops.size() != r.loops.size())
            throw Error(r.pass + ": " + std::to_string(loops.size()) + " loops for vulkan, " +
                        std::to_string(r.loops.size()) + " counted on GL");
          const CompileResult compiled = compile_with_glslang(glslang, source, Target::vulkan);
          if (!compiled.ok) throw Error(first_error(compiled, r.pass + ": its counted form does not compile for vulkan"));
          IsaEntry entry;
          entry.name = key, entry.file = r.pass, entry.defines = r.defines;
          programs.push_back({entry, compiled.spirv, {}});
          keys.push_back(key);
          loop_counts.push_back(loops.size());
        } catch (const Error& e) {
          own->error = e.what();
          compiled_[key] = own;
        }
      }
  }
  if (!programs.empty()) {
    std::vector<IsaTargetResult> results;
    try {
      results = run_isa(programs, {{setup_.family, setup_.wave}}, 1, [](const std::string&) {});
      if (!results.front().error.empty()) failed = "RADV " + setup_.family + ": " + results.front().error;
    } catch (const Error& e) {
      failed = e.what();
    }
    for (std::size_t p = 0; p < programs.size(); ++p) {
      auto own = std::make_shared<Compiled>();
      own->loops = loop_counts[p];
      if (!failed.empty()) {
        own->error = failed;
      } else {
        const IsaShader& shader = results.front().shaders[p];
        const ShaderExecutable* exe = shader.own(Stage::compute);
        if (!shader.error.empty() || !exe) {
          own->error = programs[p].entry.file + ": " + (shader.error.empty() ? "no compute shader reported" : shader.error);
        } else {
          own->figures = isa_figures(*exe, setup_.family, setup_.wave, results.front().min_wave);
          own->cost = isa_cost_model(exe->isa, own->loops,
                                     issue_model(setup_.family, setup_.wave, results.front().min_wave));
        }
      }
      compiled_[keys[p]] = own;
    }
  }

  const ReferenceCard card = reference_card(setup_.family);
  for (std::size_t c = 0; c < censuses.size(); ++c) {
    GpuEstimate& e = out[c];
    e.ok = true;
    std::map<std::string, std::size_t> pass_row;
    for (const LoopCensusRecord& r : censuses[c]->records) {
      const Compiled& compiled = *compiled_.at(variant_key(r));
      if (!compiled.error.empty()) {
        e.ok = false, e.error = compiled.error;
        break;
      }
      const IsaCostModel& cost = compiled.cost;
      if (!pass_row.count(r.pass)) {
        pass_row[r.pass] = e.passes.size();
        PassEstimate pe;
        pe.pass = r.pass;
        for (std::size_t j = 0; j < r.loops.size(); ++j)
          pe.loops.push_back({loop_where(r.loops[j]), cost.in_loop[j], 0, 0, cost.loop_bodies[j].cycles});
        e.passes.push_back(pe);
      }
      PassEstimate& pe = e.passes[pass_row[r.pass]];
      pe.dispatches += 1;
      pe.vgprs = std::max(pe.vgprs, compiled.figures.vgprs);
      pe.waves_per_simd = compiled.figures.waves;
      pe.unmarked_loops = std::max(pe.unmarked_loops, cost.unmarked_loops);
      const CensusWaves& waves = r.of_wave(setup_.wave);
      const std::size_t loops = r.loops.size();
      const std::size_t wave_count =
          loops ? waves.most.size() / loops : static_cast<std::size_t>((r.invocations() + setup_.wave - 1) / setup_.wave);
      const double occupancy = std::max(1.0, compiled.figures.waves);
      for (std::size_t w = 0; w < wave_count; ++w) {
        double loop_cycles = 0.0, loads = cost.straight.loads;
        for (std::size_t j = 0; j < loops; ++j) {
          if (!cost.in_loop[j]) continue;
          const double most = waves.most[w * loops + j];
          loop_cycles += most * cost.loop_bodies[j].cycles;
          loads += most * cost.loop_bodies[j].loads;
        }
        pe.straight_cycles += cost.straight.cycles;
        pe.loop_cycles += loop_cycles;
        pe.memory_cycles += loads * kLoadLatency / occupancy;
      }
      pe.waves += static_cast<double>(wave_count);
      // Per loop: runs per invocation and the wave's most, averaged over the pass's dispatches.
      for (std::size_t j = 0; j < loops; ++j) {
        double most = 0.0;
        for (std::size_t w = 0; w < wave_count; ++w) most += waves.most[w * loops + j];
        pe.loops[j].mean_runs += r.mean[j];
        pe.loops[j].mean_wave_most += wave_count ? most / static_cast<double>(wave_count) : 0.0;
      }
    }
    if (!e.ok) {
      e.passes.clear();
      continue;
    }
    for (PassEstimate& pe : e.passes) {
      for (LoopEstimate& l : pe.loops)
        l.mean_runs /= std::max(1, pe.dispatches), l.mean_wave_most /= std::max(1, pe.dispatches);
      e.cycles += pe.straight_cycles + pe.loop_cycles + pe.memory_cycles;
    }
    e.ms = e.cycles / (static_cast<double>(card.simds) * card.clock_ghz * 1e9) * 1e3;
  }
  return out;
}

std::vector<GpuEstimate> GpuEstimator::estimate(Comparison& comparison) {
  std::vector<const LoopCensus*> censuses;
  for (const TechniqueResult& r : comparison.results) censuses.push_back(&r.census);
  std::vector<GpuEstimate> out = estimate(censuses);
  for (TechniqueResult& r : comparison.results) r.census.records.clear();
  return out;
}

nlohmann::json gpu_estimate_json(const GpuEstimate& e, const GpuEstimateSetup& setup) {
  if (!e.ok) return {{"error", e.error}};
  nlohmann::json passes = nlohmann::json::array();
  for (const PassEstimate& p : e.passes) {
    nlohmann::json loops = nlohmann::json::array();
    for (const LoopEstimate& l : p.loops)
      loops.push_back({{"where", l.where}, {"in_isa_loop", l.in_loop}, {"mean_runs", l.mean_runs},
                       {"mean_wave_most", l.mean_wave_most}, {"body_cycles", l.body_cycles}});
    passes.push_back({{"pass", p.pass}, {"dispatches", p.dispatches}, {"waves", p.waves}, {"vgprs", p.vgprs},
                      {"waves_per_simd", p.waves_per_simd}, {"straight_cycles", p.straight_cycles},
                      {"loop_cycles", p.loop_cycles}, {"memory_cycles", p.memory_cycles},
                      {"unmarked_isa_loops", p.unmarked_loops}, {"loops", loops}});
  }
  const ReferenceCard card = reference_card(setup.family);
  return {{"family", setup.family}, {"wave", setup.wave}, {"card", card.name}, {"simds", card.simds},
          {"clock_ghz", card.clock_ghz}, {"cycles", e.cycles}, {"ms", e.ms}, {"passes", passes}};
}

const GpuEstimate* estimate_of(const Comparison& comparison, const std::vector<GpuEstimate>& estimates,
                               const std::string& technique) {
  const TechniqueResult* r = comparison.find(technique);
  const std::size_t k = r ? static_cast<std::size_t>(r - comparison.results.data()) : estimates.size();
  return k < estimates.size() && estimates[k].ok ? &estimates[k] : nullptr;
}

std::vector<double> estimate_ratios(const Comparison& comparison, const std::vector<GpuEstimate>& estimates,
                                    const std::string& base) {
  std::vector<double> out(comparison.results.size(), 0.0);
  const GpuEstimate* of_base = estimate_of(comparison, estimates, base);
  const double base_ms = of_base ? of_base->ms : 0.0;
  for (std::size_t k = 0; k < out.size() && k < estimates.size(); ++k)
    if (base_ms > 0 && estimates[k].ok && estimates[k].ms > 0) out[k] = base_ms / estimates[k].ms;
  return out;
}

nlohmann::json ratio_json(double ratio) { return ratio > 0 ? nlohmann::json(ratio) : nlohmann::json(nullptr); }

void print_estimate_cells(std::ostream& out, const std::vector<GpuEstimate>& estimates,
                          const std::vector<double>& ratios, std::size_t i) {
  const bool ok = i < estimates.size() && estimates[i].ok;
  if (ok) out << std::setw(11) << std::fixed << std::setprecision(1) << 1e3 * estimates[i].ms;
  else out << std::setw(11) << "-";
  if (ok && i < ratios.size() && ratios[i] > 0) out << std::setw(10) << std::setprecision(2) << ratios[i];
  else out << std::setw(10) << "-";
}

void print_estimate_note(std::ostream& out, const GpuEstimateSetup& setup, const std::vector<GpuEstimate>& estimates) {
  out << "est.: GPU cost estimate for " << gpu_estimate_label(setup) << " on a " << reference_card(setup.family).name
      << " (loop counts from this run, AMD's compiler on RADV's null device; docs/isa.md)\n";
  std::vector<std::string> said;
  for (const GpuEstimate& e : estimates)
    if (!e.ok && std::find(said.begin(), said.end(), e.error) == said.end()) {
      out << "  no estimate: " << e.error << "\n";
      said.push_back(e.error);
    }
}

}  // namespace pn
