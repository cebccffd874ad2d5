#include "modules/reuse_face.h"

#include <cmath>
#include <string>
#include <utility>

#include "core/error.h"
#include "core/format.h"

namespace pn {

void ReuseParams::validate() const {
  const std::pair<const char*, float> sigmas[] = {{"sigma1", sigma1}, {"sigma2", sigma2}, {"sigma3", sigma3}};
  for (const auto& [name, value] : sigmas)
    if (!(value >= 0.0f) || !std::isfinite(value))
      throw Error(std::string("reuse ") + name + " " + format_number("%g", value) + ": expected a finite number >= 0");
  if (tile < 1 || tile > kReuseMaxTile)
    throw Error("reuse tile " + std::to_string(tile) + ": expected an integer from 1 to " + std::to_string(kReuseMaxTile));
}

}  // namespace pn
