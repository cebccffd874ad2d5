#include "isa/isa_report.h"

#include <cstdio>
#include <sstream>

#include "core/content_hash.h"
#include "core/error.h"
#include "core/write_file.h"

namespace pn {

namespace {

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, v == static_cast<long long>(v) ? "%.0f" : "%.1f", v);
  return buf;
}

std::string kb(double bytes) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f KB", bytes / 1024.0);
  return buf;
}

// "87 / 144, 30 / 53 (sum 197)": each loop's own body in program order, an inner loop after a '>'
// for each loop holding it; "—" without loops.
std::string loop_bodies(const IsaFigures& f) {
  if (f.loops.empty()) return "—";
  std::string s;
  for (const IsaLoop& l : f.loops) {
    if (!s.empty()) s += ", ";
    s += std::string(l.depth, '>') + number(l.instructions) + " / " + number(l.cycles);
  }
  return s + (f.loops.size() > 1 ? " (sum " + number(f.loop_cycles_sum) + ")" : "");
}

std::string file_name(const IsaEntry& e) {
  std::string s = e.label();
  for (char& c : s)
    if (c == '/' || c == ' ') c = '_';
  return s + ".s";
}

}  // namespace

std::string isa_table(const std::vector<IsaProgram>& programs, const IsaTargetResult& result) {
  std::ostringstream out;
  out << "### " << result.target.family << ", wave" << result.target.wave << " — "
      << (result.error.empty() ? result.device : result.error) << "\n\n";
  if (!result.error.empty()) return out.str();
  out << "| entry | kind | stage | VGPRs | SGPRs | spills | scratch | code | instructions | branches | image | waves/SIMD "
         "| latency | inv. throughput | loop bodies: instr. / cycles |\n"
         "| --- | --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- |\n";
  for (size_t i = 0; i < programs.size(); ++i) {
    const IsaEntry& e = programs[i].entry;
    const IsaShader& s = result.shaders[i];
    out << "| " << e.name << " | " << isa_kind_name(e.kind) << " | " << stage_name(e.stage);
    const ShaderExecutable* own = s.own(e.stage);
    if (!s.error.empty() || !own) {
      out << " | " << (s.error.empty() ? "no executable of its stage" : s.error) << " ||||||||||||\n";
      continue;
    }
    const IsaFigures f = isa_figures(*own, result.target.family, result.target.wave, result.min_wave);
    out << " | " << number(f.vgprs) << " | " << number(f.sgprs) << " | " << number(f.spilled_vgprs + f.spilled_sgprs)
        << " | " << (f.scratch > 0 ? kb(f.scratch) : "0") << " | " << kb(f.code) << " | " << number(f.instructions)
        << " | " << number(f.branches) << " | " << number(f.image) << " | " << number(f.waves) << " | "
        << number(f.latency) << " | " << number(f.throughput) << " | " << loop_bodies(f) << " |\n";
  }
  return out.str();
}

nlohmann::json isa_json(const std::vector<IsaProgram>& programs, const std::vector<IsaTargetResult>& results) {
  using nlohmann::json;
  json targets = json::array();
  for (const IsaTargetResult& r : results) {
    json shaders = json::array();
    for (size_t i = 0; i < programs.size() && i < r.shaders.size(); ++i) {
      const IsaEntry& e = programs[i].entry;
      json defines = json::object();
      for (const Define& d : e.defines) defines[d.name] = d.value;
      json s = {{"name", e.name}, {"kind", isa_kind_name(e.kind)}, {"stage", stage_name(e.stage)},
                {"file", e.file}, {"defines", defines}, {"error", r.shaders[i].error}};
      if (const ShaderExecutable* own = r.shaders[i].own(e.stage)) {
        const IsaFigures f = isa_figures(*own, r.target.family, r.target.wave, r.min_wave);
        s["figures"] = {{"vgprs", f.vgprs}, {"sgprs", f.sgprs}, {"spilled_vgprs", f.spilled_vgprs},
                        {"spilled_sgprs", f.spilled_sgprs}, {"scratch_bytes", f.scratch}, {"code_bytes", f.code},
                        {"instructions", f.instructions}, {"branches", f.branches}, {"image_instructions", f.image},
                        {"waves_per_simd", f.waves}, {"latency", f.latency}, {"inverse_throughput", f.throughput}};
        json loops = json::array();
        for (const IsaLoop& l : f.loops)
          loops.push_back({{"depth", l.depth}, {"instructions", l.instructions}, {"issue_cycles", l.cycles},
                           {"vector_memory_loads", l.loads}});
        s["figures"]["loops"] = loops;
        json stats = json::object();
        for (const auto& [name, value] : own->statistics) stats[name] = value;
        s["statistics"] = stats;
      }
      shaders.push_back(s);
    }
    targets.push_back({{"family", r.target.family}, {"wave", r.target.wave}, {"device", r.device}, {"error", r.error},
                       {"shaders", shaders}});
  }
  return {{"compiler", "Mesa RADV null device (ACO)"}, {"targets", targets}};
}

void write_isa_files(const std::filesystem::path& dir, const std::vector<IsaProgram>& programs,
                     const std::vector<IsaTargetResult>& results) {
  const std::filesystem::path manifest_path = dir / kIsaManifestName;
  std::error_code ec;
  std::filesystem::remove(manifest_path, ec);
  if (ec) throw Error("--isa: '" + manifest_path.string() + "' cannot be removed (" + ec.message() + ")");
  std::string manifest;
  for (const IsaTargetResult& r : results) {
    if (!r.error.empty()) continue;
    const std::string sub = r.target.family + "-wave" + std::to_string(r.target.wave);
    std::filesystem::create_directories(dir / sub);
    for (size_t i = 0; i < programs.size() && i < r.shaders.size(); ++i)
      if (const ShaderExecutable* own = r.shaders[i].own(programs[i].entry.stage)) {
        const std::string name = sub + "/" + file_name(programs[i].entry);
        write_file_atomically(dir / name, own->isa);
        manifest += content_hash(own->isa) + "  " + name + "\n";
      }
  }
  write_file_atomically(manifest_path, manifest);
}

}  // namespace pn
