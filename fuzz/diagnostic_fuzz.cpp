// Fuzz target: the diagnostic mapper (shader/diagnostic) with both location
// maps the runner gives it — glslang's, by `#line` file number
// (shader/glslang_compiler.cpp), and the GL driver's, by physical line of the
// wrapped source through ShaderSource::origin_of_line (gl/compute_program.cpp).
//
// Input: a compiler log; or, when a line is exactly "//---", a shader text
// (with its `#line LINE FILE` markers) before it and the log after it. The
// shader's file table is fixed: a.glsl, b.glsl, passes/c.comp.
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "fuzz_input.h"
#include "shader/diagnostic.h"
#include "shader/target.h"

namespace {

// What standalone_source makes of a module that includes another.
const char* const kDefaultSource =
    "#version 450 core\n"
    "// #line file numbers:\n//   0  a.glsl\n//   1  b.glsl\n"
    "#line 1 0\n"
    "#line 1 1\n"
    "float b() { return 1.0; }\n"
    "#line 2 0\n"
    "float a() { return b(); }\n"
    "#line 1 2\n"
    "layout(local_size_x = 1) in;\nvoid main() {}\n";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::vector<std::string> parts = pn::fuzz::split_parts(pn::fuzz::as_text(data, size), "//---", 2);
  pn::ShaderSource source;
  source.text = parts.size() == 2 ? parts[0] : kDefaultSource;
  source.files = {"a.glsl", "b.glsl", "passes/c.comp"};
  const std::string& log = parts.back();
  const std::string entry = source.files.front();

  const pn::LocationMap by_file_number = [&](int number, int line) {
    const auto n = static_cast<size_t>(number);
    return std::pair<std::string, int>{n < source.files.size() ? source.files[n] : entry, line};
  };
  const pn::LocationMap by_physical_line = [&](int, int line) { return source.origin_of_line(line); };
  try {
    for (const pn::LocationMap* map : {&by_file_number, &by_physical_line})
      for (const pn::Diagnostic& d : pn::parse_info_log(log, *map, entry)) (void)d.str();
    (void)source.driver_text();
  } catch (const pn::Error&) {
    // refused with a message
  }
  return 0;
}
