#include "shader/loop_guard.h"

#include <algorithm>
#include <cctype>
#include <climits>

#include "core/error.h"
#include "shader/glslang_compiler.h"
#include "shader/source_scan.h"

namespace pn {
namespace {

std::string trimmed(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t\n\r"), b = s.find_last_not_of(" \t\n\r");
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

// `s` without its white space: the preprocessor spaces tokens its own way (`++ i`, `a . length()`).
std::string squeezed(const std::string& s) {
  std::string out;
  for (char c : s)
    if (std::isspace(static_cast<unsigned char>(c)) == 0) out += c;
  return out;
}

bool is_identifier(const std::string& s) {
  return !s.empty() && std::isdigit(static_cast<unsigned char>(s[0])) == 0 &&
         std::all_of(s.begin(), s.end(), identifier_char);
}

// `name.length()` or `block.member.length()` (squeezed): an array's length, fixed where it is
// declared (a buffer's run-time array is bounded by its buffer).
bool is_array_length(const std::string& e) {
  const std::string suffix = ".length()";
  if (e.size() <= suffix.size() || e.compare(e.size() - suffix.size(), suffix.size(), suffix) != 0) return false;
  const std::string chain = e.substr(0, e.size() - suffix.size());
  for (size_t a = 0; a <= chain.size();) {
    const size_t dot = std::min(chain.find('.', a), chain.size());
    if (!is_identifier(chain.substr(a, dot - a))) return false;
    a = dot + 1;
  }
  return true;
}

// The identifier that ends just before `end` (spaces skipped), or "".
std::string identifier_before(const std::string& s, size_t end) {
  size_t b = end;
  while (b > 0 && std::isspace(static_cast<unsigned char>(s[b - 1])) != 0) --b;
  size_t a = b;
  while (a > 0 && identifier_char(s[a - 1])) --a;
  return s.substr(a, b - a);
}

// The call whose argument list holds position `at`: its name and which argument `at` is in
// (commas at the call's own depth before it); name "" outside any call.
struct CallArgument {
  std::string name;
  int index = 0;
};

CallArgument enclosing_call(const std::string& s, size_t at) {
  int depth = 0, commas = 0;
  for (size_t i = at; i-- > 0;) {
    if (s[i] == ')') ++depth;
    else if (s[i] == ',' && depth == 0) ++commas;
    else if (s[i] == '(' && depth-- == 0) return {identifier_before(s, i), commas};
  }
  return {};
}

// Arguments a call may write: each out or inout parameter of the source's functions, by
// position, and every argument of the built-ins that have one (index -1).
std::vector<CallArgument> written_arguments(const std::string& s) {
  std::vector<CallArgument> written;
  for (const char* builtin : {"modf", "frexp", "uaddCarry", "usubBorrow", "umulExtended", "imulExtended",  // GLSL
                              "sincos", "GetDimensions", "InterlockedAdd", "InterlockedAnd", "InterlockedOr",  // HLSL
                              "InterlockedXor", "InterlockedMin", "InterlockedMax", "InterlockedExchange",
                              "InterlockedCompareExchange"})
    written.push_back({builtin, -1});
  for (const char* keyword : {"out", "inout"}) {
    const std::string k = keyword;
    for (size_t at = s.find(k); at != std::string::npos; at = s.find(k, at + 1)) {
      if ((at > 0 && identifier_char(s[at - 1])) || (at + k.size() < s.size() && identifier_char(s[at + k.size()])))
        continue;
      const size_t before = s.find_last_not_of(" \t\n\r", at == 0 ? 0 : at - 1);
      if (at == 0 || before == std::string::npos || (s[before] != '(' && s[before] != ',')) continue;
      const CallArgument parameter = enclosing_call(s, at);
      if (!parameter.name.empty()) written.push_back(parameter);
    }
  }
  return written;
}

// Whether `body` may change `name`: an assignment, ++ or -- of it, or an argument that a
// call may write (`written`).
bool may_change(const std::string& body, const std::string& name, const std::vector<CallArgument>& written) {
  for (size_t at = body.find(name); at != std::string::npos; at = body.find(name, at + 1)) {
    if (at > 0 && identifier_char(body[at - 1])) continue;
    const size_t end = at + name.size();
    if (end < body.size() && identifier_char(body[end])) continue;
    const size_t last = body.find_last_not_of(" \t\n\r", at == 0 ? 0 : at - 1);
    if (at > 0 && last != std::string::npos && last >= 1 &&
        (body.compare(last - 1, 2, "++") == 0 || body.compare(last - 1, 2, "--") == 0))
      return true;
    const size_t next = body.find_first_not_of(" \t\n\r", end);
    if (next == std::string::npos) continue;
    const std::string op = body.substr(next, 2);
    if (op == "++" || op == "--" || (op[0] == '=' && op != "==")) return true;
    if (op.size() == 2 && op[1] == '=' && std::string("+-*/%&|^").find(op[0]) != std::string::npos) return true;
    if ((op == "<<" || op == ">>") && body.compare(next + 2, 1, "=") == 0) return true;
    if (op[0] == ',' || op[0] == ')') {  // a bare argument: written if that parameter is out or inout
      const CallArgument call = enclosing_call(body, at);
      for (const CallArgument& w : written)
        if (w.name == call.name && (w.index < 0 || w.index == call.index)) return true;
    }
  }
  return false;
}

// The value of an integer constant expression of literals, + - * / and parentheses (the text
// the preprocessor leaves of a module's bound macros), or LLONG_MIN when it is not one this reader
// can evaluate or its magnitude exceeds 2^40.
class ConstantReader {
 public:
  long long read(const std::string& text) {
    text_ = text, at_ = 0, ok_ = true;
    const long long v = sum();
    space();
    return ok_ && at_ == text_.size() ? v : LLONG_MIN;
  }

 private:
  void space() { while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_])) != 0) ++at_; }
  long long clamp(long long v) { if (v > (1LL << 40) || v < -(1LL << 40)) ok_ = false; return v; }
  long long sum() {
    long long v = product();
    for (space(); ok_ && at_ < text_.size() && (text_[at_] == '+' || text_[at_] == '-'); space()) {
      const char op = text_[at_++];
      const long long w = product();
      v = clamp(op == '+' ? v + w : v - w);
    }
    return v;
  }
  long long product() {
    long long v = term();
    for (space(); ok_ && at_ < text_.size() && (text_[at_] == '*' || text_[at_] == '/'); space()) {
      const char op = text_[at_++];
      const long long w = term();
      if (op == '/' && w == 0) ok_ = false;
      else v = clamp(op == '*' ? v * w : v / w);
    }
    return v;
  }
  long long term() {
    space();
    if (!ok_ || at_ >= text_.size()) return ok_ = false, 0;
    const char c = text_[at_];
    if (c == '(') {
      ++at_;
      const long long v = sum();
      space();
      if (at_ >= text_.size() || text_[at_] != ')') return ok_ = false, 0;
      ++at_;
      return v;
    }
    if (c == '-') return ++at_, clamp(-term());
    if (c == '+') return ++at_, term();
    if (std::isdigit(static_cast<unsigned char>(c)) == 0) return ok_ = false, 0;
    long long v = 0;
    while (ok_ && at_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[at_])) != 0)
      v = clamp(v * 10 + (text_[at_++] - '0'));
    if (at_ < text_.size() && (text_[at_] == 'u' || text_[at_] == 'U')) ++at_;
    if (at_ < text_.size() && identifier_char(text_[at_])) ok_ = false;  // 0x10, 1e3, 2.0: not read here
    return v;
  }

  std::string text_;
  size_t at_ = 0;
  bool ok_ = true;
};

