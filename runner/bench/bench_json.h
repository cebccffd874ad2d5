// The JSON shapes the bench commands share: a technique's scores
// (metrics/scores.h) and a list of named values (stage times, stats).
#pragma once

#include <nlohmann/json.hpp>

#include "metrics/scores.h"
#include "frame/technique.h"

namespace pn {

// {"whole": {"ssim", "mae"}, "light_facing": {…}, "lit": {…}}
nlohmann::json scores_json(const Scores& scores);

// {"name": value, …}, in the list's order.
nlohmann::json named_json(const NamedValues& values);

}  // namespace pn
