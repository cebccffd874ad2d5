#include "isa/isa_entries.h"

#include <algorithm>
#include <filesystem>

#include "core/error.h"
#include "passes/pcss_one_call.h"  // PN_ONE_CALL_*

namespace fs = std::filesystem;

namespace pn {

const char* isa_kind_name(IsaKind kind) {
  switch (kind) {
    case IsaKind::engine: return "engine";
    case IsaKind::runner: return "runner";
    case IsaKind::pass: return "pass";
  }
  return "?";
}

IsaKind parse_isa_kind(const std::string& name) {
  for (IsaKind k : {IsaKind::engine, IsaKind::runner, IsaKind::pass})
    if (name == isa_kind_name(k)) return k;
  throw Error("--kind '" + name + "': expected engine, runner or pass");
}

std::string IsaEntry::label() const {
  return name + " " + isa_kind_name(kind) + " " + stage_name(stage);
}

namespace {

const char* kFullScreen = "passes/full_screen.vert";

// Files of `dir` (under the root) with extension `ext`, sorted.
std::vector<std::string> files_in(const SourceTree& tree, const std::string& dir, const std::string& ext) {
  std::vector<std::string> out;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(tree.root() / dir, ec))
    if (e.path().extension() == ext) out.push_back(dir + "/" + e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

bool exists(const SourceTree& tree, const std::string& file) { return fs::exists(tree.root() / file); }

// A fragment entry's vertex shader: X.vert beside it, else the full-screen triangle.
std::string vertex_of(const SourceTree& tree, const std::string& frag) {
  const std::string own = frag.substr(0, frag.size() - 5) + ".vert";
  return exists(tree, own) ? own : kFullScreen;
}

// An export that makes one of several calls by a block field: each call an engine compiles alone
// (vsm_call.glsl's pnVsm, pnEvsm2 and pnEvsm4; backprojection_call.glsl's two overloads).
struct EngineVariant {
  const char* exported;
  const char* name;
  Define define;
};
const EngineVariant kEngineVariants[] = {
    {"vsm", "vsm", {"PN_EXPORT_VSM_KIND", "PN_EXPORT_VSM"}},
    {"vsm", "evsm2", {"PN_EXPORT_VSM_KIND", "PN_EXPORT_EVSM2"}},
    {"vsm", "evsm4", {"PN_EXPORT_VSM_KIND", "PN_EXPORT_EVSM4"}},
    {"backprojection", "backprojection", {"PN_EXPORT_BACKPROJECTION_LAYERS", "1"}},
    {"backprojection", "backprojection-slabs", {"PN_EXPORT_BACKPROJECTION_LAYERS", "2"}},
};

// The technique passes the runner's registry runs, by technique, for its default row as the runner
// compiles it: the module's defaults as constants (PN_PCSS_ENGINE_FORM, PN_SAVSM_ENGINE_FORM,
// PN_BACKPROJECTION_ENGINE_FORM with the second layer's slabs; exact PCSS's, PCF's and VSM's calls
// have plain parameters).
struct RunnerCall {
  const char* name;
  const char* pass;  // without extension: .comp and .frag
  std::vector<Define> defines;
};
std::vector<RunnerCall> runner_calls() {
  const auto one_call = [](int call) {
    std::vector<Define> d{{"PN_PCSS_ONE_CALL", std::to_string(call)}, {"PN_PCSS_WRITE_WORK", "false"}};
    if (call != PN_ONE_CALL_EXACT) d.push_back({"PN_PCSS_ENGINE_FORM", "1"});
    return d;
  };
  return {{"fast", "passes/pcss_one_call", one_call(PN_ONE_CALL_FAST)},
          {"poisson", "passes/pcss_one_call", one_call(PN_ONE_CALL_POISSON)},
          {"vogel", "passes/pcss_one_call", one_call(PN_ONE_CALL_VOGEL)},
          {"exact", "passes/pcss_one_call", one_call(PN_ONE_CALL_EXACT)},
          {"hqepcss", "passes/pcss_one_call", one_call(PN_ONE_CALL_HQEPCSS)},
          {"pcf", "passes/pcf_shade", {}},
          {"vsm", "passes/vsm_shade", {}},
          {"savsm", "passes/savsm_shade", {{"PN_SAVSM_ENGINE_FORM", "1"}}},
          {"backprojection", "passes/backprojection_shade",
           {{"PN_BACKPROJECTION_SHADE_SLABS", "1"}, {"PN_BACKPROJECTION_ENGINE_FORM", "1"}}}};
}

}  // namespace

std::vector<IsaEntry> isa_entries(const SourceTree& tree) {
  std::vector<IsaEntry> out;
  const Define engine{"PN_EXPORT_ENGINE", "1"};
  for (const std::string& call : files_in(tree, "exports", ".glsl")) {
    const std::string stem = fs::path(call).stem().string();
    if (stem.size() < 6 || stem.substr(stem.size() - 5) != "_call") continue;
    const std::string name = stem.substr(0, stem.size() - 5);
    std::vector<std::pair<std::string, std::vector<Define>>> calls;
    for (const EngineVariant& v : kEngineVariants)
      if (name == v.exported) calls.push_back({v.name, {engine, v.define}});
    if (calls.empty()) calls.push_back({name, {engine}});
    for (const auto& [label, defines] : calls) {
      if (exists(tree, "exports/" + name + ".comp"))
        out.push_back({label, IsaKind::engine, Stage::compute, "exports/" + name + ".comp", "", defines, name});
      if (exists(tree, "exports/" + name + ".frag"))
        out.push_back({label, IsaKind::engine, Stage::fragment, "exports/" + name + ".frag", kFullScreen, defines, name});
    }
  }
  for (const RunnerCall& r : runner_calls()) {
    const std::string comp = std::string(r.pass) + ".comp", frag = std::string(r.pass) + ".frag";
    if (exists(tree, comp)) out.push_back({r.name, IsaKind::runner, Stage::compute, comp, "", r.defines, ""});
    if (exists(tree, frag)) out.push_back({r.name, IsaKind::runner, Stage::fragment, frag, kFullScreen, r.defines, ""});
  }
  for (const char* dir : {"passes", "exports"}) {
    for (const std::string& comp : files_in(tree, dir, ".comp")) out.push_back({comp, IsaKind::pass, Stage::compute, comp, "", {}, ""});
    for (const std::string& frag : files_in(tree, dir, ".frag"))
      out.push_back({frag, IsaKind::pass, Stage::fragment, frag, vertex_of(tree, frag), {}, ""});
  }
  return out;
}

}  // namespace pn
