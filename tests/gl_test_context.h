// The one GL context of a GL test binary, made by its main() before Catch
// runs; the binary exits 77 (CTest: skipped) when none can be made.
#pragma once

#include "gl/context.h"

namespace pn::test {

const Context& gl_context();

}  // namespace pn::test
