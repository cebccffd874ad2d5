// Flattening: a module and everything it includes as one GLSL string, for
// drivers and engines without `#include` support (filament's Includes.cpp is
// the model). Each file appears once, `#include` lines inside comments are
// ignored, cycles are refused, and every file switch is marked with an integer
// `#line LINE FILE_NUMBER` directive; `files` maps FILE_NUMBER to the path.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "shader/source_tree.h"

namespace pn {

// The shader stage of a file, from its extension: .vert and .frag are
// vertex and fragment passes; .comp passes and .glsl modules are compute.
enum class Stage { compute, vertex, fragment };
Stage stage_of(const std::filesystem::path& file);
const char* stage_name(Stage stage);  // "compute", "vertex", "fragment"

struct FlatSource {
  std::string text;                // flattened GLSL, no #version
  std::vector<std::string> files;  // file number → path relative to the glsl root
  bool has_main = false;           // the entry file (or an include) defines main()
  Stage stage = Stage::compute;    // from the entry file's extension

  // "// #line file numbers:\n//   0 blur.glsl\n..." for the top of a bundle.
  std::string file_table_comment() const;
};

// Throws Error "path:line: error: ..." for a missing include, an include
// outside the root or an include cycle (the location is the #include line).
FlatSource flatten(const SourceTree& tree, const std::filesystem::path& entry);

}  // namespace pn