// `for (T i = A; i < B; ++i) body` with A and B integer constants (literals and arithmetic, as
// the preprocessor leaves a module's bound macros) or B an array's length, B - A within the
// guard's limit, a step of ++i, i++ or i += a positive literal, and a body that does not touch i:
// at most B - A iterations by construction. Such loops stay as they are, so that the compiler still
// unrolls them (a guarded loop is not unrolled, and llvmpipe caps each loop's iterations at 65535).
// A bound past the limit is no bound for the guard (issue 26 B4: `i < 2000000000` ran 80 s on
// llvmpipe, silently capped, and failed naming no loop); nor is a named constant, which the
// preprocessor does not fold (`const int N = 2000000000;`), nor a counter the loop does not
// declare (a call in the body may write a global one).
bool bounded_by_construction(const std::string& s, size_t open, const Bracketed& p,
                             const std::vector<CallArgument>& written, unsigned limit) {
  const std::string init = s.substr(open + 1, p.semicolons[0] - open - 1);
  const std::string condition = squeezed(s.substr(p.semicolons[0] + 1, p.semicolons[1] - p.semicolons[0] - 1));
  const std::string step = squeezed(s.substr(p.semicolons[1] + 1, p.close - p.semicolons[1] - 1));
  const size_t eq = init.find('=');
  if (eq == std::string::npos) return false;
  const std::string declared = trimmed(init.substr(0, eq));
  const size_t space = declared.find_last_of(" \t\n");
  if (space == std::string::npos) return false;  // `i = 0`: a counter declared elsewhere
  const std::string name = declared.substr(space + 1);
  if (!is_identifier(name) || !is_identifier(trimmed(declared.substr(0, space)))) return false;
  const size_t less = condition.find('<');
  if (less == std::string::npos || condition.substr(0, less) != name) return false;
  const size_t bound = condition.compare(less, 2, "<=") == 0 ? less + 2 : less + 1;
  const std::string most_text = condition.substr(bound);
  const long long start = ConstantReader().read(init.substr(eq + 1));
  if (start == LLONG_MIN) return false;
  if (!is_array_length(most_text)) {
    const long long most = ConstantReader().read(most_text);
    if (most == LLONG_MIN || most - start > static_cast<long long>(limit)) return false;
  }
  bool step_ok = step == "++" + name || step == name + "++";
  if (!step_ok && step.compare(0, name.size() + 2, name + "+=") == 0) {
    const std::string amount = step.substr(name.size() + 2);
    const auto digit = [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; };
    step_ok = !amount.empty() && amount.size() < 10 && std::all_of(amount.begin(), amount.end(), digit) &&
              std::stoul(amount) > 0;
  }
  if (!step_ok) return false;
  // The body: a braced block, or one simple statement (a nested loop or branch counts as unknown).
  const size_t first = skip_space(s, p.close + 1);
  if (first >= s.size()) return false;
  size_t end = std::string::npos;
  if (s[first] == '{') {
    end = match_bracket(s, first).close;
  } else {
    const std::string word = s.substr(first, identifier_end(s, first) - first);
    if (loop_keyword(word) || word == "if" || word == "switch") return false;
    end = s.find(';', first);
  }
  if (end == std::string::npos) return false;
  return !may_change(s.substr(first, end - first + 1), name, written);
}

