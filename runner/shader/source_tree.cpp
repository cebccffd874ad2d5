#include "shader/source_tree.h"

#include <cstdlib>
#include <fstream>
#include <mutex>
#include <sstream>

#include "core/error.h"

namespace fs = std::filesystem;

namespace pn {

namespace {

// PENUMBRA_SOURCE_LOG=FILE: each file read is appended to FILE, one name a line, relative to the
// root (tests/mutation/mutate.py learns from it which modules a check's passes read). A test's
// hook: a log that cannot be opened is not written, and never fails the command.
void log_read(const std::string& name) {
  static std::mutex mutex;
  const char* log = std::getenv("PENUMBRA_SOURCE_LOG");
  if (log == nullptr || *log == '\0') return;
  std::lock_guard<std::mutex> lock(mutex);
  std::ofstream out(log, std::ios::app);
  if (out) out << name << '\n';
}

}  // namespace

SourceTree::SourceTree(const fs::path& root) {
  std::error_code ec;
  fs::path canonical = fs::canonical(root, ec);
  if (ec || !fs::is_directory(canonical))
    throw Error("glsl root '" + root.string() + "': expected an existing directory of GLSL modules");
  root_ = canonical;
}

bool SourceTree::inside_root(const fs::path& canonical) const {
  auto rel = canonical.lexically_relative(root_);
  return !rel.empty() && *rel.begin() != "..";
}

fs::path SourceTree::locate(const fs::path& file) const {
  std::error_code ec;
  // A relative name is first taken from the working directory, then from the root.
  fs::path candidate = file;
  if (file.is_relative() && !fs::exists(file, ec)) candidate = root_ / file;
  fs::path canonical = fs::canonical(candidate, ec);
  if (ec)
    throw Error("'" + file.string() + "': no such file (looked in the working directory and in '" +
                root_.string() + "')");
  if (!fs::is_regular_file(canonical))
    throw Error("'" + file.string() + "': expected a GLSL file, found a directory or special file");
  if (!inside_root(canonical))
    throw Error("'" + file.string() + "': expected a file inside the glsl root '" + root_.string() + "'");
  return canonical;
}

fs::path SourceTree::locate_in_root(const fs::path& file) const {
  std::error_code ec;
  const fs::path canonical = fs::canonical(file.is_relative() ? root_ / file : file, ec);
  if (ec) throw Error("'" + file.string() + "': no such file in the glsl root '" + root_.string() + "'");
  if (!fs::is_regular_file(canonical))
    throw Error("'" + file.string() + "': expected a GLSL file, found a directory or special file");
  if (!inside_root(canonical))
    throw Error("'" + file.string() + "': expected a file inside the glsl root '" + root_.string() + "'");
  return canonical;
}

fs::path SourceTree::resolve_include(const fs::path& includer, const std::string& requested) const {
  if (requested.empty()) throw Error("#include \"\": expected a file name");
  if (fs::path(requested).is_absolute())
    throw Error("#include \"" + requested + "\": expected a path relative to the glsl root, not an absolute path");
  std::error_code ec;
  for (const fs::path& base : {includer.parent_path(), root_}) {
    fs::path candidate = (base / requested).lexically_normal();
    if (!inside_root(candidate))
      throw Error("#include \"" + requested + "\": leaves the glsl root '" + root_.string() + "'");
    if (!fs::exists(candidate, ec)) continue;
    fs::path canonical = fs::canonical(candidate, ec);
    if (ec || !inside_root(canonical))
      throw Error("#include \"" + requested + "\": resolves outside the glsl root '" + root_.string() + "'");
    // A directory opens and reads as an empty file: it would be included as one (fuzz_flatten).
    if (!fs::is_regular_file(canonical, ec))
      throw Error("#include \"" + requested + "\": expected a GLSL file, found a directory or special file");
    return canonical;
  }
  throw Error("#include \"" + requested + "\": no such file next to '" + diagnostic_path(includer) +
              "' or at the glsl root");
}

std::string SourceTree::display_name(const fs::path& canonical) const {
  if (inside_root(canonical)) return canonical.lexically_relative(root_).generic_string();
  return canonical.generic_string();
}

std::string SourceTree::diagnostic_path(const fs::path& canonical) const {
  std::error_code ec;
  fs::path rel = canonical.lexically_relative(fs::current_path(ec));
  if (!ec && !rel.empty() && *rel.begin() != "..") return rel.generic_string();
  return canonical.generic_string();
}

std::string SourceTree::read(const fs::path& canonical) const {
  // A FIFO or a device would block or never end; a module is text of a bounded size.
  std::error_code ec;
  const fs::file_status status = fs::status(canonical, ec);
  if (fs::exists(status) && !fs::is_regular_file(status))
    throw Error("'" + diagnostic_path(canonical) + "': not a regular file");
  const auto size = fs::file_size(canonical, ec);
  if (!ec && size > kMaxSourceBytes)
    throw Error("'" + diagnostic_path(canonical) + "': " + std::to_string(size) + " bytes: expected a GLSL file of at most " +
                std::to_string(kMaxSourceBytes) + " bytes");
  std::ifstream in(canonical, std::ios::binary);
  if (!in) throw Error("'" + diagnostic_path(canonical) + "': cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw Error("'" + diagnostic_path(canonical) + "': read failed");
  log_read(display_name(canonical));
  // A UTF-8 byte-order mark (an editor's) is not GLSL: dropped, as compilers of UTF-8 text do
  // (issue 39 C21: it used to reach the driver, which then reported "lacks `main'").
  std::string source = text.str();
  if (source.compare(0, 3, "\xEF\xBB\xBF") == 0) source.erase(0, 3);
  return source;
}

}  // namespace pn
