// Where one compiled stage came from when the executor may take it from elsewhere than the glsl
// root: `check --api hlsl --hlsl-root DIR` (vk/hlsl_root.h) runs DIR/X.hlsl for the compute entry
// X when it has one. The Vulkan executor records one for every stage it compiles under a root,
// and each check says which it ran (check/report.cpp), so no check runs the library's export in
// place of a copy in silence.
#pragma once

#include <string>

namespace pn {

struct PassOrigin {
  std::string pass;     // the entry, "exports/pcf.comp"
  std::string copy;     // the copy's file it ran ("r/pcf.hlsl"), or "" for the library's own export
  std::string why_not;  // when copy is "": why, a reason many passes share ("no copy of it in r")
  std::string detail;   // that pass's own part of it, or "" ("PN_EXPORT_SUM_TABLE=1")
};

}  // namespace pn
