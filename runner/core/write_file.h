// Writing output files without leaving half of one behind.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace pn {

// Throws Error unless `path` can name an output file: not empty, not a directory, in an
// existing directory. For commands to call before long work whose result goes there.
void validate_output_path(const std::filesystem::path& path);

// Throws Error unless `directory` is an existing directory or could be made: every missing
// part of it lies under an existing directory. For commands that make it only once their
// work has succeeded.
void validate_output_directory(const std::filesystem::path& directory);

// Makes `directory` (and its missing parents) ready for `names` before any long work (issue 26
// B9, B10), or throws Error and leaves nothing made: each name fits the file system's name limit
// (NAME_MAX) and the whole path PATH_MAX; none is there already as something other than a
// regular file or a link (a FIFO there would block the write, a directory would refuse it); the
// directory is created, and a temporary of its own created in it and removed (the OS's reason
// when it cannot: read-only file system, permission denied, …) — on failure the directories it
// made are removed again. Returns the directories it made, deepest first (for MadeDirectories).
std::vector<std::filesystem::path> prepare_output_directory(const std::filesystem::path& directory,
                                                            const std::vector<std::string>& names);

// The directories a run made (prepare_output_directory's answer) removed again, when still
// empty, unless keep() is called: a run that fails leaves no empty --out behind (issue 39 C19).
class MadeDirectories {
 public:
  explicit MadeDirectories(std::vector<std::filesystem::path> made) : made_(std::move(made)) {}
  MadeDirectories(const MadeDirectories&) = delete;
  MadeDirectories& operator=(const MadeDirectories&) = delete;
  ~MadeDirectories() {
    std::error_code ec;
    for (const std::filesystem::path& directory : made_) std::filesystem::remove(directory, ec);  // only if empty
  }
  void keep() { made_.clear(); }

 private:
  std::vector<std::filesystem::path> made_;
};

// The same for one output file `path` (validate_output_path, then its directory probed for
// its name). An existing file that is not a regular one (a device, a FIFO: written in place)
// has to be writable.
void probe_output_file(const std::filesystem::path& path);

// Throws Error when two of `outputs` (an option's name and its path) name one file (issue 39
// C11): the same path by any spelling, a link to the other, or one device or FIFO. For commands to
// call with their probe_output_file calls, before any work.
void require_distinct_outputs(const std::vector<std::pair<std::string, std::filesystem::path>>& outputs);

// SIGINT, SIGTERM and SIGHUP remove the temporaries being written (write_file_atomically) and
// then end the process as the signal would: an interrupted run leaves no `.pn-*.tmp` behind.
// SIGXFSZ (a write past `ulimit -f`) is ignored: the write fails with EFBIG instead, reported as
// `write failed (File too large)` with its temporary removed (issue 39 C7).
// Installed once by main; the one global state of the runner (a handler can reach no other).
void remove_temporaries_on_signals();

// Writes `text` to `path` through a temporary file of its own in the same
// directory (`.pn-<random>.tmp`, O_EXCL) that is renamed over it, so a failure
// leaves no partial file and concurrent writers never share a temporary. A symbolic link stays a link (the file
// it points to is replaced, or made when it is missing: a dangling link's target; a loop is
// refused); an existing file that is not a regular one (a device such as /dev/null, a FIFO, a
// pipe behind /dev/stdout) is written in place, never replaced.
// Throws Error naming the path (validate_output_path's errors, a failed write).
void write_file_atomically(const std::filesystem::path& path, const std::string& text);

}  // namespace pn
