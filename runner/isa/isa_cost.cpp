#include "isa/isa_cost.h"

#include <algorithm>
#include <map>
#include <sstream>

namespace pn {
namespace {

bool starts(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }
bool contains(const std::string& s, const char* part) { return s.find(part) != std::string::npos; }

// gfx11's VALU operations that issue once in wave64 (ACO's is_dual_issue_capable).
bool dual_issue(const std::string& m) {
  static const char* const names[] = {"v_fma_f32", "v_fmac_f32", "v_fmaak_f32", "v_fmamk_f32", "v_mul_f32",
                                      "v_add_f32", "v_sub_f32", "v_subrev_f32", "v_mov_b32", "v_cndmask_b32",
                                      "v_max_f32", "v_min_f32", "v_mul_legacy_f32", "v_fma_f16", "v_mul_f16",
                                      "v_add_f16", "v_sub_f16", "v_max_f16", "v_min_f16"};
  for (const char* n : names)
    if (m == n || starts(m, (std::string(n) + "_e").c_str())) return true;
  return false;
}

struct Line {
  std::string mnemonic, text;
};

}  // namespace

IssueModel issue_model(const std::string& family, int wave, int min_wave) {
  IssueModel m;
  m.rdna = min_wave == 32;
  m.gfx11 = starts(family, "gfx11");
  m.wave = wave;
  return m;
}

double issue_cycles(const std::string& m, const IssueModel& model) {
  // Scalar, branch and wait instructions: one wave, any size.
  if (starts(m, "s_waitcnt") || m == "s_nop" || m == "s_endpgm" || m == "s_clause" || m == "s_delay_alu" ||
      starts(m, "s_inst_prefetch") || m == "s_setprio" || m == "s_code_end")
    return model.rdna ? 0.0 : 4.0;
  if (m == "s_branch" || starts(m, "s_cbranch") || starts(m, "s_setpc") || starts(m, "s_sendmsg"))
    return model.rdna ? 1.0 : 8.0;
  if (starts(m, "s_")) return model.rdna ? 1.0 : 4.0;  // SALU and SMEM
  // Vector instructions: a wave64 takes two passes of a SIMD32 on RDNA (one for gfx11's dual-issue
  // operations); GCN's SIMD16 takes four cycles a wave64 pass.
  double cycles = 1.0;
  if (starts(m, "v_")) {
    if (contains(m, "_f64")) cycles = 16.0;
    else if (starts(m, "v_mul_lo_u32") || starts(m, "v_mul_hi_") || starts(m, "v_mul_lo_i32") ||
             starts(m, "v_mad_u64_u32") || starts(m, "v_mad_i64_i32"))
      cycles = 4.0;  // quarter rate
    else if (starts(m, "v_rcp_") || starts(m, "v_rsq_") || starts(m, "v_sqrt_") || starts(m, "v_exp_") ||
             starts(m, "v_log_") || starts(m, "v_sin_") || starts(m, "v_cos_"))
      cycles = 4.0;  // the transcendental unit
    else if (contains(m, "_b64") || contains(m, "_i64") || contains(m, "_u64"))
      cycles = 2.0;
  }
  if (!model.rdna) return 4.0 * cycles * (model.wave / 64.0);
  const bool once = model.gfx11 && dual_issue(m);
  return cycles * (model.wave == 64 && !once ? 2.0 : 1.0);
}

bool vector_memory_load(const std::string& m) {
  return (starts(m, "image_") && !starts(m, "image_store") && !starts(m, "image_atomic")) ||
         starts(m, "buffer_load") || starts(m, "global_load") || starts(m, "tbuffer_load") || starts(m, "flat_load") ||
         starts(m, "scratch_load");
}

namespace {

// The ISA's instructions (labels taken out) and its loops: [target, branch] for each branch back to
// a label at or before it; back edges to one label (a `continue`, the loop's end) are one loop.
struct ParsedIsa {
  struct Region {
    std::size_t first, last;
  };
  std::vector<Line> lines;
  std::vector<Region> regions;

