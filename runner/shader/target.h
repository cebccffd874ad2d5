// The three GLSL targets every module must compile for (SPEC §2), and the
// standalone wrapper that turns a flattened module into a whole compute shader
// for one of them. Lint, bundle and the GL passes all use this one wrapper.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "shader/flatten.h"

namespace pn {

enum class Target { gl450, vulkan, es310 };

const std::vector<Target>& all_targets();
const char* target_name(Target target);  // "gl450", "vulkan", "es310"
Target parse_target(const std::string& name);  // throws Error naming the accepted values

struct Define {
  std::string name;
  std::string value;
};

// The key a set of defines is kept under (a pass compiled once per set): "NAME=value;" for each, in order.
std::string define_key(const std::vector<Define>& defines);

// A whole shader: `#version` and (for ES) default precisions, the defines,
// the flattened source and, when it has no main(), a minimal 1×1×1 compute
// entry point. `files` extends the flattened file table with the entry point.
struct ShaderSource {
  std::string text;
  std::vector<std::string> files;
  Stage stage = Stage::compute;

  // `text` with every `#line` marker blanked, for GL drivers: their logs
  // disagree on source-string numbers (Mesa prints 0 whatever `#line` says),
  // so driver messages are mapped back by physical line instead.
  std::string driver_text() const;

  // File and line that physical line `line` (1-based) of `text` came from;
  // the file is "<wrapper>" for the #version/precision/define prelude.
  std::pair<std::string, int> origin_of_line(int line) const;
};

ShaderSource standalone_source(const FlatSource& flat, Target target,
                               const std::vector<Define>& defines = {});

}  // namespace pn
