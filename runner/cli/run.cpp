// The command line: every command's options parsed with CLI11, run, and every error as one
// line and an exit code (main.cpp calls it; the fuzz target fuzz_cli too).
#include <filesystem>
#include <iostream>
#include <new>
#include <set>
#include <string>

#include "cli/commands.h"
#include "core/error.h"
#include "core/write_file.h"

namespace {

// The documented one-line form of a CLI11 parse error (issue 26 B15): CLI11's own
// text, first line only, naming the option; "see --help" on the same line.
std::string parse_error_line(const CLI::ParseError& e) {
  std::string what = e.what();
  what = what.substr(0, what.find('\n'));
  if (what.rfind("Could not convert: ", 0) == 0) what = what.substr(19) + ": not a value of the option's type";
  return what + " (penumbra COMMAND --help lists the options)";
}

// Issue 26 B15: an unknown command named as such, with the commands there are.
void refuse_unknown_command(CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return;
  std::string names;
  for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
    if (sub->check_name(argv[1])) return;
    names += (names.empty() ? "" : ", ") + sub->get_name();
  }
  throw pn::Error("unknown command '" + std::string(argv[1]) + "': expected one of " + names);
}

// Issue 26 B14: a list option's value with an empty name ("," or "a,,b") is refused by
// name, before CLI11 drops the empty part and takes the next argument as a value.
void refuse_empty_list_names(CLI::App& app, int argc, char** argv) {
  std::set<std::string> lists;
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
    for (const CLI::Option* o : sub->get_options())
      if (o->get_delimiter() == ',')
        for (const std::string& name : o->get_lnames()) lists.insert("--" + name);
  for (int i = 1; i < argc; ++i) {
    std::string option = argv[i], value;
    const size_t eq = option.find('=');
    if (eq != std::string::npos) value = option.substr(eq + 1), option = option.substr(0, eq);
    else if (i + 1 < argc) value = argv[i + 1];
    else continue;
    if (!lists.count(option)) continue;
    bool empty = value.empty();
    for (size_t start = 0; !empty;) {
      const size_t comma = value.find(',', start);
      const std::string name = value.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      empty = name.find_first_not_of(" \t") == std::string::npos;
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    if (empty)
      throw pn::Error(option + " '" + value + "': an empty name in the list (a stray comma?): expected NAME[,NAME...]");
  }
}

}  // namespace

namespace pn::cli {

int run(int argc, char** argv) {
  CLI::App app{"penumbra: GLSL soft-shadow modules, linted, bundled and checked against CPU references"};
  app.require_subcommand(1);
  pn::cli::GlobalOptions global;
  int exit_code = 0;
  pn::cli::add_render_command(app, global, exit_code);
  pn::cli::add_lint_command(app, global, exit_code);
  pn::cli::add_bundle_command(app, global, exit_code);
  pn::cli::add_check_command(app, global, exit_code);
  pn::cli::add_info_command(app, global, exit_code);
  pn::cli::add_bench_command(app, global, exit_code);
  pn::cli::add_figures_command(app, global, exit_code);
  pn::cli::add_poisson_command(app, exit_code);
  pn::cli::add_sample_table_command(app, exit_code);
  try {
    refuse_unknown_command(app, argc, argv);
    refuse_empty_list_names(app, argc, argv);
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    std::cerr << "penumbra: error: " << parse_error_line(e) << "\n";
    return static_cast<int>(pn::ExitCode::bad_input);
  } catch (const pn::Error& e) {
    std::cerr << "penumbra: error: " << e.what() << "\n";
    return static_cast<int>(e.code());
  } catch (const std::filesystem::filesystem_error& e) {
    // A path the user named that the system refused: bad input, not a crash.
    std::cerr << "penumbra: error: " << e.what() << "\n";
    return static_cast<int>(pn::ExitCode::bad_input);
  } catch (const std::bad_alloc&) {
    std::cerr << "penumbra: error: out of memory\n";
    return static_cast<int>(pn::ExitCode::failed);
  } catch (const std::exception& e) {
    // Every command reports its own errors as pn::Error; reaching here is a runner bug,
    // still reported as one line and an exit code rather than an abort.
    std::cerr << "penumbra: error: internal error: " << e.what() << "\n";
    return static_cast<int>(pn::ExitCode::failed);
  } catch (...) {
    std::cerr << "penumbra: error: internal error: unknown exception\n";
    return static_cast<int>(pn::ExitCode::failed);
  }
  // Output the user pointed at a full disk or a closed pipe is a failure, not a success.
  if (!std::cout.flush()) {
    std::cerr << "penumbra: error: standard output: write failed\n";
    return static_cast<int>(pn::ExitCode::bad_input);
  }
  return exit_code;
}

}  // namespace pn::cli
