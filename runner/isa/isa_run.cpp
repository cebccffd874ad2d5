#include "isa/isa_run.h"

#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/error.h"
#include "shader/flatten.h"

namespace fs = std::filesystem;
using nlohmann::json;

namespace pn {

namespace {

std::vector<std::uint32_t> spirv_of(const GlslangProcess& glslang, const SourceTree& tree, const std::string& file,
                                    const std::vector<Define>& defines) {
  const CompileResult r =
      compile_with_glslang(glslang, standalone_source(flatten(tree, file), Target::vulkan, defines), Target::vulkan);
  if (!r.ok) throw Error(first_error(r, file + ": does not compile for vulkan"), ExitCode::failed);
  return r.spirv;
}

Stage stage_named(const std::string& name) {
  for (Stage s : {Stage::vertex, Stage::fragment})
    if (name == stage_name(s)) return s;
  return Stage::compute;
}

json executable_json(const ShaderExecutable& e) {
  json stats = json::array();
  for (const auto& [name, value] : e.statistics) stats.push_back({name, value});
  return {{"stage", stage_name(e.stage)}, {"name", e.name}, {"statistics", stats}, {"isa", e.isa}};
}

ShaderExecutable executable_from(const json& j) {
  ShaderExecutable e;
  e.stage = stage_named(j.at("stage").get<std::string>());
  e.name = j.at("name").get<std::string>();
  for (const json& s : j.at("statistics")) e.statistics.emplace_back(s.at(0).get<std::string>(), s.at(1).get<double>());
  e.isa = j.at("isa").get<std::string>();
  return e;
}

// The signals that end the runner (core/write_file.h): while the children compile, the parent
// notes one instead, ends its children, removes their temporaries, then lets it end the process
// as before (issue 54 X2: the children ran on as orphans and left their results for good).
constexpr int kEndingSignals[] = {SIGINT, SIGTERM, SIGHUP};
volatile std::sig_atomic_t g_ending_signal = 0;  // a handler reaches nothing else
extern "C" void note_ending_signal(int signal) { g_ending_signal = signal; }

class ParentSignals {
 public:
  ParentSignals() {
    g_ending_signal = 0;
    struct sigaction note {};
    note.sa_handler = note_ending_signal;
    sigemptyset(&note.sa_mask);
    note.sa_flags = 0;  // no SA_RESTART: the parent's waitpid returns EINTR
    for (std::size_t k = 0; k < std::size(kEndingSignals); ++k) sigaction(kEndingSignals[k], &note, &before_[k]);
  }
  ~ParentSignals() {
    for (std::size_t k = 0; k < std::size(kEndingSignals); ++k) sigaction(kEndingSignals[k], &before_[k], nullptr);
  }
  ParentSignals(const ParentSignals&) = delete;
  ParentSignals& operator=(const ParentSignals&) = delete;
  int noted() const { return g_ending_signal; }