  // The innermost loop (the smallest region) holding instruction i, or -1.
  int innermost(std::size_t i) const {
    int best = -1;
    for (std::size_t r = 0; r < regions.size(); ++r)
      if (regions[r].first <= i && i <= regions[r].last &&
          (best < 0 || regions[r].last - regions[r].first <
                           regions[static_cast<std::size_t>(best)].last - regions[static_cast<std::size_t>(best)].first))
        best = static_cast<int>(r);
    return best;
  }
};

ParsedIsa parse_isa(const std::string& isa) {
  ParsedIsa p;
  std::map<std::string, std::size_t> labels;  // label -> index of the next instruction
  std::istringstream in(isa);
  for (std::string raw; std::getline(in, raw);) {
    const std::size_t a = raw.find_first_not_of(" \t");
    if (a == std::string::npos) continue;
    std::string text = raw.substr(a, raw.find(';', a) == std::string::npos ? std::string::npos : raw.find(';', a) - a);
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.pop_back();
    if (text.empty()) continue;
    if (text.back() == ':' && text.find(' ') == std::string::npos) {
      labels[text.substr(0, text.size() - 1)] = p.lines.size();
      continue;
    }
    p.lines.push_back({text.substr(0, text.find_first_of(" \t")), text});
  }
  for (std::size_t i = 0; i < p.lines.size(); ++i) {
    const Line& l = p.lines[i];
    if (l.mnemonic != "s_branch" && !starts(l.mnemonic, "s_cbranch")) continue;
    const std::size_t space = l.text.find_last_of(" \t");
    const auto target = labels.find(l.text.substr(space + 1));
    if (target == labels.end() || target->second > i) continue;
    const auto same = std::find_if(p.regions.begin(), p.regions.end(),
                                   [&](const ParsedIsa::Region& r) { return r.first == target->second; });
    if (same != p.regions.end()) same->last = std::max(same->last, i);
    else p.regions.push_back({target->second, i});
  }
  std::sort(p.regions.begin(), p.regions.end(),
            [](const ParsedIsa::Region& a, const ParsedIsa::Region& b) { return a.first < b.first; });
  return p;
}

}  // namespace

std::vector<IsaLoop> isa_loops(const std::string& isa, const IssueModel& model) {
  const ParsedIsa p = parse_isa(isa);
  std::vector<IsaLoop> out(p.regions.size());
  for (std::size_t r = 0; r < p.regions.size(); ++r)
    for (std::size_t q = 0; q < p.regions.size(); ++q)
      if (q != r && p.regions[q].first <= p.regions[r].first && p.regions[r].last <= p.regions[q].last) ++out[r].depth;
  for (std::size_t i = 0; i < p.lines.size(); ++i) {
    const int r = p.innermost(i);
    if (r < 0) continue;
    IsaLoop& l = out[static_cast<std::size_t>(r)];
    l.instructions += 1.0;
    l.cycles += issue_cycles(p.lines[i].mnemonic, model);
    l.loads += vector_memory_load(p.lines[i].mnemonic) ? 1.0 : 0.0;
  }
  return out;
}

IsaCostModel isa_cost_model(const std::string& isa, std::size_t census_loops, const IssueModel& model) {
  const ParsedIsa parsed = parse_isa(isa);
  const std::vector<Line>& lines = parsed.lines;
  const auto& regions = parsed.regions;
  const auto innermost = [&](std::size_t i) { return parsed.innermost(i); };
  // The markers: a buffer store at offset:4(j+1) after a load of the same address, descriptor and offset.
  std::vector<bool> marker(lines.size(), false);
  std::vector<std::vector<int>> marked(census_loops);  // census loop -> the regions (or -1) of its markers
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (!starts(lines[i].mnemonic, "buffer_store_dword")) continue;
    const std::size_t at = lines[i].text.find("offset:");
    if (at == std::string::npos) continue;
    const long offset = std::strtol(lines[i].text.c_str() + at + 7, nullptr, 0);
    if (offset < 4 || offset % 4 != 0 || static_cast<std::size_t>(offset / 4 - 1) >= census_loops) continue;
    const std::string operands = lines[i].text.substr(lines[i].text.find(',') + 1);  // address, descriptor, offset
    for (std::size_t k = i; k-- > 0;) {
      if (!starts(lines[k].mnemonic, "buffer_load_dword") || lines[k].text.find(',') == std::string::npos) continue;
      if (lines[k].text.substr(lines[k].text.find(',') + 1) != operands) continue;
      marker[i] = marker[k] = true;
      // The add between them: the store's data register, written from the load's.
      const std::string data = lines[i].text.substr(lines[i].mnemonic.size(), lines[i].text.find(',') - lines[i].mnemonic.size());
      for (std::size_t a = k + 1; a < i; ++a)
        if (starts(lines[a].mnemonic, "v_add") && lines[a].text.find(data.substr(data.find_first_not_of(' ')) + ",") ==
                                                       lines[a].mnemonic.size() + 1) {
          marker[a] = true;
          break;
        }
      marked[static_cast<std::size_t>(offset / 4 - 1)].push_back(innermost(i));
      break;
    }
  }
  // Costs: the straight part, and each region's own instructions (markers left out).
  std::vector<CodeCost> region_cost(regions.size());
  IsaCostModel m;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (marker[i]) continue;
    const int r = innermost(i);
    CodeCost& c = r < 0 ? m.straight : region_cost[static_cast<std::size_t>(r)];
    c.cycles += issue_cycles(lines[i].mnemonic, model);
    c.loads += vector_memory_load(lines[i].mnemonic) ? 1.0 : 0.0;
  }
  std::vector<bool> region_marked(regions.size(), false);
  m.loop_bodies.assign(census_loops, CodeCost{});
  m.in_loop.assign(census_loops, false);
  for (std::size_t j = 0; j < census_loops; ++j) {
    std::vector<int> in;
    for (int r : marked[j])
      if (r >= 0 && std::find(in.begin(), in.end(), r) == in.end()) in.push_back(r);
    if (in.empty()) continue;  // unrolled, or never reached: its code is in the straight part
    m.in_loop[j] = true;
    // A function's loop inlined at several calls: one count for all of them, each copy the same
    // code. A loop unrolled k times inside its ISA loop has k markers there: a run is 1/k of it.
    for (int r : in) {
      const double copies = static_cast<double>(std::count(marked[j].begin(), marked[j].end(), r));
      const double share = 1.0 / (static_cast<double>(in.size()) * copies);
      region_marked[static_cast<std::size_t>(r)] = true;
      m.loop_bodies[j].cycles += region_cost[static_cast<std::size_t>(r)].cycles * share;
      m.loop_bodies[j].loads += region_cost[static_cast<std::size_t>(r)].loads * share;
    }
  }
  for (std::size_t r = 0; r < regions.size(); ++r)
    if (!region_marked[r]) {  // a loop no census count is in: counted as if it ran once
      ++m.unmarked_loops;
      m.straight.cycles += region_cost[r].cycles;
      m.straight.loads += region_cost[r].loads;
    }
  return m;
}

}  // namespace pn
