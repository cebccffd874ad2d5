// A throw-away directory of GLSL files for tests of include handling.
#pragma once

#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <string>

namespace pn::test {

class TempTree {
 public:
  using Files = std::map<std::string, std::string>;
  explicit TempTree(const Files& files) {
    std::random_device rd;
    root_ = std::filesystem::temp_directory_path() / ("penumbra-test-" + std::to_string(rd()) + std::to_string(rd()));
    for (const auto& [name, text] : files) {
      const auto path = root_ / name;
      std::filesystem::create_directories(path.parent_path());
      std::ofstream(path) << text;
    }
    std::filesystem::create_directories(root_);
  }
  ~TempTree() {
    std::error_code ec;
    std::filesystem::remove_all(root_, ec);
  }
  TempTree(const TempTree&) = delete;
  TempTree& operator=(const TempTree&) = delete;
  const std::filesystem::path& root() const { return root_; }

 private:
  std::filesystem::path root_;
};

}  // namespace pn::test
