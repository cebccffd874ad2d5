#include "scene/model.h"

#include <algorithm>
#include <assimp/DefaultIOSystem.h>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <cerrno>
#include <fcntl.h>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstring>
#include <fstream>
#include <limits>
#include <new>
#include <string>
#include <thread>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/error.h"
#include "core/format.h"

namespace pn {
namespace {

namespace fs = std::filesystem;

std::string model_name(const fs::path& file) { return "model '" + file.string() + "'"; }

// Assimp's messages may span lines; an Error's message is one line.
std::string one_line(const std::string& text) {
  std::string out;
  for (char c : text) {
    const bool space = c == '\n' || c == '\r' || c == '\t' || c == ' ';
    if (space && (out.empty() || out.back() == ' ')) continue;
    out += space ? ' ' : c;
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out.empty() ? "no reason given" : out;
}

// What Assimp would otherwise report in its own words, or not at all: a path
// that is not a readable, non-empty regular file within the size limit.
void check_model_file(const fs::path& file, const ModelLimits& limits) {
  const std::string name = model_name(file);
  std::error_code ec;
  const fs::file_status status = fs::status(file, ec);
  if (status.type() == fs::file_type::not_found) throw Error(name + ": no such file");
  if (ec) throw Error(name + ": cannot be read: " + ec.message());
  if (fs::is_directory(status)) throw Error(name + ": is a directory, expected a mesh file");
  if (!fs::is_regular_file(status)) throw Error(name + ": not a regular file, expected a mesh file");
  if (!std::ifstream(file, std::ios::binary)) throw Error(name + ": cannot be read: " + std::strerror(errno));
  const std::uintmax_t bytes = fs::file_size(file, ec);
  if (ec) throw Error(name + ": cannot be read: " + ec.message());
  if (bytes == 0) throw Error(name + ": empty file, expected a mesh file (glTF, OBJ or another format Assimp reads)");
  if (bytes > limits.max_file_bytes)
    throw Error(name + ": " + std::to_string(bytes) + " bytes, expected at most " + std::to_string(limits.max_file_bytes));
}

// Faces of `min_corners` or more corners (also run before validation: no pointer trusted).
std::size_t count_faces(const aiScene& scene, unsigned min_corners) {
  std::size_t count = 0;
  for (unsigned m = 0; m < scene.mNumMeshes && scene.mMeshes != nullptr; ++m) {
    const aiMesh* mesh = scene.mMeshes[m];
    if (mesh == nullptr || mesh->mFaces == nullptr) continue;
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) count += mesh->mFaces[f].mNumIndices >= min_corners;
  }
  return count;
}

// Assimp's file access with the model's own rule for every file it opens (a glTF's buffers, an
// OBJ's material library, …): a regular file or nothing. A FIFO or a device named by a model
// would block the import or read without end; refused, it is a file Assimp cannot open.
class RegularFilesOnly : public Assimp::DefaultIOSystem {
 public:
  bool Exists(const char* path) const override { return regular(path) && DefaultIOSystem::Exists(path); }
  Assimp::IOStream* Open(const char* path, const char* mode) override {
    return regular(path) ? DefaultIOSystem::Open(path, mode) : nullptr;
  }

 private:
  static bool regular(const char* path) {
    std::error_code ec;
    return path != nullptr && fs::is_regular_file(fs::status(path, ec));
  }
};

std::vector<glm::vec3> read_triangles(const fs::path& file, const ModelLimits& limits) {
  const std::string name = model_name(file);
  const auto unreadable = [&](const Assimp::Importer& importer) {
    const std::string reason = one_line(importer.GetErrorString());
    if (reason == "std::bad_alloc") throw std::bad_alloc();  // Assimp caught the memory limit: say so
    return Error(name + ": not a mesh file Assimp can read: " + reason);
  };
  Assimp::Importer importer;  // owns the scene it returns; Assimp logs nowhere unless a logger is created
  importer.SetIOHandler(new RegularFilesOnly);  // the importer owns it
  // Read as is first: a file without a polygon (only vertices, points or lines) is "no triangles",
  // not the validation's "mesh contains no faces" or "mNumMeshes is 0".
  const aiScene* scene = importer.ReadFile(file.string(), 0);
  if (scene == nullptr) throw unreadable(importer);
  if (count_faces(*scene, 3) == 0)
    throw Error(name + ": no triangles (points and lines are ignored), expected a triangle mesh");
  // Then validated (indices in range), polygons split into triangles, node transforms baked into
  // the vertices (a mesh that several nodes draw is repeated).
  scene = importer.ApplyPostProcessing(aiProcess_ValidateDataStructure | aiProcess_Triangulate |
                                       aiProcess_PreTransformVertices);
  if (scene == nullptr) throw unreadable(importer);

  const std::size_t triangles = count_faces(*scene, 3);  // every polygon is a triangle now
  if (triangles > limits.max_triangles)
    throw Error(name + ": " + std::to_string(triangles) + " triangles, expected at most " +
                std::to_string(limits.max_triangles));
  std::vector<glm::vec3> out;
  out.reserve(3 * triangles);
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh& mesh = *scene->mMeshes[m];
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;  // a point or a line
      for (unsigned k = 0; k < 3; ++k) {
        const aiVector3D& v = mesh.mVertices[face.mIndices[k]];  // in range: validated
        out.emplace_back(v.x, v.y, v.z);
      }
    }
  }
  return out;
}

