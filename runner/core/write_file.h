// Writing output files without leaving half of one behind.
#pragma once

#include <filesystem>
#include <string>

namespace pn {

// Writes `text` to `path` through a temporary file that is renamed over it,
// so a failure leaves no partial file. Throws Error naming the path.
void write_file_atomically(const std::filesystem::path& path, const std::string& text);

}  // namespace pn
