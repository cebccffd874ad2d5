#include "png_file.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <system_error>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb/stb_image_write.h>

namespace example {

std::string encode_png(const FloatImage& image) {
  std::vector<unsigned char> rgb(static_cast<std::size_t>(image.width) * image.height * 3);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const std::size_t from = (static_cast<std::size_t>(image.height - 1 - y) * image.width + x) * image.channels +
                                 std::min(c, image.channels - 1);  // GL's bottom row becomes the PNG's last
        const float v = image.texels[from];
        rgb[(static_cast<std::size_t>(y) * image.width + x) * 3 + c] =
            static_cast<unsigned char>(std::lround(255.0f * std::clamp(std::isfinite(v) ? v : 0.0f, 0.0f, 1.0f)));
      }
  std::string png;
  const auto append = [](void* out, void* data, int size) {
    static_cast<std::string*>(out)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
  };
  if (!stbi_write_png_to_func(append, &png, image.width, image.height, 3, rgb.data(), image.width * 3))
    throw std::runtime_error("PNG encoding failed");
  return png;
}

void write_files(const std::vector<std::pair<std::filesystem::path, std::string>>& files) {
  std::vector<std::filesystem::path> temporaries;
  const auto discard = [&] {
    std::error_code ignored;
    for (const auto& t : temporaries) std::filesystem::remove(t, ignored);
  };
  for (const auto& [path, bytes] : files) {
    temporaries.push_back(path.string() + ".partial");
    std::ofstream out(temporaries.back(), std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) {
      discard();
      throw std::runtime_error("'" + path.string() + "': cannot be written");
    }
  }
  for (std::size_t i = 0; i < files.size(); ++i) {
    std::error_code ec;
    std::filesystem::rename(temporaries[i], files[i].first, ec);
    if (ec) {
      discard();
      throw std::runtime_error("'" + files[i].first.string() + "': cannot be written (" + ec.message() + ")");
    }
  }
}

}  // namespace example
