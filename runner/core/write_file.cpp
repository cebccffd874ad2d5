#include "core/write_file.h"

#include <fstream>

#include "core/error.h"

namespace fs = std::filesystem;

namespace pn {
namespace {

// Writes `text` straight into an existing file that is not a regular one (a device, a FIFO):
// there is nothing to replace, and renaming a temporary over it would destroy the node.
void write_in_place(const fs::path& path, const std::string& text) {
  std::ofstream file(path, std::ios::binary);
  if (!file) throw Error("output '" + path.string() + "': cannot be written");
  file << text;
  if (!file.flush()) throw Error("output '" + path.string() + "': write failed");
}

}  // namespace

void validate_output_path(const fs::path& path) {
  std::error_code ec;
  if (path.empty()) throw Error("output '': expected a file name");
  if (fs::is_directory(path, ec)) throw Error("output '" + path.string() + "': is a directory, expected a file");
  const fs::path parent = fs::absolute(path, ec).parent_path();
  if (!fs::is_directory(parent, ec))
    throw Error("output '" + path.string() + "': its directory '" + parent.string() + "' does not exist");
}

void validate_output_directory(const fs::path& directory) {
  std::error_code ec;
  if (directory.empty()) throw Error("output directory '': expected a directory name");
  const fs::file_status status = fs::status(directory, ec);
  if (fs::exists(status)) {
    if (!fs::is_directory(status))
      throw Error("output directory '" + directory.string() + "': is not a directory");
    return;
  }
  // It will be made: its nearest existing ancestor has to be a directory.
  fs::path ancestor = fs::absolute(directory, ec).parent_path();
  while (!ancestor.empty() && !fs::exists(ancestor, ec) && ancestor != ancestor.parent_path())
    ancestor = ancestor.parent_path();
  if (!fs::is_directory(ancestor, ec))
    throw Error("output directory '" + directory.string() + "': cannot be created ('" + ancestor.string() +
                "' is not a directory)");
}

void write_file_atomically(const fs::path& requested, const std::string& text) {
  validate_output_path(requested);
  std::error_code ec;
  // A symbolic link stays one: the file it points to is what gets replaced.
  fs::path path = requested;
  if (fs::is_symlink(fs::symlink_status(requested, ec))) {
    path = fs::weakly_canonical(requested, ec);
    if (ec) throw Error("output '" + requested.string() + "': its link cannot be followed");
  }
  const fs::file_status status = fs::status(path, ec);
  if (fs::exists(status) && !fs::is_regular_file(status)) return write_in_place(path, text);

  const fs::path temporary = path.string() + ".partial";
  {
    std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
    if (!file) throw Error("output '" + requested.string() + "': cannot be written");
    file << text;
    if (!file.flush()) {
      file.close();
      fs::remove(temporary, ec);
      throw Error("output '" + requested.string() + "': write failed");
    }
  }
  fs::rename(temporary, path, ec);
  if (ec) {
    fs::remove(temporary, ec);
    throw Error("output '" + requested.string() + "': cannot be replaced");
  }
}

}  // namespace pn
