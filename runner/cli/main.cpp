// penumbra — lint, bundle and check the GLSL soft-shadow modules.
#include "cli/commands.h"
#include "core/write_file.h"

int main(int argc, char** argv) {
  pn::remove_temporaries_on_signals();  // an interrupted write leaves no temporary behind
  return pn::cli::run(argc, argv);
}
