// Writing output files without leaving half of one behind.
#pragma once

#include <filesystem>
#include <string>

namespace pn {

// Throws Error unless `path` can name an output file: not empty, not a directory, in an
// existing directory. For commands to call before long work whose result goes there.
void validate_output_path(const std::filesystem::path& path);

// Throws Error unless `directory` is an existing directory or could be made: every missing
// part of it lies under an existing directory. For commands that make it only once their
// work has succeeded.
void validate_output_directory(const std::filesystem::path& directory);

// Writes `text` to `path` through a temporary file of its own in the same
// directory (`.pn-<random>.tmp`, O_EXCL) that is renamed over it, so a failure
// leaves no partial file and concurrent writers never share a temporary. A symbolic link stays a link (the file
// it points to is replaced); an existing file that is not a regular one (a
// device such as /dev/null, a FIFO) is written in place, never replaced.
// Throws Error naming the path (validate_output_path's errors, a failed write).
void write_file_atomically(const std::filesystem::path& path, const std::string& text);

}  // namespace pn
