#include "core/write_file.h"

#include <fcntl.h>
#include <limits.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <random>

#include "core/error.h"

namespace fs = std::filesystem;

namespace pn {
namespace {

// Writes `text` straight into an existing file that is not a regular one (a device, a FIFO):
// there is nothing to replace, and renaming a temporary over it would destroy the node.
// The descriptor `path` names (/dev/stdout 1, /dev/stderr 2, /dev/fd/N, /proc/self/fd/N), or -1.
int named_descriptor(const fs::path& path) {
  const std::string name = path.lexically_normal().string();
  if (name == "/dev/stdout") return 1;
  if (name == "/dev/stderr") return 2;
  for (const std::string prefix : {"/dev/fd/", "/proc/self/fd/"}) {
    if (name.rfind(prefix, 0) != 0 || name.size() == prefix.size() || name.size() > prefix.size() + 9) continue;
    const std::string digits = name.substr(prefix.size());
    if (digits.find_first_not_of("0123456789") == std::string::npos) return std::stoi(digits);
  }
  return -1;
}

void write_in_place(const fs::path& path, const std::string& text) {
  // A descriptor the caller opened is written as opened (issue 39 C13): reopening /dev/stdout would
  // truncate a file the shell opened to append to.
  if (const int fd = named_descriptor(path); fd >= 0) {
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    for (size_t done = 0; done < text.size();) {
      const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0)
        throw Error("output '" + path.string() + "': write failed (" + std::strerror(n < 0 ? errno : EIO) + ")");
      done += static_cast<size_t>(n);
    }
    return;
  }
  std::ofstream file(path, std::ios::binary);
  if (!file) throw Error("output '" + path.string() + "': cannot be written");
  file << text;
  if (!file.flush()) throw Error("output '" + path.string() + "': write failed");
}

// The temporaries being written, for the signal handler (remove_temporaries_on_signals): a
// fixed table of paths, each slot claimed with an atomic flag, so the handler reads only
// memory that stays put and calls only unlink (async-signal-safe).
constexpr int kTemporarySlots = 16;
struct TemporarySlot {
  std::atomic<int> state{0};  // 0 free, 1 being filled, 2 holds a path
  char path[PATH_MAX] = {};
};
TemporarySlot g_temporaries[kTemporarySlots];

int register_temporary(const fs::path& path) {
  const std::string text = path.string();
  if (text.size() >= PATH_MAX) return -1;
  for (int i = 0; i < kTemporarySlots; ++i) {
    int expected = 0;
    if (!g_temporaries[i].state.compare_exchange_strong(expected, 1)) continue;
    std::memcpy(g_temporaries[i].path, text.c_str(), text.size() + 1);
    g_temporaries[i].state.store(2);
    return i;
  }
  return -1;  // more than 16 at once: that one is not cleaned up on a signal
}

void release_temporary(int slot) {
  if (slot >= 0) g_temporaries[slot].state.store(0);
}

extern "C" void remove_temporaries_and_reraise(int signal) {
  for (TemporarySlot& slot : g_temporaries)
    if (slot.state.load() == 2) ::unlink(slot.path);
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}


// The name limit of `directory`'s file system (NAME_MAX where it does not say).
long name_limit(const fs::path& directory) {
  const long limit = ::pathconf(directory.c_str(), _PC_NAME_MAX);
  return limit > 0 ? limit : NAME_MAX;
}

// A temporary file of its own in `directory` (issue 26 B7, B10): a short name no other
// writer uses (two processes writing one output each rename their own), made with O_EXCL,
// mode 0666 less the umask like any output; the name never lengthens the target's. Its path is
// in the signal handler's table before the file exists, so no signal between the two leaves it
// behind (another thread may take the signal: blocking it here would not do). fd -1, errno set,
// when none can be made. The caller releases `slot` once the file is renamed or removed.
struct Temporary {
  fs::path path;
  int fd = -1;
  int slot = -1;
};
Temporary open_temporary(const fs::path& directory) {
  std::random_device entropy;
  for (int attempt = 0; attempt < 64; ++attempt) {
    char name[32];
    std::snprintf(name, sizeof name, ".pn-%08x%08x.tmp", entropy(), entropy());
    const fs::path candidate = directory / name;
    const int slot = register_temporary(candidate);
    const int fd = ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) return {candidate, fd, slot};
    const int reason = errno;
    release_temporary(slot);
    errno = reason;
    if (reason != EEXIST) return {candidate, fd, -1};
  }
  return {};  // errno: EEXIST, no free name
}