struct Insertion {
  size_t at;
  std::string text;
};

std::string guard_call(size_t id) { return "pnLoopGuard(" + std::to_string(id) + "u)"; }

// One counter per loop, so that the limit reads as llvmpipe's own cap does: a loop's
// iterations summed over all its entries in one invocation.
std::string guard_prelude(const LoopGuardSettings& settings, GuardSyntax syntax, size_t loops) {
  const std::string limit = std::to_string(settings.iterations) + "u";
  const std::string n = std::to_string(std::max<size_t>(loops, 1));
  std::string zeros;
  for (size_t k = 0; k < std::max<size_t>(loops, 1); ++k) zeros += k == 0 ? "0u" : ", 0u";
  if (syntax == GuardSyntax::hlsl)  // as SPIRV-Cross writes a GLSL storage buffer and atomicCompSwap
    return "globallycoherent RWByteAddressBuffer pnLoopGuardState : register(u" + std::to_string(settings.binding) +
           (settings.space != 0 ? ", space" + std::to_string(settings.space) : std::string()) + ");\n"
           "static uint pnLoopGuardCounts[" + n + "] = { " + zeros + " };\n"
           "bool pnLoopGuard(uint loop) {\n"
           "  pnLoopGuardCounts[loop] += 1u;\n"
           "  if (pnLoopGuardCounts[loop] <= " + limit + " && pnLoopGuardState.Load(0) == 0u) return true;\n"
           "  uint pnLoopGuardWas;\n"
           "  if (pnLoopGuardCounts[loop] > " + limit +
           ") pnLoopGuardState.InterlockedCompareExchange(0, 0u, loop + 1u, pnLoopGuardWas);\n"
           "  return false;\n"
           "}\n";
  return "layout(std430, binding = " + std::to_string(settings.binding) +
         ") coherent buffer PnLoopGuardState { uint pnLoopGuardTripped; uint pnLoopGuardSpare; };\n"
         "uint pnLoopGuardCounts[" + n + "] = uint[" + n + "](" + zeros + ");\n"
         "bool pnLoopGuard(uint loop) {\n"
         "  pnLoopGuardCounts[loop] += 1u;\n"
         "  if (pnLoopGuardCounts[loop] <= " + limit + " && pnLoopGuardTripped == 0u) return true;\n"
         "  if (pnLoopGuardCounts[loop] > " + limit + ") atomicCompSwap(pnLoopGuardTripped, 0u, loop + 1u);\n"
         "  return false;\n"
         "}\n";
}

}  // namespace

