// penumbra — lint, bundle and check the GLSL soft-shadow modules.
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <iostream>

#include "cli/commands.h"
#include "core/write_file.h"
#include "vk/vulkan_device.h"

int main(int argc, char** argv) {
  pn::remove_temporaries_on_signals();  // an interrupted write leaves no temporary behind
  // A parent that ignores SIGCHLD passes that on: children would be reaped unseen and every wait
  // for one (isa's compilers, the model import's child) would find none (issue 54 X1).
  std::signal(SIGCHLD, SIG_DFL);
  const int code = pn::cli::run(argc, argv);
  if (pn::vulkan_job_abandoned()) {
    // A Vulkan job past its deadline still runs (`check --gpu-timeout`: the verdict is printed):
    // end now, without the exit handlers and static destructors that could wait for its threads.
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    std::_Exit(code);
  }
  return code;
}
