#include "core/write_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>

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

// A temporary file of its own in the target's directory (issue 26 B7, B10): a short name
// no other writer uses (two processes writing one output each rename their own), made with
// O_EXCL, mode 0666 less the umask like any output; the name never lengthens the target's.
struct Temporary {
  fs::path path;
  int fd = -1;
};
Temporary create_temporary(const fs::path& target, const fs::path& requested) {
  const fs::path directory = fs::absolute(target).parent_path();
  std::random_device entropy;
  for (int attempt = 0; attempt < 64; ++attempt) {
    char name[32];
    std::snprintf(name, sizeof name, ".pn-%08x%08x.tmp", entropy(), entropy());
    const fs::path candidate = directory / name;
    const int fd = ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) return {candidate, fd};
    if (errno != EEXIST)
      throw Error("output '" + requested.string() + "': cannot be written (" + std::strerror(errno) + ")");
  }
  throw Error("output '" + requested.string() + "': cannot be written (no free temporary name)");
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

  const Temporary temporary = create_temporary(path, requested);
  for (size_t done = 0; done < text.size();) {
    const ssize_t n = ::write(temporary.fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const std::string reason = std::strerror(n < 0 ? errno : EIO);
      ::close(temporary.fd);
      fs::remove(temporary.path, ec);
      throw Error("output '" + requested.string() + "': write failed (" + reason + ")");
    }
    done += static_cast<size_t>(n);
  }
  if (::close(temporary.fd) != 0) {
    const std::string reason = std::strerror(errno);
    fs::remove(temporary.path, ec);
    throw Error("output '" + requested.string() + "': write failed (" + reason + ")");
  }
  fs::rename(temporary.path, path, ec);
  if (ec) {
    fs::remove(temporary.path);
    throw Error("output '" + requested.string() + "': cannot be replaced (" + ec.message() + ")");
  }
}

}  // namespace pn
