#include "modules/depth_pyramid_face.h"

#include <algorithm>
#include <string>

#include "core/error.h"

namespace pn {

int floor_log2(int n) {
  int log = 0;
  while ((n >> (log + 1)) > 0) ++log;
  return log;
}

int pyramid_level_count(int n, int max_level) {
  if (n < 2) throw Error("shadow map " + std::to_string(n) + "x" + std::to_string(n) + ": expected N >= 2");
  if (max_level < 0) throw Error("pyramid maximum level " + std::to_string(max_level) + ": expected >= 0");
  return std::min(floor_log2(n), max_level) + 1;
}

}  // namespace pn
