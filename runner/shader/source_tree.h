// A glsl root directory: the only place module sources are read from.
// Resolves `#include "x"` the way a C preprocessor resolves quoted includes —
// first next to the including file, then at the root — and refuses any path
// whose canonical form leaves the root.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace pn {

class SourceTree {
 public:
  // Throws Error when `root` is not a readable directory.
  explicit SourceTree(const std::filesystem::path& root);

  const std::filesystem::path& root() const { return root_; }

  // Canonical absolute path of a file named on the command line or by a check
  // (absolute, relative to the working directory, or relative to the root).
  // Throws Error when it does not exist or lies outside the root.
  std::filesystem::path locate(const std::filesystem::path& file) const;

  // The same for a file the runner itself names (its passes: "passes/blur.comp"): a relative name
  // is taken from the root only, whatever the working directory holds (a `passes/` folder in the
  // working directory must never stand in for the root's). Throws Error like locate.
  std::filesystem::path locate_in_root(const std::filesystem::path& file) const;

  // Canonical path for `#include "requested"` written in `includer`.
  // Throws Error (message without location) when the file is missing or outside the root.
  std::filesystem::path resolve_include(const std::filesystem::path& includer,
                                        const std::string& requested) const;

  // The path relative to the root, with '/' separators: the name in bundle tables.
  std::string display_name(const std::filesystem::path& canonical) const;

  // The path as diagnostics print it: relative to the working directory when
  // the file lies below it, absolute otherwise (so editors can jump to it).
  std::string diagnostic_path(const std::filesystem::path& canonical) const;

  // The largest module file read (16 MiB): the library's largest is a few tens of KiB.
  static constexpr std::uintmax_t kMaxSourceBytes = 16u << 20;

  // Whole file contents. Throws Error when unreadable, not a regular file, or larger than kMaxSourceBytes.
  std::string read(const std::filesystem::path& canonical) const;

 private:
  bool inside_root(const std::filesystem::path& canonical) const;
  std::filesystem::path root_;
};

}  // namespace pn
