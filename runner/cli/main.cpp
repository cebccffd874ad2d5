// penumbra — lint, bundle and check the GLSL soft-shadow modules.
#include <filesystem>
#include <iostream>
#include <new>

#include "cli/commands.h"
#include "core/error.h"

int main(int argc, char** argv) {
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
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : static_cast<int>(pn::ExitCode::bad_input);
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
