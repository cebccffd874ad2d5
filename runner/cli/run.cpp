// The command line: every command's options parsed with CLI11, run, and every error as one
// line and an exit code (main.cpp calls it; the fuzz target fuzz_cli too).
#include <fcntl.h>
#include <limits.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <filesystem>
#include <iostream>
#include <map>
#include <new>
#include <set>
#include <string>
#include <vector>

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

// Issue 39 C15: a number is read as decimal. CLI11 reads an integer with strtoll's base 0 (0100 as
// octal 64, 0x10 as 16) and a real with strtold (0x10 as 16 too): every integer option takes
// [+-]digits, a leading zero read as decimal (--map-size 016 is 16); hexadecimal is refused.
void read_numbers_as_decimal(CLI::App& app) {
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
    for (CLI::Option* o : sub->get_options()) {
      const std::string type = o->get_type_name();
      const bool integer = type == "INT" || type == "UINT";
      if (!integer && type != "FLOAT") continue;
      o->transform(CLI::Validator(
          [integer](std::string& value) -> std::string {
            if (!integer) {
              if (value.find_first_of("xX") == std::string::npos) return "";
              return value + ": expected a decimal number, not hexadecimal";
            }
            const size_t digits = value.find_first_not_of("+-") == 1 ? 1 : 0;
            if (value.size() > digits && value.find_first_not_of("0123456789", digits) == std::string::npos &&
                value.find_first_of("+-", 1) == std::string::npos) {
              const size_t first = std::min(value.find_first_not_of('0', digits), value.size() - 1);
              value = value.substr(0, digits) + value.substr(first);
              return "";
            }
            return value + ": expected a decimal integer (digits only: not hexadecimal, octal or a fraction)";
          },
          ""));
    }
}

// Issue 39 C16: a list option (or a flag) given twice is refused by name; CLI11 would merge
// `--techniques pcf --techniques fast` into one list. (A repeated single-value option CLI11 refuses itself.)
void refuse_repeated_lists(CLI::App& app, int argc, char** argv) {
  if (argc < 2) return;
  CLI::App* command = nullptr;
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
    if (sub->check_name(argv[1])) command = sub;
  if (!command) return;
  std::map<const CLI::Option*, int> given;
  for (int i = 2; i < argc; ++i) {
    const std::string token = argv[i];
    if (token == "--") break;
    if (token.size() < 2 || token[0] != '-') continue;
    const size_t eq = token.find('=');
    const std::string name = token.substr(0, eq);
    for (const CLI::Option* o : command->get_options()) {
      if (o->get_lnames().empty() && o->get_snames().empty()) continue;  // a positional
      if (!o->check_name(name)) continue;
      const bool flag = o->get_expected_max() == 0;  // takes no value
      if (++given[o] > 1 && (flag || o->get_delimiter() == ','))
        throw pn::Error(name + ": given twice: expected it once" +
                        (flag ? std::string() : ", its entries in one list (" + name + " A,B)"));
      if (!flag && eq == std::string::npos) ++i;  // its value
      break;
    }
  }
}

// Issue 39 C19: a standard stream the caller closed (`>&-`) is opened on /dev/null first, so no
// output file the run opens takes its number (what the run prints would land in it); a closed
// standard output is then refused, before any work: the run could only end in exit 2 after writing.
void refuse_closed_standard_output() {
  bool closed_output = false;
  for (int fd = 0; fd <= 2; ++fd) {
    if (::fcntl(fd, F_GETFD) != -1 || errno != EBADF) continue;
    closed_output = closed_output || fd == 1;
    const int null = ::open("/dev/null", fd == 0 ? O_RDONLY : O_WRONLY);
    if (null >= 0 && null != fd) ::dup2(null, fd), ::close(null);
  }
  if (closed_output)
    throw pn::Error("standard output is closed: expected it open (> /dev/null discards what the command prints)");
}

// Every error is one line (issue 39 C18): a message that carries a log (the driver's lines after
// "the GL driver rejected the pass:") has its lines joined with "; ".
std::string one_line(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  std::string out;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\r') continue;
    if (text[i] != '\n') {
      out += text[i];
      continue;
    }
    while (!out.empty() && out.back() == ' ') out.pop_back();
    out += !out.empty() && out.back() == ':' ? " " : "; ";
    while (i + 1 < text.size() && (text[i + 1] == ' ' || text[i + 1] == '\n')) ++i;
  }
  return out;
}

// Issue 39 C21: relative paths need the working directory; a deleted one is named as such.
void refuse_deleted_working_directory(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") return;
  std::vector<char> buffer(PATH_MAX + 1);
  if (::getcwd(buffer.data(), buffer.size()) == nullptr && errno == ENOENT)
    throw pn::Error("the working directory was deleted: expected to run in an existing directory (cd to one)");
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
  pn::cli::add_techniques_command(app, exit_code);
  pn::cli::add_isa_command(app, global, exit_code);
  try {
    refuse_closed_standard_output();
    refuse_unknown_command(app, argc, argv);
    refuse_empty_list_names(app, argc, argv);
    refuse_repeated_lists(app, argc, argv);
    refuse_deleted_working_directory(argc, argv);
    read_numbers_as_decimal(app);
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    std::cerr << "penumbra: error: " << parse_error_line(e) << "\n";
    return static_cast<int>(pn::ExitCode::bad_input);
  } catch (const pn::Error& e) {
    std::cerr << "penumbra: error: " << one_line(e.what()) << "\n";
    return static_cast<int>(e.code());
  } catch (const std::filesystem::filesystem_error& e) {
    // A path the user named that the system refused: bad input, not a crash.
    std::cerr << "penumbra: error: " << one_line(e.what()) << "\n";
    return static_cast<int>(pn::ExitCode::bad_input);
  } catch (const std::bad_alloc&) {
    std::cerr << "penumbra: error: out of memory\n";
    return static_cast<int>(pn::ExitCode::failed);
  } catch (const std::exception& e) {
    // Every command reports its own errors as pn::Error; reaching here is a runner bug,
    // still reported as one line and an exit code rather than an abort.
    std::cerr << "penumbra: error: internal error: " << one_line(e.what()) << "\n";
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