Temporary create_temporary(const fs::path& target, const fs::path& requested) {
  const Temporary temporary = open_temporary(fs::absolute(target).parent_path());
  if (temporary.fd < 0)
    throw Error("output '" + requested.string() + "': cannot be written (" +
                (errno == EEXIST ? std::string("no free temporary name") : std::strerror(errno)) + ")");
  return temporary;
}

// The OS's reason a file cannot be made in `directory` (empty when it can: one made and removed).
std::string cannot_write_reason(const fs::path& directory) {
  const Temporary probe = open_temporary(directory);
  if (probe.fd < 0) return std::strerror(errno);
  ::close(probe.fd);
  ::unlink(probe.path.c_str());
  release_temporary(probe.slot);
  return "";
}

// Where a write to `requested` lands (issue 39 C12, C13, C14). `special`: an existing file that is
// not a regular one, reached by any links (/dev/stdout -> /proc/self/fd/1 -> a pipe): written in
// place through `requested` itself, which the kernel follows. Otherwise `path` is `requested`, or for
// a symbolic link the file it points to, followed link by link (each relative to its own
// directory), which may be missing: a dangling link's target is made, the link stays. A loop, or a
// link that cannot be read, is refused.
struct OutputTarget {
  fs::path path;
  bool special = false;
};
OutputTarget resolve_output_target(const fs::path& requested) {
  std::error_code ec;
  // A descriptor the caller opened (`-o /dev/stdout > file`, `>> file`): written through it, as the
  // shell set it up, whatever it is; renaming over the file it names would undo an append.
  if (named_descriptor(requested) >= 0) return {requested, true};
  const fs::file_status followed = fs::status(requested, ec);
  if (fs::exists(followed)) {
    if (!fs::is_regular_file(followed)) return {requested, true};
  } else if (ec && ec.value() == ELOOP) {
    throw Error("output '" + requested.string() + "': its link cannot be followed (a loop of symbolic links)");
  }
  fs::path path = requested;
  for (int hops = 0;; ++hops) {
    if (!fs::is_symlink(fs::symlink_status(path, ec))) return {path, false};
    if (hops == 40)
      throw Error("output '" + requested.string() + "': its link cannot be followed (a loop of symbolic links)");
    const fs::path target = fs::read_symlink(path, ec);
    if (ec) throw Error("output '" + requested.string() + "': its link cannot be read (" + ec.message() + ")");
    path = target.is_absolute() ? target : fs::absolute(path).parent_path() / target;
  }
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

namespace {

// Each of `names` legal in `directory` (or, while it does not exist, in `existing`, its nearest
// existing ancestor) and not there as something a write cannot replace.
void check_output_names(const fs::path& directory, const fs::path& existing, const std::vector<std::string>& names) {
  const long most = name_limit(existing);
  for (const std::string& name : names) {
    const fs::path path = directory / name;
    if (static_cast<long>(name.size()) > most)
      throw Error("output '" + path.string() + "': its name has " + std::to_string(name.size()) +
                  " bytes, expected at most " + std::to_string(most) + " (the file system's limit; use a shorter technique name)");
    if (fs::absolute(path).string().size() >= PATH_MAX)
      throw Error("output '" + path.string() + "': its path is longer than " + std::to_string(PATH_MAX - 1) + " bytes");
    std::error_code ec;
    const fs::file_status status = fs::symlink_status(path, ec);
    if (fs::exists(status) && !fs::is_regular_file(status) && !fs::is_symlink(status))
      throw Error("output '" + path.string() + "': " + (fs::is_directory(status) ? "is a directory" : "is not a regular file") +
                  ", expected a file or nothing there");
  }
}

// A set's name that is a symbolic link (issue 39 C9): refused when it leads out of `directory`
// (a render or figures into D writes D, not a file elsewhere) or onto another of the set's files
// (two pictures would be one file).
void check_output_links(const fs::path& directory, const std::vector<std::string>& names) {
  std::error_code ec;
  if (!fs::is_directory(directory, ec)) return;  // made by this run: no links in it
  const fs::path home = fs::weakly_canonical(fs::absolute(directory), ec);
  std::vector<std::pair<std::string, fs::path>> links;
  for (const std::string& name : names) {
    const fs::path path = directory / name;
    if (!fs::is_symlink(fs::symlink_status(path, ec))) continue;
    const OutputTarget target = resolve_output_target(path);
    const fs::path lands = fs::weakly_canonical(fs::absolute(target.path), ec);
    if (target.special || lands.parent_path() != home)
      throw Error("output '" + path.string() + "': a link to '" + (target.special ? path : lands).string() +
                  "', outside the output directory: expected a file or nothing there");
    links.emplace_back(name, lands);
  }
  for (const auto& [name, lands] : links)
    for (const std::string& other : names)
      if (other != name && lands == home / other)
        throw Error("output '" + (directory / name).string() + "': a link to '" + other +
                    "', another file of this run: expected a file or nothing there");
}

}  // namespace

std::vector<fs::path> prepare_output_directory(const fs::path& directory, const std::vector<std::string>& names) {
  validate_output_directory(directory);
  std::error_code ec;
  std::vector<fs::path> missing;  // deepest first
  fs::path existing = fs::absolute(directory, ec);
  while (!existing.empty() && !fs::exists(existing, ec) && existing != existing.parent_path())
    missing.push_back(existing), existing = existing.parent_path();
  check_output_names(directory, existing, names);
  check_output_links(directory, names);
  fs::create_directories(directory, ec);
  if (ec) throw Error("output directory '" + directory.string() + "': cannot be created (" + ec.message() + ")");
  const std::string reason = cannot_write_reason(directory);
  if (!reason.empty()) {
    for (const fs::path& made : missing) fs::remove(made, ec);  // empty: nothing was written
    throw Error("output directory '" + directory.string() + "': cannot be written (" + reason + ")");
  }
  return missing;
}

void probe_output_file(const fs::path& path) {
  validate_output_path(path);
  const OutputTarget target = resolve_output_target(path);
  if (target.special) {
    if (::access(path.c_str(), W_OK) != 0)
      throw Error("output '" + path.string() + "': cannot be written (" + std::strerror(errno) + ")");
    return;
  }
  std::error_code ec;
  if (target.path != path && fs::is_directory(target.path, ec))
    throw Error("output '" + path.string() + "': its link points to a directory, expected a file");
  const fs::path directory = fs::absolute(target.path).parent_path();
  if (!fs::is_directory(directory, ec))
    throw Error("output '" + path.string() + "': its link points into '" + directory.string() +
                "', which is not a directory");
  check_output_names(directory, directory, {target.path.filename().string()});
  const std::string reason = cannot_write_reason(directory);
  if (!reason.empty()) throw Error("output '" + path.string() + "': cannot be written (" + reason + ")");
}

void require_distinct_outputs(const std::vector<std::pair<std::string, fs::path>>& outputs) {
  const auto where = [](const fs::path& path) {
    const OutputTarget target = resolve_output_target(path);
    std::error_code ec;
    const fs::path canonical = fs::weakly_canonical(fs::absolute(target.path, ec), ec);
    return ec ? fs::absolute(target.path).lexically_normal() : canonical;
  };
  for (size_t i = 0; i < outputs.size(); ++i)
    for (size_t j = i + 1; j < outputs.size(); ++j) {
      const auto& [first_name, first] = outputs[i];
      const auto& [second_name, second] = outputs[j];
      if (first.empty() || second.empty()) continue;
      std::error_code ec;
      const bool same = fs::equivalent(first, second, ec) || where(first) == where(second);
      if (same)
        throw Error(second_name + " '" + second.string() + "': names the same file as " + first_name + " '" +
                    first.string() + "': expected another file (one would overwrite the other)");
    }
}

void remove_temporaries_on_signals() {
  for (int signal : {SIGINT, SIGTERM, SIGHUP}) std::signal(signal, remove_temporaries_and_reraise);
  std::signal(SIGXFSZ, SIG_IGN);  // past `ulimit -f`: write() fails with EFBIG, reported and cleaned up
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
  // A symbolic link stays one: the file it points to is what gets replaced (or made).
  const OutputTarget target = resolve_output_target(requested);
  if (target.special) return write_in_place(requested, text);
  const fs::path& path = target.path;
  if (path != requested) validate_output_path(path);

  const Temporary temporary = create_temporary(path, requested);
  struct Release {
    int slot;
    ~Release() { release_temporary(slot); }
  } release{temporary.slot};
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