// The child's address space and resident memory now (/proc/self/statm's first two fields).
std::uintmax_t statm_bytes(int field) {
  std::ifstream statm("/proc/self/statm");
  std::uintmax_t pages[2] = {0, 0};
  statm >> pages[0] >> pages[1];
  return pages[field] * static_cast<std::uintmax_t>(sysconf(_SC_PAGESIZE));
}
[[maybe_unused]] std::uintmax_t address_space_bytes() { return statm_bytes(0); }
[[maybe_unused]] std::uintmax_t resident_bytes() { return statm_bytes(1); }

// The child's exit status when the sanitizer builds' memory watchdog ends it.
constexpr int kMemoryLimitExit = 86;

std::string memory_limit_message(const fs::path& file, const ModelLimits& limits) {
  return model_name(file) + ": its import needs more than " + std::to_string(limits.max_import_bytes >> 20) +
         " MiB of memory (the import's limit), expected a model that imports within it";
}

// read_triangles with every exception as an Error's message: "" when it succeeded.
std::string read_triangles_or_message(const fs::path& file, const ModelLimits& limits, std::vector<glm::vec3>& out) {
  try {
    out = read_triangles(file, limits);
    return "";
  } catch (const Error& e) {
    return e.what();
  } catch (const std::bad_alloc&) {  // the child's memory limit (limit_import)
    return memory_limit_message(file, limits);
  } catch (const std::exception& e) {  // Assimp's own: never past this function
    return model_name(file) + ": cannot be read: " + one_line(e.what());
  } catch (...) {
    return model_name(file) + ": cannot be read: unknown failure in Assimp";
  }
}

bool write_all(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = write(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    data += n, size -= static_cast<std::size_t>(n);
  }
  return true;
}

// The import child's limits (docs/reliability.md, "The import child's limits"): at most
// limits.max_import_bytes of address space beyond what it starts with (an allocation past it
// fails: std::bad_alloc, one line), and limits.max_import_seconds of wall-clock time (SIGALRM
// ends it). A file Assimp expands without end (its own invalid/OutOfMemory.off, a glTF whose
// nodes share children) is refused in seconds instead of taking the machine's memory.
// Sanitizer builds reserve terabytes of shadow address space, which RLIMIT_AS would count:
// there a watchdog thread bounds the resident memory instead.
void limit_import(const ModelLimits& limits) {
#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
  const std::uintmax_t most = address_space_bytes() + limits.max_import_bytes;
  const rlimit memory{static_cast<rlim_t>(most), static_cast<rlim_t>(most)};
  setrlimit(RLIMIT_AS, &memory);
#else
  // A watchdog on the resident memory instead: the child ends itself (kMemoryLimitExit) once it
  // holds max_import_bytes more than it started with.
  const std::uintmax_t most = resident_bytes() + limits.max_import_bytes;
  std::thread([most] {
    for (;;) {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      if (resident_bytes() > most) _exit(kMemoryLimitExit);
    }
  }).detach();
#endif
  alarm(static_cast<unsigned>(limits.max_import_seconds));
}

