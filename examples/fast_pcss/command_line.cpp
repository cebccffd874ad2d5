#include "command_line.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <system_error>

#include "scene_setup.h"

namespace example {

namespace fs = std::filesystem;

std::string common_usage(const std::string& out) {
  return "  --model PATH  a mesh file Assimp reads (default /usr/share/assimp/models/OBJ/spider.obj)\n"
         "  --out DIR     writes DIR/<model>_fast_pcss_lit.png and _visibility.png (default " + out + ");\n"
         "  --out F.png   writes F.png and F_visibility.png\n"
         "  --size N      screen size, 16..4096 (default 512)\n"
         "  --bias B      Fast PCSS depth bias in light-depth units, >= 0 (default 0.02)\n";
}

bool read_common_option(int argc, char** argv, int& i, CommonOptions& o) {
  const std::string flag = argv[i];
  if (flag != "--model" && flag != "--out" && flag != "--size" && flag != "--bias") return false;
  if (i + 1 >= argc) throw std::invalid_argument(flag + ": expected a value");
  const std::string value = argv[++i];
  std::size_t used = 0;
  const auto number = [&](auto parse) {
    try {
      const auto v = parse(value, &used);
      if (used == value.size()) return v;
    } catch (const std::logic_error&) {
    }
    throw std::invalid_argument(flag + " '" + value + "': expected a number");
  };
  if (flag == "--model") o.model = value;
  else if (flag == "--out") o.out = value;
  else if (flag == "--size") o.size = number([](const std::string& s, std::size_t* n) { return std::stoi(s, n); });
  else o.bias = number([](const std::string& s, std::size_t* n) { return std::stof(s, n); });
  return true;
}

void check_common_options(const CommonOptions& o) {
  static_assert(kDefaultScreenSize == 512 && kDepthBias == 0.02f, "CommonOptions' defaults are scene_setup.h's");
  if (o.size < 16 || o.size > 4096)
    throw std::invalid_argument("--size " + std::to_string(o.size) + ": expected 16..4096");
  if (!(o.bias >= 0.0f) || !std::isfinite(o.bias)) throw std::invalid_argument("--bias: expected a finite number >= 0");
}

Outputs plan_outputs(const CommonOptions& o) {
  Outputs out;
  if (o.out.extension() == ".png") {
    out.directory = o.out.parent_path().empty() ? fs::path(".") : o.out.parent_path();
    out.lit = o.out;
    out.visibility = out.directory / (o.out.stem().string() + "_visibility.png");
  } else {
    const std::string stem = o.model.stem().string();
    out.directory = o.out;
    out.lit = o.out / (stem + "_fast_pcss_lit.png");
    out.visibility = o.out / (stem + "_fast_pcss_visibility.png");
  }
  fs::path existing = fs::absolute(out.directory);
  while (!fs::exists(existing) && existing.has_relative_path()) existing = existing.parent_path();
  if (!fs::is_directory(existing))
    throw std::invalid_argument("--out '" + o.out.string() + "': " + existing.string() + " is not a directory");
  if (fs::is_directory(out.lit))
    throw std::invalid_argument("--out '" + o.out.string() + "': " + out.lit.string() + " is a directory");
  return out;
}

void make_directory(const fs::path& directory) {
  std::error_code ec;
  fs::create_directories(directory, ec);
  if (ec) throw std::runtime_error("'" + directory.string() + "': cannot be made a directory (" + ec.message() + ")");
}

}  // namespace example
