#include "shader/loop_guard.h"

#include <algorithm>
#include <cctype>

#include "core/error.h"

namespace pn {
namespace {

bool identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

// The index just past the identifier that starts at `i` (`i` when none does).
size_t identifier_end(const std::string& s, size_t i) {
  while (i < s.size() && identifier_char(s[i])) ++i;
  return i;
}

bool loop_keyword(const std::string& word) { return word == "for" || word == "while" || word == "do"; }

// The module file and line of position `at` in the flattened source (ShaderSource::origin_of_line).
std::pair<std::string, int> origin_of(const ShaderSource& source, size_t at) {
  const std::string& s = source.text;
  return source.origin_of_line(static_cast<int>(std::count(s.begin(), s.begin() + static_cast<std::ptrdiff_t>(at), '\n')) + 1);
}

// The index just past the comment starting at `i`, or `i` when none starts there.
size_t skip_comment(const std::string& s, size_t i) {
  if (s.compare(i, 2, "//") == 0) {
    const size_t end = s.find('\n', i);
    return end == std::string::npos ? s.size() : end;
  }
  if (s.compare(i, 2, "/*") == 0) {
    const size_t end = s.find("*/", i + 2);
    return end == std::string::npos ? s.size() : end + 2;
  }
  return i;
}

size_t skip_space(const std::string& s, size_t i) {
  while (i < s.size()) {
    if (std::isspace(static_cast<unsigned char>(s[i])) != 0) ++i;
    else if (const size_t after = skip_comment(s, i); after != i) i = after;
    else break;
  }
  return i;
}

// For the bracket at `open` ('(' or '{'): the index of the one that closes it, and of each
// ';' at its own depth inside it (a for header's two).
struct Bracketed {
  size_t close = std::string::npos;
  std::vector<size_t> semicolons;
};

Bracketed match_bracket(const std::string& s, size_t open) {
  const char opening = s[open], closing = opening == '(' ? ')' : '}';
  Bracketed b;
  int depth = 0;
  for (size_t i = open; i < s.size();) {
    if (const size_t after = skip_comment(s, i); after != i) {
      i = after;
      continue;
    }
    if (s[i] == opening) ++depth;
    else if (s[i] == closing && --depth == 0) {
      b.close = i;
      return b;
    } else if (s[i] == ';' && depth == 1) b.semicolons.push_back(i);
    ++i;
  }
  return b;
}

std::string trimmed(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t\n\r"), b = s.find_last_not_of(" \t\n\r");
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

bool is_identifier(const std::string& s) {
  return !s.empty() && std::isdigit(static_cast<unsigned char>(s[0])) == 0 &&
         std::all_of(s.begin(), s.end(), identifier_char);
}

// A compile-time constant as modules write bounds: integer literals, ALL_CAPS macro names,
// `NAME.length()`, + - * / and parentheses.
bool is_constant_bound(const std::string& e) {
  if (trimmed(e).empty()) return false;
  for (size_t i = 0; i < e.size();) {
    const char c = e[i];
    if (std::isupper(static_cast<unsigned char>(c)) != 0 || c == '_') {
      while (i < e.size() && (std::isupper(static_cast<unsigned char>(e[i])) != 0 ||
                              std::isdigit(static_cast<unsigned char>(e[i])) != 0 || e[i] == '_'))
        ++i;
      if (e.compare(i, 9, ".length()") == 0) i += 9;
    } else if (std::isdigit(static_cast<unsigned char>(c)) != 0 || std::string(" \t+-*/()u").find(c) != std::string::npos) {
      ++i;
    } else {
      return false;
    }
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
  for (const char* builtin : {"modf", "frexp", "uaddCarry", "usubBorrow", "umulExtended", "imulExtended"})
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

// The source's object-like macros: name -> replacement text (the last #define wins; function-
// like macros are left out: their bodies are read where they are used, below).
using Macros = std::vector<std::pair<std::string, std::string>>;

Macros object_macros(const std::string& s) {
  Macros macros;
  for (size_t at = s.find("#define"); at != std::string::npos; at = s.find("#define", at + 1)) {
    size_t i = skip_space(s, at + 7);
    const size_t e = identifier_end(s, i);
    if (e == i || (e < s.size() && s[e] == '(')) continue;
    const size_t line_end = s.find('\n', e);
    std::string text = s.substr(e, (line_end == std::string::npos ? s.size() : line_end) - e);
    const size_t comment = text.find("//");
    if (comment != std::string::npos) text.erase(comment);
    macros.emplace_back(s.substr(i, e - i), trimmed(text));
  }
  return macros;
}

const std::string* find_macro(const Macros& macros, const std::string& name) {
  for (auto it = macros.rbegin(); it != macros.rend(); ++it)
    if (it->first == name) return &it->second;
  return nullptr;
}

// The value of an integer constant expression (literals, + - * / and parentheses, the source's
// macros expanded), or -1 when it is not one this reader can evaluate or exceeds 2^40.
class ConstantReader {
 public:
  ConstantReader(const Macros& macros, int depth = 0) : macros_(macros), depth_(depth) {}
  long long read(const std::string& text) {
    text_ = text, at_ = 0, ok_ = depth_ < 8;
    const long long v = sum();
    space();
    return ok_ && at_ == text_.size() && v >= 0 && v <= (1LL << 40) ? v : -1;
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
    if (at_ >= text_.size()) return ok_ = false, 0;
    const char c = text_[at_];
    if (c == '(') {
      ++at_;
      const long long v = sum();
      space();
      if (at_ >= text_.size() || text_[at_] != ')') return ok_ = false, 0;
      ++at_;
      return v;
    }
    if (c == '-') return ++at_, -term();
    if (std::isdigit(static_cast<unsigned char>(c)) != 0) {
      long long v = 0;
      while (at_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[at_])) != 0)
        v = clamp(v * 10 + (text_[at_++] - '0'));
      if (at_ < text_.size() && (text_[at_] == 'u' || text_[at_] == 'U')) ++at_;
      return v;
    }
    const size_t e = identifier_end(text_, at_);
    const std::string* value = e > at_ ? find_macro(macros_, text_.substr(at_, e - at_)) : nullptr;
    if (value == nullptr) return ok_ = false, 0;
    at_ = e;
    const long long v = ConstantReader(macros_, depth_ + 1).read(*value);
    if (v < 0) ok_ = false;
    return v;
  }

  const Macros& macros_;
  int depth_;
  std::string text_;
  size_t at_ = 0;
  bool ok_ = true;
};

// Whether `body` may change `name` through a macro it uses: an object-like macro whose text
// names it, or a function-like macro (its body unread here) — a counter reset through
// `#define RESET i = 0` is not seen by may_change (issue 26 B4).
bool macro_may_change(const std::string& s, const std::string& body, const std::string& name, const Macros& macros) {
  for (size_t k = 0; k < body.size();) {
    if (!identifier_char(body[k])) {
      ++k;
      continue;
    }
    const size_t e = identifier_end(body, k);
    const std::string word = body.substr(k, e - k);
    k = e;
    if (const std::string* text = find_macro(macros, word)) {
      for (size_t at = text->find(name); at != std::string::npos; at = text->find(name, at + 1))
        if ((at == 0 || !identifier_char((*text)[at - 1])) &&
            (at + name.size() >= text->size() || !identifier_char((*text)[at + name.size()])))
          return true;
    } else if (s.find("#define " + word + "(") != std::string::npos) {
      return true;
    }
  }
  return false;
}

// `for (T i = A; i < B; ++i) body` with B a compile-time constant, a step of ++i, i++ or
// i += a positive literal, and a body that does not touch i (nor use a macro that may): at most
// B - A iterations by construction — when B - A is within the guard's limit. Such loops stay as they are, so that the compiler still unrolls them (a
// guarded loop is not unrolled, and llvmpipe caps each loop's iterations at 65535).
bool bounded_by_construction(const std::string& s, size_t open, const Bracketed& p,
                             const std::vector<CallArgument>& written, const Macros& macros, unsigned limit) {
  const std::string init = s.substr(open + 1, p.semicolons[0] - open - 1);
  const std::string condition = trimmed(s.substr(p.semicolons[0] + 1, p.semicolons[1] - p.semicolons[0] - 1));
  const std::string step = trimmed(s.substr(p.semicolons[1] + 1, p.close - p.semicolons[1] - 1));
  const size_t eq = init.find('=');
  if (eq == std::string::npos) return false;
  const std::string declared = trimmed(init.substr(0, eq));
  const size_t space = declared.find_last_of(" \t");
  const std::string name = space == std::string::npos ? declared : declared.substr(space + 1);
  if (!is_identifier(name)) return false;
  const size_t less = condition.find('<');
  if (less == std::string::npos || trimmed(condition.substr(0, less)) != name) return false;
  const size_t bound = condition.compare(less, 2, "<=") == 0 ? less + 2 : less + 1;
  if (!is_constant_bound(condition.substr(bound))) return false;
  // A bound past the guard's limit is no bound for the guard (issue 26 B4: `i < 2000000000` ran
  // 80 s on llvmpipe, silently capped, and failed naming no loop): guarded like any other.
  const long long most = ConstantReader(macros).read(condition.substr(bound));
  const long long start = ConstantReader(macros).read(init.substr(eq + 1));
  if (most >= 0 && most - std::max(start, 0LL) > static_cast<long long>(limit)) return false;
  bool step_ok = step == "++" + name || step == name + "++";
  if (!step_ok && step.compare(0, name.size(), name) == 0) {
    const std::string rest = trimmed(step.substr(name.size()));
    if (rest.compare(0, 2, "+=") == 0) {
      const std::string amount = trimmed(rest.substr(2));
      step_ok = !amount.empty() && std::all_of(amount.begin(), amount.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }) &&
                std::stoul(amount.substr(0, 9)) > 0;
    }
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
  const std::string body = s.substr(first, end - first + 1);
  return !may_change(body, name, written) && !macro_may_change(s, body, name, macros);
}

struct Insertion {
  size_t at;
  std::string text;
};

std::string guard_call(size_t id) { return "pnLoopGuard(" + std::to_string(id) + "u)"; }

// One counter per loop, so that the limit reads as llvmpipe's own cap does: a loop's
// iterations summed over all its entries in one invocation.
std::string guard_prelude(const LoopGuardSettings& settings, size_t loops) {
  const std::string limit = std::to_string(settings.iterations) + "u";
  const std::string n = std::to_string(std::max<size_t>(loops, 1));
  std::string zeros;
  for (size_t k = 0; k < std::max<size_t>(loops, 1); ++k) zeros += k == 0 ? "0u" : ", 0u";
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

// The guard reads the source before the preprocessor: a loop that a macro spells
// (`#define REPEAT while`, or a keyword pasted together with ##) would run unguarded
// — a driver may then drop it and the check pass (issue 26 B3). Such a #define is
// refused, naming its line: the loop has to be written out where it runs.
void refuse_macro_loops(const ShaderSource& source, size_t start) {
  const std::string& s = source.text;
  for (size_t line_start = start; line_start < s.size();) {
    size_t line_end = s.find('\n', line_start);
    // A directive continues over lines that end in a backslash.
    while (line_end != std::string::npos && line_end > line_start && s[line_end - 1] == '\\') line_end = s.find('\n', line_end + 1);
    if (line_end == std::string::npos) line_end = s.size();
    size_t i = line_start;
    while (i < line_end && (s[i] == ' ' || s[i] == '\t')) ++i;
    if (i < line_end && s[i] == '#') {
      ++i;
      while (i < line_end && (s[i] == ' ' || s[i] == '\t')) ++i;
      if (s.compare(i, 6, "define") == 0) {
        // The directive without its comments, as tokens.
        std::string text;
        for (size_t k = i + 6; k < line_end;) {
          if (const size_t after = skip_comment(s, k); after != k) {
            text += ' ';
            k = after;
          } else {
            text += s[k++];
          }
        }
        bool refused = text.find("##") != std::string::npos;
        for (size_t k = 0; k < text.size() && !refused;) {
          if (!identifier_char(text[k])) {
            ++k;
            continue;
          }
          const size_t e = identifier_end(text, k);
          refused = loop_keyword(text.substr(k, e - k));
          k = e;
        }
        if (refused) {
          const auto [file, file_line] = origin_of(source, line_start);
          throw Error(file + ":" + std::to_string(file_line) +
                      ": a #define that spells a loop keyword (for, while, do) or pastes tokens (##): the loop guard "
                      "cannot bound a loop a macro writes; expected the loop written out");
        }
      }
    }
    line_start = line_end + 1;
  }
}

}  // namespace

std::vector<GuardedLoop> guard_loops(ShaderSource& source, const LoopGuardSettings& settings) {
  std::string& s = source.text;
  // The prelude goes before the first #line marker: lines up to there map to "<wrapper>".
  size_t start = s.find("\n#line ");
  start = start == std::string::npos ? s.size() : start + 1;
  refuse_macro_loops(source, start);

  std::vector<Insertion> edits;
  std::vector<GuardedLoop> loops;
  const std::vector<CallArgument> written = written_arguments(s);
  const Macros macros = object_macros(s);
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
      if (bounded_by_construction(s, open, parens, written, macros, settings.iterations)) continue;
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
  s.insert(start, guard_prelude(settings, loops.size()));
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
