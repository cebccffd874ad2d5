#include "shader/register_plan.h"

#include <cctype>

#include "core/error.h"

namespace pn {

char RegisterPlan::register_kind(DescriptorKind kind, bool read_only) const {
  switch (kind) {
    case DescriptorKind::combined_image_sampler:
    case DescriptorKind::sampled_image: return 't';
    case DescriptorKind::sampler: return 's';
    case DescriptorKind::storage_image: return 'u';
    case DescriptorKind::uniform_buffer: return 'b';
    case DescriptorKind::storage_buffer: return read_only ? 't' : 'u';
  }
  return 't';
}

unsigned RegisterPlan::shift(char register_kind) const {
  switch (register_kind) {
    case 't': return t;
    case 's': return s;
    case 'u': return u;
    default: return b;
  }
}

std::string RegisterPlan::describe() const {
  if (identity()) return "the export's own (no shift, space 0)";
  return "t+" + std::to_string(t) + " s+" + std::to_string(s) + " u+" + std::to_string(u) + " b+" +
         std::to_string(b) + ", space " + std::to_string(space);
}

RegisterPlan parse_register_plan(const std::string& shift_text, long long space) {
  RegisterPlan plan;
  if (space < 0 || space > kMaxRegisterSpace)
    throw Error("--register-space " + std::to_string(space) + ": expected a space from 0 to " +
                std::to_string(kMaxRegisterSpace));
  plan.space = static_cast<unsigned>(space);
  if (shift_text.empty()) return plan;
  const std::string expected = "expected KIND=N[,KIND=N…], KIND one of t, s, u, b (each once), N from 0 to " +
                               std::to_string(kMaxRegisterShift) + ", e.g. t=8,s=8,u=2,b=1";
  std::string seen;
  std::size_t at = 0;
  while (at <= shift_text.size()) {
    const std::size_t comma = shift_text.find(',', at);
    const std::string item = shift_text.substr(at, comma == std::string::npos ? std::string::npos : comma - at);
    const bool shaped = item.size() >= 3 && item[1] == '=' && std::string("tsub").find(item[0]) != std::string::npos &&
                        item.size() <= 2 + 5;
    bool digits = shaped;
    for (std::size_t i = 2; digits && i < item.size(); ++i) digits = std::isdigit(static_cast<unsigned char>(item[i])) != 0;
    if (!digits) throw Error("--register-shift '" + shift_text + "': '" + item + "': " + expected);
    if (seen.find(item[0]) != std::string::npos)
      throw Error("--register-shift '" + shift_text + "': " + std::string(1, item[0]) + " twice: " + expected);
    seen += item[0];
    const unsigned long value = std::stoul(item.substr(2));
    if (value > kMaxRegisterShift) throw Error("--register-shift '" + shift_text + "': '" + item + "': " + expected);
    const unsigned v = static_cast<unsigned>(value);
    switch (item[0]) {
      case 't': plan.t = v; break;
      case 's': plan.s = v; break;
      case 'u': plan.u = v; break;
      default: plan.b = v; break;
    }
    if (comma == std::string::npos) break;
    at = comma + 1;
  }
  return plan;
}

}  // namespace pn
