// Fuzz target: the whole command line, `penumbra ARGS…` (cli/run.cpp): CLI11's
// option parsing, the runner's own refusals (unknown commands, empty list
// names, options a command does not use), each command's validation — and
// whatever runs before a GL context, which this target never gets
// (GALLIUM_DRIVER=nonexistent: every backend fails, exit 3).
//
// Input: the arguments after `penumbra`, one a line (at most 16, each cut at
// 256 bytes). Every '/' becomes '_': an argument names files in the target's
// scratch directory (its working directory), never elsewhere.
//
// What must hold: the exit code is 0, 1, 2 or 3; on exit 2 or 3 standard error
// is exactly one line `penumbra: error: …`; and nothing crashes, leaks or hangs.
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "fuzz_input.h"

namespace {

// Swaps a stream's buffer for the duration of a run.
class Capture {
 public:
  Capture(std::ostream& stream, std::streambuf* into) : stream_(stream), saved_(stream.rdbuf(into)) {}
  ~Capture() { stream_.rdbuf(saved_); }
  Capture(const Capture&) = delete;
  Capture& operator=(const Capture&) = delete;

 private:
  std::ostream& stream_;
  std::streambuf* saved_;
};

}  // namespace

// The failed eglInitialize of each run (GALLIUM_DRIVER=nonexistent) leaves tables in Mesa's DRI
// driver, as tests/sanitize/lsan.supp says: kept mapped (no dlclose) so that LeakSanitizer can
// name the driver, and that driver's (and OSMesa's) leaks suppressed — never penumbra's own.
extern "C" int dlclose(void*) { return 0; }
extern "C" const char* __lsan_default_suppressions() { return "leak:swrast_dri.so\nleak:libOSMesa.so\n"; }

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  setenv("GALLIUM_DRIVER", "nonexistent", 1);  // no GL context: the target stays in the parser and validation
  setenv("EGL_LOG_LEVEL", "fatal", 1);         // and Mesa does not say so on every run
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const pn::fuzz::ScratchDir scratch("cli");
  static const std::filesystem::path home = std::filesystem::current_path();  // libFuzzer's paths are relative to it
  scratch.clear();
  if (chdir(scratch.path().c_str()) != 0) std::abort();  // the harness itself is broken, not the input
  std::vector<std::string> arguments{"penumbra"};
  std::istringstream lines(pn::fuzz::as_text(data, size));
  for (std::string line; arguments.size() <= 16 && std::getline(lines, line);) {
    line.resize(std::min<size_t>(line.size(), 256));
    for (char& c : line)
      if (c == '/' || c == '\0') c = '_';
    arguments.push_back(line);
  }
  std::vector<char*> argv;
  for (std::string& a : arguments) argv.push_back(a.data());
  argv.push_back(nullptr);

  std::ostringstream out, err;
  int code = 0;
  {
    const Capture capture_out(std::cout, out.rdbuf()), capture_err(std::cerr, err.rdbuf());
    code = pn::cli::run(static_cast<int>(arguments.size()), argv.data());
  }
  if (chdir(home.c_str()) != 0) std::abort();
  if (code < 0 || code > 3) std::abort();
  if (code == 2 || code == 3) {
    const std::string e = err.str();
    if (e.rfind("penumbra: error: ", 0) != 0 || e.empty() || e.back() != '\n' || e.find('\n') != e.size() - 1)
      std::abort();  // not the documented one line
  }
  return 0;
}
