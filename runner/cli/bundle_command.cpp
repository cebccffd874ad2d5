#include <cstdio>
#include <filesystem>
#include <iostream>

#include "cli/commands.h"
#include "core/error.h"
#include "core/write_file.h"
#include "shader/export_source.h"
#include "shader/flatten.h"
#include "shader/pass_interface.h"
#include "shader/target.h"

namespace pn::cli {

namespace {

// What `command` printed on its first line, or "" (no git, not a checkout).
std::string first_line_of(const std::string& command) {
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return "";
  char line[256] = {};
  const bool got = std::fgets(line, sizeof line, pipe) != nullptr;
  pclose(pipe);
  std::string out = got ? line : "";
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out;
}

std::string shell_quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// Where the glsl root's files come from, the same in every clone (issue 41: no absolute path): the
// root's path inside its repository, the last commit that changed it (not HEAD: a commit elsewhere
// changes no bundle), and whether it has local changes.
std::string provenance(const std::filesystem::path& root) {
  const std::string git = "git -C " + shell_quoted(root.string()) + " ";
  const std::string commit = first_line_of(git + "log -1 --format=%H -- . 2>/dev/null");
  if (commit.empty()) {
    // Inside a checkout that never committed it (issue 54 X14), or outside any.
    const std::string top = first_line_of(git + "rev-parse --show-toplevel 2>/dev/null");
    return top.empty() ? "a copy outside any git checkout (see the hashes)"
                       : "untracked in the checkout at " + top + ": no commit has it (see the hashes)";
  }
  std::string inside = first_line_of(git + "rev-parse --show-prefix 2>/dev/null");
  if (inside.empty()) inside = "./";
  const bool changed = !first_line_of(git + "status --porcelain -- . 2>/dev/null").empty();
  return inside + " of its repository at commit " + commit + ", the last commit that changed it" +
         (changed ? ", with local changes (see the hashes)" : "");
}

}  // namespace

void add_bundle_command(CLI::App& app, GlobalOptions& global, int& exit_code) {
  struct Options {
    std::string module, output, target = "gl450", shader_model;
    bool bare = false, interface = false;
    RegisterPlanOptions registers;
  };
  auto opt = std::make_shared<Options>();
  auto* cmd = app.add_subcommand("bundle", "Flatten a module and its includes into one GLSL file");
  cmd->add_option("module", opt->module, "Module or pass, e.g. glsl/blur.glsl")->required();
  cmd->add_option("-o,--output", opt->output, "Output file (default: standard output)");
  cmd->add_option("--target", opt->target,
                  "gl450 | vulkan | es310: the #version header of the standalone form; hlsl | msl: the module's export "
                  "entry (exports/X.comp) or the pass as HLSL or MSL, through SPIR-V and SPIRV-Cross");
  cmd->add_option("--shader-model", opt->shader_model,
                  "With --target hlsl: 5.0 (the default), 5.1 or 6.0 (register spaces: 5.1 and 6.0)");
  cmd->add_flag("--interface", opt->interface,
                "Print the module's or pass's resource interface instead, from its SPIR-V: a markdown table of each "
                "binding's HLSL register, kind, format, access, whether the entry uses it and what it holds");
  cmd->add_flag("--bare", opt->bare,
                "Only the flattened source, no #version and no entry point: to paste after an engine's own header");
  add_register_plan_options(*cmd, opt->registers, "With --target hlsl");
  cmd->add_option("--glsl-root", global.glsl_root, "Directory that #include paths resolve under (default: the module's own copy of glsl/)");
  cmd->callback([opt, &global, &exit_code] {
    const bool cross = opt->target == "hlsl" || opt->target == "msl";
    if (opt->interface && (opt->bare || !opt->shader_model.empty() || opt->target != "gl450"))
      throw Error("--interface: reads the Vulkan SPIR-V of the module's entry: expected no --target, --shader-model or --bare");
    if (!opt->shader_model.empty() && opt->target != "hlsl")
      throw Error("--shader-model " + opt->shader_model + ": applies to --target hlsl only");
    if (!opt->shader_model.empty() && opt->shader_model != "5.0" && opt->shader_model != "5.1" &&
        opt->shader_model != "6.0")
      throw Error("--shader-model " + opt->shader_model + ": expected 5.0, 5.1 or 6.0");
    if (cross && opt->bare) throw Error("--bare: applies to the GLSL targets, not " + opt->target);
    const RegisterPlan plan = register_plan_of(opt->registers, opt->target == "hlsl" && !opt->interface, "--target hlsl");
    if (plan.space != 0 && (opt->shader_model.empty() || opt->shader_model == "5.0"))
      throw Error("--register-space " + std::to_string(plan.space) +
                  ": shader model 5.0 has no register spaces: expected --shader-model 5.1 or 6.0");
    const Target target = cross ? Target::vulkan : [&] {
      try {
        return parse_target(opt->target);
      } catch (const Error&) {
        throw Error("target '" + opt->target + "': expected one of gl450, vulkan, es310, hlsl, msl");
      }
    }();
    // A path to a copy's module: the copy is its root, as for lint; a name: the library's (or --glsl-root's).
    const bool path = global.glsl_root.empty() && std::filesystem::exists(opt->module);
    const SourceTree tree(path ? root_for(opt->module, global).string() : glsl_root_or_default(global));
    // The files the output is made from (a module exported through its export entry).
    const FlatSource flat =
        cross ? flatten(tree, tree.root() / export_entry(tree, opt->module)) : flatten(tree, opt->module);
    const std::string header = "// penumbra bundle of " + flat.files.front() + " (generated by `penumbra bundle`)\n";
    std::string text;
    if (opt->interface) {
      const GlslangProcess process;
      text = interface_markdown(pass_interface(process, tree, opt->module));
    } else if (cross) {
      const CrossLanguage language = opt->target == "msl"          ? CrossLanguage::msl
                                     : opt->shader_model == "6.0" ? CrossLanguage::hlsl60
                                     : opt->shader_model == "5.1" ? CrossLanguage::hlsl51
                                                                  : CrossLanguage::hlsl50;
      const GlslangProcess process;
      text = export_source(process, tree, opt->module, language, provenance(tree.root()), plan);
    } else if (opt->bare) {
      text = header + flat.file_table_comment() + flat.text;
    } else {
      // #version must come first: the header comment follows the wrapper's prelude.
      const ShaderSource source = standalone_source(flat, target);
      const size_t first_line_end = source.text.find('\n') + 1;
      text = source.text.substr(0, first_line_end) + header + source.text.substr(first_line_end);
    }
    if (!opt->output.empty()) {
      // Writing over a file the bundle was made from would destroy the module (issue 26 B12).
      std::error_code ec;
      for (const std::string& file : flat.files)
        if (std::filesystem::equivalent(opt->output, tree.root() / file, ec))
          throw Error("output '" + opt->output + "': it is " + file + ", one of the bundle's inputs: expected another file");
    }
    if (opt->output.empty()) std::cout << text;
    else write_file_atomically(opt->output, text);
    exit_code = 0;
  });
}

}  // namespace pn::cli
