#include "shader/flatten.h"

#include <cctype>
#include <set>
#include <sstream>
#include <string>

#include "core/error.h"

namespace fs = std::filesystem;

namespace pn {
namespace {

// Removes comments from one line, carrying the open-block-comment state
// across lines, so that directives inside comments are not seen.
std::string strip_comments(const std::string& line, bool& in_block) {
  std::string code;
  for (size_t i = 0; i < line.size(); ++i) {
    if (in_block) {
      if (line.compare(i, 2, "*/") == 0) { in_block = false; ++i; }
      continue;
    }
    if (line.compare(i, 2, "//") == 0) break;
    if (line.compare(i, 2, "/*") == 0) { in_block = true; ++i; code += ' '; continue; }
    code += line[i];
  }
  return code;
}

// The directives are scanned by hand, not with std::regex: libstdc++'s regex
// recurses per character and overflowed the stack on a 50,000-character line.
bool is_space(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f' || c == '\r'; }
bool is_word(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

size_t skip_spaces(const std::string& s, size_t i) {
  while (i < s.size() && is_space(s[i])) ++i;
  return i;
}

// After optional spaces, `#`, optional spaces: the position of the directive's name, or npos.
size_t directive_name(const std::string& code) {
  size_t i = skip_spaces(code, 0);
  if (i >= code.size() || code[i] != '#') return std::string::npos;
  return skip_spaces(code, i + 1);
}

bool word_at(const std::string& s, size_t i, const char* word) {
  const size_t n = std::char_traits<char>::length(word);
  return s.compare(i, n, word) == 0 && (i + n >= s.size() || !is_word(s[i + n]));
}

// `#include "name"` (or <name>, or mismatched quotes, reported by the caller): the quotes and the name.
struct IncludeLine {
  char open = 0, close = 0;
  std::string name;
};

bool parse_include(const std::string& code, IncludeLine& out) {
  size_t i = directive_name(code);
  if (i == std::string::npos || code.compare(i, 7, "include") != 0) return false;
  i = skip_spaces(code, i + 7);
  if (i >= code.size() || (code[i] != '"' && code[i] != '<')) return false;
  out.open = code[i];
  const size_t end = code.find_first_of("\">", i + 1);
  if (end == std::string::npos) return false;
  out.name = code.substr(i + 1, end - i - 1);
  out.close = code[end];
  return skip_spaces(code, end + 1) == code.size();
}

// `#extension GL_GOOGLE_include_directive ...`
bool is_include_extension(const std::string& code) {
  size_t i = directive_name(code);
  if (i == std::string::npos || !word_at(code, i, "extension")) return false;
  const size_t name = skip_spaces(code, i + 9);
  return name > i + 9 && word_at(code, name, "GL_GOOGLE_include_directive");
}

// `#line ...`
bool is_line_directive(const std::string& code) {
  const size_t i = directive_name(code);
  return i != std::string::npos && word_at(code, i, "line");
}

// `void main (` with `void` and `main` whole words.
bool declares_main(const std::string& code) {
  for (size_t i = code.find("void"); i != std::string::npos; i = code.find("void", i + 1)) {
    if ((i > 0 && is_word(code[i - 1])) || !word_at(code, i, "void")) continue;
    size_t j = skip_spaces(code, i + 4);
    if (j == i + 4 || !word_at(code, j, "main")) continue;
    j = skip_spaces(code, j + 4);
    if (j < code.size() && code[j] == '(') return true;
  }
  return false;
}

class Flattener {
 public:
  explicit Flattener(const SourceTree& tree) : tree_(tree) {}

  FlatSource run(const fs::path& entry) {
    emit(entry);
    return std::move(out_);
  }

 private:
  void emit(const fs::path& file) {
    if (done_.count(file)) return;
    const int number = static_cast<int>(out_.files.size());
    out_.files.push_back(tree_.display_name(file));
    open_.push_back(file);
    const std::string source = tree_.read(file);

    marker(1, number);
    std::istringstream lines(source);
    std::string line;
    bool in_block = false;
    for (int line_no = 1; std::getline(lines, line); ++line_no) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      const bool starts_in_block = in_block;
      const std::string code = strip_comments(line, in_block);
      IncludeLine m;
      if (!starts_in_block && parse_include(code, m)) {
        include(file, line_no, m);
        marker(line_no + 1, number);
        continue;
      }
      if (!starts_in_block && is_include_extension(code)) {
        out_.text += "\n";  // drivers reject this extension; keep the line count
        continue;
      }
      if (!starts_in_block && is_line_directive(code)) {
        // The file's own `#line N F` (issue 39 C21) would renumber what follows under a file
        // number of the flattener's table (`#line 77 9`: "<wrapper>:77"): it is replaced by the
        // flattener's marker, so a message names this file and its real line.
        marker(line_no + 1, number);
        continue;
      }
      if (declares_main(code)) out_.has_main = true;
      out_.text += line;
      out_.text += '\n';
    }
    open_.pop_back();
    done_.insert(file);
  }

  void include(const fs::path& file, int line_no, const IncludeLine& m) {
    const std::string where = tree_.diagnostic_path(file) + ":" + std::to_string(line_no) + ": error: ";
    if ((m.open == '"') != (m.close == '"'))
      throw Error(where + "#include: expected \"file\" with matching quotes");
    fs::path child;
    try {
      child = tree_.resolve_include(file, m.name);
    } catch (const Error& e) {
      throw Error(where + e.what());
    }
    for (size_t i = 0; i < open_.size(); ++i) {
      if (open_[i] != child) continue;
      std::string chain;
      for (size_t j = i; j < open_.size(); ++j) chain += tree_.display_name(open_[j]) + " -> ";
      throw Error(where + "include cycle: " + chain + tree_.display_name(child));
    }
    emit(child);
  }

  void marker(int line, int number) {
    out_.text += "#line " + std::to_string(line) + " " + std::to_string(number) + "\n";
  }

  const SourceTree& tree_;
  FlatSource out_;
  std::vector<fs::path> open_;  // the include chain being emitted, for cycle detection
  std::set<fs::path> done_;     // files already emitted once
};

}  // namespace

std::string FlatSource::file_table_comment() const {
  std::string table = "// #line file numbers:\n";
  for (size_t i = 0; i < files.size(); ++i) table += "//   " + std::to_string(i) + "  " + files[i] + "\n";
  return table;
}

Stage stage_of(const fs::path& file) {
  const std::string ext = file.extension().string();
  if (ext == ".vert") return Stage::vertex;
  if (ext == ".frag") return Stage::fragment;
  return Stage::compute;
}

const char* stage_name(Stage stage) {
  return stage == Stage::fragment ? "fragment" : stage == Stage::vertex ? "vertex" : "compute";
}

FlatSource flatten(const SourceTree& tree, const fs::path& entry) {
  FlatSource flat = Flattener(tree).run(tree.locate(entry));
  flat.stage = stage_of(entry);
  return flat;
}

}  // namespace pn
