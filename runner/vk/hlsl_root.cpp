#include "vk/hlsl_root.h"

#include <algorithm>
#include <cctype>
#include <system_error>

#include "core/error.h"
#include "shader/source_tree.h"

namespace pn {

namespace fs = std::filesystem;

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// The stems of `folder`'s *.comp under the glsl root, sorted.
std::vector<std::string> comp_stems(const fs::path& folder) {
  std::vector<std::string> out;
  std::error_code ec;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
    if (it->path().extension() == ".comp") out.push_back(it->path().stem().string());
  std::sort(out.begin(), out.end());
  return out;
}

std::string joined(const std::vector<std::string>& names, std::size_t at_most) {
  std::string out;
  for (std::size_t i = 0; i < names.size() && i < at_most; ++i) out += (i ? ", " : "") + names[i];
  if (names.size() > at_most) out += ", … (" + std::to_string(names.size()) + " in all)";
  return out;
}

// Why `entry` (a name of an entry in the root) cannot be read as a copy, or "".
std::string unusable(const fs::path& entry) {
  std::error_code ec;
  const fs::file_status link = fs::symlink_status(entry, ec);
  const fs::file_status target = fs::status(entry, ec);
  if (fs::is_symlink(link)) {
    std::error_code read_ec;
    const fs::path to = fs::read_symlink(entry, read_ec);
    if (target.type() == fs::file_type::not_found) return "is a link to nothing (" + to.string() + ")";
    if (ec) return "is a link that cannot be followed (" + ec.message() + ")";
  }
  if (ec) return "cannot be read (" + ec.message() + ")";
  if (fs::is_directory(target)) return "is a directory";
  if (!fs::is_regular_file(target)) return "is not a regular file";
  return "";
}

}  // namespace

std::vector<std::string> hlsl_copy_names(const SourceTree& tree) {
  std::vector<std::string> names = comp_stems(tree.root() / "exports");
  for (const std::string& pass : comp_stems(tree.root() / "passes"))
    if (std::find(names.begin(), names.end(), pass) == names.end()) names.push_back(pass);
  return names;
}

std::vector<std::string> usable_hlsl_copies(const fs::path& root, const SourceTree& tree) {
  const std::string where = "--hlsl-root " + root.string() + ": ";
  std::error_code ec;
  if (!fs::is_directory(root, ec)) throw Error(where + "expected a directory of HLSL exports");
  const std::vector<std::string> entries = hlsl_copy_names(tree);
  const std::vector<std::string> exports = comp_stems(tree.root() / "exports");
  std::vector<std::string> names;  // every name in the root
  for (fs::directory_iterator it(root, ec), end; !ec && it != end; it.increment(ec))
    names.push_back(it->path().filename().string());
  if (ec) throw Error(where + "cannot be read (" + ec.message() + ")");
  std::sort(names.begin(), names.end());

  const SourceTree copies(root);
  std::vector<std::string> usable, others;
  for (const std::string& name : names) {
    if (!ends_with(lower(name), ".hlsl")) continue;
    const std::string stem = name.substr(0, name.size() - 5);
    const bool exact = ends_with(name, ".hlsl") && std::find(entries.begin(), entries.end(), stem) != entries.end();
    if (!exact) {
      const auto cased = std::find_if(entries.begin(), entries.end(),
                                      [&](const std::string& e) { return lower(e) == lower(stem); });
      if (cased != entries.end())
        throw Error(where + name + " names the entry " + *cased + " in another case (names are case-sensitive): expected " +
                    *cased + ".hlsl");
      others.push_back(name);
      continue;
    }
    const std::string why = unusable(root / name);
    if (!why.empty()) throw Error(where + name + " " + why + ": expected a regular file, the copy of " + stem);
    try {
      copies.locate_in_root(name);  // a link out of the root is refused as a module's would be
    } catch (const Error& e) {
      throw Error(where + e.what());
    }
    usable.push_back(name);
  }
  if (usable.empty())
    throw Error(where + "no HLSL copy there (" +
                (others.empty() ? std::string("no .hlsl file directly in it")
                                : "its .hlsl files name no entry: " + joined(others, 4)) +
                "): expected X.hlsl, as `penumbra bundle X.glsl --target hlsl` writes it, for an export entry X (" +
                joined(exports, 12) + ") or for a compute pass passes/X.comp");
  return usable;
}

}  // namespace pn
