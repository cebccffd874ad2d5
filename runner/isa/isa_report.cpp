#include "isa/isa_report.h"

#include <cstdio>
#include <sstream>

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
         "| latency | inv. throughput |\n"
         "| --- | --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
  for (size_t i = 0; i < programs.size(); ++i) {
    const IsaEntry& e = programs[i].entry;
    const IsaShader& s = result.shaders[i];
    out << "| " << e.name << " | " << isa_kind_name(e.kind) << " | " << stage_name(e.stage);
    const ShaderExecutable* own = s.own(e.stage);
    if (!s.error.empty() || !own) {
      out << " | " << (s.error.empty() ? "no executable of its stage" : s.error) << " |||||||||||\n";
      continue;
    }
    const IsaFigures f = isa_figures(*own, result.target.wave, result.min_wave);
    out << " | " << number(f.vgprs) << " | " << number(f.sgprs) << " | " << number(f.spilled_vgprs + f.spilled_sgprs)
        << " | " << (f.scratch > 0 ? kb(f.scratch) : "0") << " | " << kb(f.code) << " | " << number(f.instructions)
        << " | " << number(f.branches) << " | " << number(f.image) << " | " << number(f.waves) << " | "
        << number(f.latency) << " | " << number(f.throughput) << " |\n";
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
        const IsaFigures f = isa_figures(*own, r.target.wave, r.min_wave);
        s["figures"] = {{"vgprs", f.vgprs}, {"sgprs", f.sgprs}, {"spilled_vgprs", f.spilled_vgprs},
                        {"spilled_sgprs", f.spilled_sgprs}, {"scratch_bytes", f.scratch}, {"code_bytes", f.code},
                        {"instructions", f.instructions}, {"branches", f.branches}, {"image_instructions", f.image},
                        {"waves_per_simd", f.waves}, {"latency", f.latency}, {"inverse_throughput", f.throughput}};
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
  for (const IsaTargetResult& r : results) {
    if (!r.error.empty()) continue;
    const std::filesystem::path sub = dir / (r.target.family + "-wave" + std::to_string(r.target.wave));
    std::filesystem::create_directories(sub);
    for (size_t i = 0; i < programs.size() && i < r.shaders.size(); ++i)
      if (const ShaderExecutable* own = r.shaders[i].own(programs[i].entry.stage))
        write_file_atomically(sub / file_name(programs[i].entry), own->isa);
  }
}

}  // namespace pn
