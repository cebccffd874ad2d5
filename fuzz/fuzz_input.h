// What the fuzz targets share: an input cut into parts at separator lines,
// and a scratch directory for the targets whose entry point reads files.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <system_error>
#include <unistd.h>
#include <vector>

namespace pn::fuzz {

// The bytes as a string (they may hold NULs and invalid UTF-8: so may a file).
inline std::string as_text(const uint8_t* data, size_t size) { return {reinterpret_cast<const char*>(data), size}; }

// `text` cut at every line that is exactly `separator` (the separator lines dropped),
// into at most `max_parts` parts: the last part keeps the rest, separators included.
inline std::vector<std::string> split_parts(const std::string& text, std::string_view separator, size_t max_parts) {
  std::vector<std::string> parts(1);
  size_t begin = 0;
  while (begin <= text.size()) {
    size_t end = text.find('\n', begin);
    const bool last = end == std::string::npos;
    if (last) end = text.size();
    const std::string_view line(text.data() + begin, end - begin);
    if (line == separator && parts.size() < max_parts) {
      parts.emplace_back();
    } else {
      parts.back().append(line);
      if (!last) parts.back() += '\n';
    }
    if (last) break;
    begin = end + 1;
  }
  return parts;
}

// A private directory under $TMPDIR for the whole run, removed on normal exit
// (scripts/fuzz.sh points TMPDIR into its own work directory, which it removes).
class ScratchDir {
 public:
  explicit ScratchDir(const char* name) {
    std::error_code ec;
    path_ = std::filesystem::temp_directory_path(ec) / (std::string("penumbra-fuzz-") + name + "-" +
                                                        std::to_string(static_cast<long>(getpid())));
    std::filesystem::create_directories(path_, ec);
    if (ec) std::abort();  // the harness itself is broken, not the input
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const std::filesystem::path& path() const { return path_; }

  // Empties the directory (what the previous input left).
  void clear() const {
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(path_, ec)) std::filesystem::remove_all(entry.path(), ec);
  }

  // Writes `text` to `name` (relative, may name subdirectories).
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    const std::filesystem::path file = path_ / name;
    std::error_code ec;
    std::filesystem::create_directories(file.parent_path(), ec);
    std::ofstream out(file, std::ios::binary);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    if (!out) std::abort();
    return file;
  }

 private:
  std::filesystem::path path_;
};

}  // namespace pn::fuzz