std::vector<GuardedLoop> guard_preprocessed_loops(ShaderSource& source, const LoopGuardSettings& settings,
                                                  GuardSyntax syntax) {
  std::string& s = source.text;
  // The prelude goes before the first #line marker: lines up to there map to "<wrapper>".
  size_t start = s.compare(0, 6, "#line ") == 0 ? 0 : s.find("\n#line ");
  start = start == 0 ? 0 : start == std::string::npos ? s.size() : start + 1;

  std::vector<Insertion> edits;
  std::vector<GuardedLoop> loops;
  const std::vector<CallArgument> written = written_arguments(s);
  for (size_t i = start; i < s.size();) {
    if (const size_t after = skip_comment(s, i); after != i) {
      i = after;
      continue;
    }
    if (!identifier_char(s[i])) {
      ++i;
      continue;
    }
    const size_t end = identifier_end(s, i);
    const std::string word = s.substr(i, end - i);
    const size_t keyword = i;
    i = end;
    if (word != "for" && word != "while") continue;
    const size_t open = skip_space(s, end);
    if (open >= s.size() || s[open] != '(') continue;
    const Bracketed parens = match_bracket(s, open);
    if (parens.close == std::string::npos) continue;  // the compiler reports the syntax error
    const size_t id = loops.size();
    if (word == "while") {
      edits.push_back({open + 1, guard_call(id) + " && ("});
      edits.push_back({parens.close, ")"});
    } else {
      if (parens.semicolons.size() != 2) continue;  // not a for header the compiler accepts
      if (bounded_by_construction(s, open, parens, written, settings.iterations)) continue;
      const size_t from = parens.semicolons[0] + 1, to = parens.semicolons[1];
      const bool empty = skip_space(s, from) >= to;
      edits.push_back({from, " " + guard_call(id) + (empty ? "" : " && (")});
      if (!empty) edits.push_back({to, ")"});
    }
    const auto [file, file_line] = origin_of(source, keyword);
    loops.push_back({file, file_line});
  }
  // Back to front, so that each insertion leaves the earlier positions valid.
  std::stable_sort(edits.begin(), edits.end(), [](const Insertion& a, const Insertion& b) { return a.at > b.at; });
  for (const Insertion& e : edits) s.insert(e.at, e.text);
  s.insert(start, guard_prelude(settings, syntax, loops.size()));
  return loops;
}

std::vector<GuardedLoop> guard_loops(const GlslangProcess& process, ShaderSource& source, Target target,
                                     const LoopGuardSettings& settings) {
  const Preprocessed p = preprocess_with_glslang(process, source, target);
  throw_unless_preprocessed(p);
  source.text = p.text;
  return guard_preprocessed_loops(source, settings, GuardSyntax::glsl);
}

std::vector<GuardedLoop> guard_hlsl_loops(const GlslangProcess& process, std::string& text, const std::string& name,
                                          Stage stage, const LoopGuardSettings& settings) {
  // A marker first, so that the copy's lines map to it (origin_of_line) and the prelude goes above.
  ShaderSource source;
  source.files = {name};
  source.stage = stage;
  const Preprocessed p = preprocess_hlsl_with_glslang(process, "#line 1 0\n" + text, name, stage);
  throw_unless_preprocessed(p);
  source.text = p.text;
  std::vector<GuardedLoop> loops = guard_preprocessed_loops(source, settings, GuardSyntax::hlsl);
  text = source.text;
  return loops;
}

void throw_if_loop_tripped(const LoopGuardState& state, const std::vector<GuardedLoop>& loops, unsigned iterations,
                           const std::string& what) {
  if (state.tripped == 0) return;
  const size_t loop = state.tripped - 1;
  const std::string where = loop < loops.size() ? loops[loop].file + ":" + std::to_string(loops[loop].line) : "?";
  throw Error(what + ": the loop at " + where + " ran past " + std::to_string(iterations) +
                  " iterations in one invocation: an endless loop, or more work than a check allows (--loop-limit)",
              ExitCode::failed);
}

}  // namespace pn
