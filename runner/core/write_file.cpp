#include "core/write_file.h"

#include <fstream>

#include "core/error.h"

namespace fs = std::filesystem;

namespace pn {

void write_file_atomically(const fs::path& path, const std::string& text) {
  const fs::path temporary = path.string() + ".partial";
  std::error_code ec;
  {
    std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
    if (!file) throw Error("output '" + path.string() + "': cannot be written");
    file << text;
    if (!file.flush()) {
      file.close();
      fs::remove(temporary, ec);
      throw Error("output '" + path.string() + "': write failed");
    }
  }
  fs::rename(temporary, path, ec);
  if (ec) {
    fs::remove(temporary, ec);
    throw Error("output '" + path.string() + "': cannot be replaced");
  }
}

}  // namespace pn
