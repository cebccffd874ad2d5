#include "shader/flatten.h"

#include <regex>
#include <set>
#include <sstream>

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

    static const std::regex include_re(R"(^\s*#\s*include\s*(["<])([^">]*)([">])\s*$)");
    static const std::regex extension_re(R"(^\s*#\s*extension\s+GL_GOOGLE_include_directive\b.*$)");
    static const std::regex main_re(R"(\bvoid\s+main\s*\()");

    marker(1, number);
    std::istringstream lines(source);
    std::string line;
    bool in_block = false;
    for (int line_no = 1; std::getline(lines, line); ++line_no) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      const bool starts_in_block = in_block;
      const std::string code = strip_comments(line, in_block);
      std::smatch m;
      if (!starts_in_block && std::regex_match(code, m, include_re)) {
        include(file, line_no, m);
        marker(line_no + 1, number);
        continue;
      }
      if (!starts_in_block && std::regex_match(code, extension_re)) {
        out_.text += "\n";  // drivers reject this extension; keep the line count
        continue;
      }
      if (std::regex_search(code, main_re)) out_.has_main = true;
      out_.text += line;
      out_.text += '\n';
    }
    open_.pop_back();
    done_.insert(file);
  }

  void include(const fs::path& file, int line_no, const std::smatch& m) {
    const std::string where = tree_.diagnostic_path(file) + ":" + std::to_string(line_no) + ": error: ";
    if ((m[1] == "\"") != (m[3] == "\""))
      throw Error(where + "#include: expected \"file\" with matching quotes");
    fs::path child;
    try {
      child = tree_.resolve_include(file, m[2]);
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

FlatSource flatten(const SourceTree& tree, const fs::path& entry) {
  FlatSource flat = Flattener(tree).run(tree.locate(entry));
  flat.stage = stage_of(entry);
  return flat;
}

}  // namespace pn