 private:
  struct sigaction before_[std::size(kEndingSignals)] {};
};

// The child: compiles every program on `target`, writes {"device", "min_wave", "shaders"} to `out`.
[[noreturn]] void child(const std::vector<IsaProgram>& programs, const RadvTarget& target, const std::string& manifest,
                        const std::string& out, const std::string& runtime_dir) {
  // The parent's way with signals is its own (ParentSignals): a child ends on them, and with its
  // parent, whatever ends the parent (SIGKILL included).
  for (int signal : kEndingSignals) std::signal(signal, SIG_DFL);
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  // The driver's own lines (an abort's reason) into OUT.err, for the parent's message.
  std::fflush(stderr);
  if (std::freopen((out + ".err").c_str(), "w", stderr) == nullptr) std::_Exit(1);
  std::setvbuf(stderr, nullptr, _IONBF, 0);  // an abort flushes nothing
  int code = 0;
  try {
    set_radv_environment(target, manifest, runtime_dir);
    const RadvNullDevice device;
    json shaders = json::array();
    const bool wave_ok = target.wave == 64 || device.min_wave() <= target.wave;
    for (const IsaProgram& p : programs) {
      json shader = {{"error", ""}, {"executables", json::array()}};
      if (!wave_ok) {
        shader["error"] = "no wave" + std::to_string(target.wave) + " on this family";
      } else {
        try {
          const std::vector<ShaderExecutable> made =
              p.entry.stage == Stage::fragment ? device.compile_graphics(p.vertex, p.spirv, p.entry.label())
                                               : device.compile_compute(p.spirv, p.entry.label());
          for (const ShaderExecutable& e : made) shader["executables"].push_back(executable_json(e));
        } catch (const Error& e) {
          shader["error"] = e.what();
        }
      }
      shaders.push_back(shader);
    }
    std::ofstream(out) << json{{"device", device.device_name()}, {"min_wave", device.min_wave()}, {"shaders", shaders}};
  } catch (const std::exception& e) {
    std::ofstream(out) << json{{"error", e.what()}};
    code = 1;
  }
  std::_Exit(code);
}

IsaTargetResult read_child(const RadvTarget& target, const std::string& file, int status, size_t count) {
  IsaTargetResult r;
  r.target = target;
  if (WIFSIGNALED(status)) {
    std::ifstream said(file + ".err");  // the driver's last words, when it left any
    std::string line;
    std::getline(said, line);
    r.error = "the driver died (signal " + std::to_string(WTERMSIG(status)) + (line.empty() ? "" : ": " + line) + ")";
  } else {
    std::ifstream in(file);
    json j = json::parse(in, nullptr, false);
    if (j.is_discarded() || !j.is_object()) {
      r.error = "the child wrote no result (exit " + std::to_string(WEXITSTATUS(status)) + ")";
    } else if (j.contains("error")) {
      r.error = j["error"].get<std::string>();
    } else {
      r.device = j["device"].get<std::string>();
      r.min_wave = j["min_wave"].get<int>();
      for (const json& s : j["shaders"]) {
        IsaShader shader;
        shader.error = s["error"].get<std::string>();
        for (const json& e : s["executables"]) shader.executables.push_back(executable_from(e));
        r.shaders.push_back(std::move(shader));
      }
    }
  }
  if (r.error.empty() && r.shaders.size() != count) r.error = "the child's result lists " + std::to_string(r.shaders.size()) + " shaders, not " + std::to_string(count);
  if (!r.error.empty()) r.shaders.assign(count, IsaShader{r.error, {}});
  return r;
}

// A fresh directory for the children's results and RADV's XDG_RUNTIME_DIR, removed on the way out.
class TempDir {
 public:
  TempDir() {
    std::string pattern = (fs::temp_directory_path() / "penumbra-isa-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw Error("isa: cannot make a temporary directory under " + fs::temp_directory_path().string(), ExitCode::failed);
    path_ = pattern;
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

}  // namespace

std::vector<IsaProgram> compile_isa_programs(const GlslangProcess& glslang, const SourceTree& tree,
                                             const std::vector<IsaEntry>& entries) {
  std::vector<IsaProgram> out;
  for (const IsaEntry& e : entries) {
    IsaProgram p{e, spirv_of(glslang, tree, e.file, e.defines), {}};
    if (e.stage == Stage::fragment) p.vertex = spirv_of(glslang, tree, e.vertex, {});
    out.push_back(std::move(p));
  }
  return out;
}

const ShaderExecutable* IsaShader::own(Stage stage) const {
  for (const ShaderExecutable& e : executables)
    if (e.stage == stage) return &e;
  return nullptr;
}

IsaFigures isa_figures(const ShaderExecutable& e, const std::string& family, int wave, int min_wave) {
  IsaFigures f;
  const auto stat = [&](const char* name) { return std::max(0.0, e.statistic(name)); };
  f.vgprs = stat("VGPRs");
  f.sgprs = stat("SGPRs");
  f.spilled_vgprs = stat("Spilled VGPRs");
  f.spilled_sgprs = stat("Spilled SGPRs");
  f.scratch = stat("Scratch size");
  f.code = stat("Code size");
  f.instructions = stat("Instructions");
  f.branches = stat("Branches");
  f.latency = stat("Latency");
  f.throughput = stat("Inverse Throughput");
  // RADV counts subgroups per SIMD in wave32 units on gfx10 and later: a wave64 is two.
  f.waves = stat("Subgroups per SIMD") / (min_wave == 32 && wave == 64 ? 2.0 : 1.0);
  std::istringstream isa(e.isa);
  for (std::string line; std::getline(isa, line);) {
    const size_t start = line.find_first_not_of(" \t");
    if (start != std::string::npos && line.compare(start, 6, "image_") == 0) ++f.image;
  }
  f.loops = isa_loops(e.isa, issue_model(family, wave, min_wave));
  for (const IsaLoop& l : f.loops) {
    f.loop_cycles_max = std::max(f.loop_cycles_max, l.cycles);
    f.loop_cycles_sum += l.cycles;
  }
  return f;
}

bool supports_wave(const std::string& family, int wave) {
  return wave == 64 || !(family.rfind("polaris", 0) == 0 || family.rfind("vega", 0) == 0);
}

std::vector<IsaTargetResult> run_isa(const std::vector<IsaProgram>& programs, const std::vector<RadvTarget>& targets,
                                     int jobs, const std::function<void(const std::string&)>& progress) {
  const std::string manifest = radeon_icd_manifest();
  if (manifest.empty())
    throw Error("isa: no radeon ICD (radeon_icd.*.json under /usr/share/vulkan/icd.d): install mesa-vulkan-drivers "
                "(scripts/install-deps.sh does)",
                ExitCode::failed);
  std::vector<IsaTargetResult> out(targets.size());
  int ending_signal = 0;
  {
    const TempDir temp;
    const ParentSignals signals;
    std::vector<std::pair<pid_t, size_t>> running;
    const auto file_of = [&](size_t i) { return (temp.path() / ("target-" + std::to_string(i) + ".json")).string(); };
    const auto reap = [&] {
      int status = 0;
      const pid_t pid = waitpid(-1, &status, 0);
      if (pid < 0) {
        if (errno == EINTR) return;
        // No child to wait for (ECHILD: reaped unseen, e.g. under an ignored SIGCHLD): their results are lost.
        for (const auto& [child_pid, i] : running) {
          out[i].target = targets[i];
          out[i].error = std::string("its compiler process could not be waited for (") + std::strerror(errno) + ")";
          out[i].shaders.assign(programs.size(), IsaShader{out[i].error, {}});
        }
        running.clear();
        return;
      }
      for (auto it = running.begin(); it != running.end(); ++it) {
        if (it->first != pid) continue;
        const size_t i = it->second;
        out[i] = read_child(targets[i], file_of(i), status, programs.size());
        running.erase(it);
        progress(targets[i].family + " wave" + std::to_string(targets[i].wave) + ": " +
                 (out[i].error.empty() ? out[i].device : out[i].error));
        return;
      }
    };
    for (size_t i = 0; i < targets.size() && signals.noted() == 0; ++i) {
      while (static_cast<int>(running.size()) >= std::max(1, jobs) && signals.noted() == 0) reap();
      if (signals.noted() != 0) break;
      std::fflush(nullptr);
      const pid_t pid = fork();
      if (pid < 0) throw Error("isa: fork failed", ExitCode::failed);
      if (pid == 0) child(programs, targets[i], manifest, file_of(i), temp.path().string());
      running.push_back({pid, i});
    }
    while (!running.empty() && signals.noted() == 0) reap();
    ending_signal = signals.noted();
    if (ending_signal != 0) {
      for (const auto& [pid, i] : running) kill(pid, SIGKILL);
      for (const auto& [pid, i] : running)
        while (waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
        }
    }
  }  // the handlers as before, the temporaries removed
  if (ending_signal != 0) std::raise(ending_signal);  // ends the process as the signal would have
  return out;
}

void require_radv_families(const std::vector<std::string>& families, int jobs) {
  std::vector<RadvTarget> targets;
  for (const std::string& family : families)
    if (std::none_of(targets.begin(), targets.end(), [&](const RadvTarget& t) { return t.family == family; }))
      targets.push_back({family, 64});
  for (const IsaTargetResult& r : run_isa({}, targets, jobs, [](const std::string&) {}))
    if (!r.error.empty())
      throw Error("--families '" + r.target.family + "': RADV makes no device of that family (" + r.error +
                  "): expected a chip name it knows, such as polaris10, vega10, navi10, navi21, gfx1100");
}

}  // namespace pn
