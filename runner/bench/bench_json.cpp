#include "bench/bench_json.h"

namespace pn {

nlohmann::json scores_json(const Scores& s) {
  const auto one = [](const ImageScore& i) { return nlohmann::json{{"ssim", i.ssim}, {"mae", i.mae}}; };
  return {{"whole", one(s.whole)},
          {"light_facing", one(s.light_facing)},
          {"lit", one(s.lit)},
          {"light_facing_bias", {{"acne", s.bias.acne}, {"leak", s.bias.leak}}}};
}

nlohmann::json named_json(const NamedValues& values) {
  nlohmann::json o = nlohmann::json::object();
  for (const auto& [name, v] : values) o[name] = v;
  return o;
}

}  // namespace pn