// Assimp 5.2.5 (Debian 12) reads out of bounds on some malformed files: fuzz_model found a
// 24-byte OFF file that makes it crash (docs/reliability.md, "Fuzzing"), and OSS-Fuzz lists many
// more in its importers. So the import runs in a child process, which sends back 'T' and the
// triangles' floats, or 'E' and the error's message: a crash inside Assimp costs the child,
// and the parent reports the file as bad input; the child's memory and time are limited
// (limit_import).
std::vector<glm::vec3> read_triangles_in_child(const fs::path& file, const ModelLimits& limits) {
  const std::string name = model_name(file);
  int pipe_fds[2];
  if (pipe(pipe_fds) != 0) throw Error(name + ": cannot be read: pipe: " + std::strerror(errno));
  std::fflush(nullptr);  // nothing buffered is written twice
  const pid_t parent = getpid();
  const pid_t child = fork();
  if (child < 0) {
    const int error = errno;
    close(pipe_fds[0]), close(pipe_fds[1]);
    throw Error(name + ": cannot be read: fork: " + std::strerror(error));
  }
  if (child == 0) {
    close(pipe_fds[0]);
    prctl(PR_SET_PDEATHSIG, SIGKILL);  // not left running (a hang in Assimp) when the parent dies
    if (getppid() != parent) _exit(1);
    // Assimp and its parsers print to the standard streams ("nullptr returned by creating DDLNode."
    // for an empty OpenGEX camera, issue 39 C18): the import's only voice is its reply, so an
    // error stays one line. A sanitizer build keeps standard error for the sanitizer's report.
    const int null = open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (null >= 0) {
      dup2(null, STDOUT_FILENO);
#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
      dup2(null, STDERR_FILENO);
#endif
      close(null);
    }
    limit_import(limits);
    std::vector<glm::vec3> triangles;
    const std::string message = read_triangles_or_message(file, limits, triangles);
    const bool sent = message.empty()
                          ? write_all(pipe_fds[1], "T", 1) &&
                                write_all(pipe_fds[1], reinterpret_cast<const char*>(triangles.data()),
                                          triangles.size() * sizeof(glm::vec3))
                          : write_all(pipe_fds[1], "E", 1) && write_all(pipe_fds[1], message.data(), message.size());
    _exit(sent ? 0 : 1);  // no atexit handlers, no destructors: they belong to the parent
  }
  close(pipe_fds[1]);
  std::string reply;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = read(pipe_fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    reply.append(buffer, static_cast<std::size_t>(n));
  }
  close(pipe_fds[0]);
  int status = 0;
  while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  const bool exited = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  const bool whole = !reply.empty() && (reply[0] == 'E' || (reply[0] == 'T' && (reply.size() - 1) % sizeof(glm::vec3) == 0));
  if (!exited || !whole) {
    if (WIFEXITED(status) && WEXITSTATUS(status) == kMemoryLimitExit) throw Error(memory_limit_message(file, limits));
    if (WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM)
      throw Error(name + ": its import took longer than " + std::to_string(limits.max_import_seconds) +
                  " s (the import's time limit), expected a model that imports within it");
    const std::string how = WIFSIGNALED(status) ? "crashed (signal " + std::to_string(WTERMSIG(status)) + ")"
                            : WIFEXITED(status) ? "failed (exit " + std::to_string(WEXITSTATUS(status)) + ")"
                                                : "failed";
    throw Error(name + ": not a mesh file Assimp can read: its importer " + how + " on it");
  }
  if (reply[0] == 'E') throw Error(reply.substr(1));
  std::vector<glm::vec3> triangles((reply.size() - 1) / sizeof(glm::vec3));
  if (!triangles.empty()) std::memcpy(triangles.data(), reply.data() + 1, reply.size() - 1);
  return triangles;
}

}  // namespace

std::vector<glm::vec3> load_model_triangles(const fs::path& file, const ModelLimits& limits) {
  check_model_file(file, limits);
  return read_triangles_in_child(file, limits);
}

std::vector<glm::vec3> place_model_on_ground(const std::vector<glm::vec3>& triangles, const fs::path& file) {
  // In double, so that the extent of coordinates near FLT_MAX does not overflow.
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const glm::vec3& v : triangles) {
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
      throw Error(model_name(file) + ": a vertex coordinate is not finite, expected finite coordinates");
    lo = glm::min(lo, glm::dvec3(v)), hi = glm::max(hi, glm::dvec3(v));
  }
  const glm::dvec3 extent = hi - lo;
  const double longest = std::max({extent.x, extent.y, extent.z});
  const double scale = kModelFitSide / longest;
  if (!(longest > 0) || !std::isfinite(scale)) {
    // Far from the origin float cannot hold a small size: 1e30 + 1 is 1e30 (issue 26).
    const double farthest = std::max({std::fabs(lo.x), std::fabs(lo.y), std::fabs(lo.z), std::fabs(hi.x),
                                      std::fabs(hi.y), std::fabs(hi.z)});
    if (farthest >= 0x1p24)  // float's spacing there is 1 or more
      throw Error(model_name(file) + ": zero extent at float precision (coordinates near " +
                  format_number("%g", farthest) + " hold no size below " + format_number("%g", farthest * 0x1p-23) +
                  "), expected a model near the origin");
    throw Error(model_name(file) + ": zero extent (every vertex at one point), expected a model with a size");
  }
  // The origin of the placed model: the centre of its footprint, at its lowest point.
  const glm::dvec3 base(0.5 * (lo.x + hi.x), lo.y, 0.5 * (lo.z + hi.z));
  std::vector<glm::vec3> out;
  out.reserve(triangles.size());
  for (const glm::vec3& v : triangles) out.emplace_back((glm::dvec3(v) - base) * scale);
  return out;
}

Scene make_model_scene(const fs::path& file, int shadow_map_size, float light_width, const ModelLimits& limits) {
  // The ground and the light exactly as the box scenes have them: a random-boxes fixture with no boxes.
  const fixtures::SceneFixture ground_only{"", fixtures::SceneKind::random_boxes, 0, 0, light_width};
  Scene scene = make_scene(ground_only, shadow_map_size);
  scene.name = file.stem().string();
  scene.mesh = place_model_on_ground(load_model_triangles(file, limits), file);
  return scene;
}

}  // namespace pn
