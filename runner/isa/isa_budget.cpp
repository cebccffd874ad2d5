#include "isa/isa_budget.h"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "core/error.h"

namespace pn {

namespace {

const char* kMarker = "// isa budget:";

double figure(const IsaFigures& f, const std::string& key) {
  if (key == "vgprs") return f.vgprs;
  if (key == "instructions") return f.instructions;
  if (key == "code") return f.code;
  if (key == "loop") return f.loop_cycles_max;
  if (key == "loops") return f.loop_cycles_sum;
  return f.scratch;  // "scratch"
}

std::string format(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

std::optional<IsaBudget> read_budget(const SourceTree& tree, const std::string& module) {
  const std::string file = module + ".glsl";
  std::ifstream in(tree.root() / file);
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (line.rfind(kMarker, 0) != 0) continue;
    IsaBudget b{module, file, number, {}};
    std::istringstream items(line.substr(std::string(kMarker).size()));
    for (std::string item; std::getline(items, item, ',');) {
      item.erase(0, item.find_first_not_of(' '));
      std::istringstream kv(item);
      std::string key, value, rest;
      kv >> key >> value >> rest;
      // N: decimal digits, at most 9 (a register count or a size, never a sign, a fraction or 20
      // digits: issue 54 X16); each key once.
      const bool digits = !value.empty() && value.size() <= 9 && value.find_first_not_of("0123456789") == std::string::npos;
      const bool known = key == "vgprs" || key == "instructions" || key == "code" || key == "scratch" || key == "loop" ||
                         key == "loops";
      const bool again = std::any_of(b.limits.begin(), b.limits.end(), [&](const auto& l) { return l.first == key; });
      if (!known || !digits || !rest.empty() || again)
        throw Error(file + ":" + std::to_string(number) + ": isa budget item '" + item +
                    (again ? "': " + key + " a second time" : "'") +
                    ": expected 'vgprs N', 'instructions N', 'code BYTES', 'scratch BYTES', 'loop CYCLES' or "
                    "'loops CYCLES', each once, N a whole number of up to 9 digits");
      b.limits.emplace_back(key, std::stod(value));
    }
    return b;
  }
  return std::nullopt;
}

IsaBudgets read_budgets(const SourceTree& tree, const std::vector<IsaEntry>& entries) {
  IsaBudgets out;
  for (const IsaEntry& e : entries)
    if (!e.module.empty() && !out.count(e.module)) out[e.module] = read_budget(tree, e.module);
  return out;
}

std::vector<std::string> budget_breaches(const IsaBudgets& budgets, const std::vector<IsaProgram>& programs,
                                         const IsaTargetResult& result) {
  std::vector<std::string> out;
  for (size_t i = 0; i < programs.size() && i < result.shaders.size(); ++i) {
    const IsaEntry& entry = programs[i].entry;
    const IsaShader& shader = result.shaders[i];
    if (!shader.error.empty()) {
      out.push_back(entry.label() + ": did not compile on " + result.target.family + ": " + shader.error);
      continue;
    }
    const ShaderExecutable* own = shader.own(entry.stage);
    if (!own) continue;
    const IsaFigures f = isa_figures(*own, result.target.family, result.target.wave, result.min_wave);
    const auto found = budgets.find(entry.module);
    const std::optional<IsaBudget> budget = found == budgets.end() ? std::nullopt : found->second;
    bool scratch_budgeted = false;
    if (budget)
      for (const auto& [key, limit] : budget->limits) {
        scratch_budgeted |= key == "scratch";
        if (figure(f, key) > limit)
          out.push_back(entry.label() + ": " + format(figure(f, key)) + " " + key + " > " + format(limit) + " (" +
                        budget->file + ":" + std::to_string(budget->line) + ")");
      }
    if (!scratch_budgeted && f.scratch > 0)
      out.push_back(entry.label() + ": " + format(f.scratch) + " bytes of scratch (a local array or a spill: no entry may use scratch)");
  }
  return out;
}

}  // namespace pn
