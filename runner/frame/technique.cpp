#include "frame/technique.h"

namespace pn {

double TechniqueFrame::total_ms() const {
  double sum = 0.0;
  for (const auto& stage : stages) sum += stage.second;
  return sum;
}

}  // namespace pn
