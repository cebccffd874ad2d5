// The one error type of the runner: a one-line message that names the input
// and what was expected, plus the process exit code it maps to.
#pragma once

#include <stdexcept>
#include <string>

namespace pn {

// Exit codes of the `penumbra` binary, documented in docs/cli.md.
enum class ExitCode : int {
  ok = 0,
  failed = 1,      // a check or a lint found an error in the modules
  bad_input = 2,   // a file, argument or parameter the user gave is wrong
  no_context = 3,  // no headless GL context could be created
};

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message, ExitCode code = ExitCode::bad_input)
      : std::runtime_error(message), code_(code) {}
  ExitCode code() const { return code_; }

 private:
  ExitCode code_;
};

}  // namespace pn
