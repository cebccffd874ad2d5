// main() of the GL test binary: `--backend NAME` picks the context backend
// (default: the first that works) and `--api gl450|es310` its API (default
// gl450); without a context it reports why and exits 77, which CTest's
// SKIP_RETURN_CODE shows as skipped, never passed.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include <cstring>
#include <iostream>
#include <optional>
#include <vector>

#include "core/error.h"
#include "gl_test_context.h"

namespace pn::test {
namespace {
const Context* current_context = nullptr;
}
const Context& gl_context() { return *current_context; }
}  // namespace pn::test

int main(int argc, char** argv) {
  std::optional<pn::Backend> backend;
  pn::Api api = pn::Api::gl450;
  std::vector<char*> catch_args{argv[0]};
  try {
    for (int i = 1; i < argc; ++i) {
      if (std::strcmp(argv[i], "--backend") == 0 && i + 1 < argc) backend = pn::parse_backend(argv[++i]);
      else if (std::strcmp(argv[i], "--api") == 0 && i + 1 < argc) api = pn::parse_api(argv[++i]);
      else catch_args.push_back(argv[i]);
    }
  } catch (const pn::Error& e) {
    std::cerr << "penumbra GL tests: " << e.what() << "\n";
    return 2;
  }
  std::unique_ptr<pn::Context> context;
  try {
    context = pn::create_context(backend, api);
  } catch (const pn::Error& e) {
    std::cerr << "SKIPPED (no GL context): " << e.what() << "\n";
    return 77;
  }
  std::cout << "GL tests on " << pn::backend_name(context->backend()) << ": " << context->renderer() << ", "
            << context->version() << "\n";
  pn::test::current_context = context.get();
  return Catch::Session().run(static_cast<int>(catch_args.size()), catch_args.data());
}
