// OSMesa backend: Mesa's off-screen renderer, for machines whose EGL cannot
// give a core context. Optional at build time (Mesa 25.1 removed OSMesa).
// Desktop GL only: OSMesa makes no OpenGL ES contexts.
#include "core/error.h"
#include "gl/context.h"

#ifdef PENUMBRA_HAVE_OSMESA
#include <GL/osmesa.h>

#include <array>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace pn {
namespace {

// OSMesa renders through a Gallium software driver picked by GALLIUM_DRIVER; Mesa 22
// dereferences a null screen when the name is anything but llvmpipe or softpipe (an unknown
// name, or a hardware driver such as zink), so any other value is refused before Mesa sees it.
void require_software_gallium_driver() {
  const char* driver = std::getenv("GALLIUM_DRIVER");
  if (driver == nullptr || *driver == '\0') return;
  const std::string name = driver;
  if (name != "llvmpipe" && name != "softpipe")
    throw Error("GALLIUM_DRIVER '" + name + "': OSMesa renders only with llvmpipe or softpipe");
}

class OsmesaContext final : public Context {
 public:
  OsmesaContext() : Context(Backend::osmesa) {
    require_software_gallium_driver();
    const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0,
                              OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION, 4, OSMESA_CONTEXT_MINOR_VERSION, 5, 0};
    context_ = OSMesaCreateContextAttribs(attributes, nullptr);
    if (context_ == nullptr) throw Error("OSMesaCreateContextAttribs for OpenGL 4.5 core failed");
    // OSMesa needs a colour buffer to be current; all real work goes to FBOs.
    if (!OSMesaMakeCurrent(context_, pixel_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
      OSMesaDestroyContext(context_);
      throw Error("OSMesaMakeCurrent failed");
    }
    try {
      load(reinterpret_cast<GLADloadfunc>(OSMesaGetProcAddress));
    } catch (...) {
      OSMesaDestroyContext(context_);
      throw;
    }
  }
  ~OsmesaContext() override { OSMesaDestroyContext(context_); }

 private:
  OSMesaContext context_ = nullptr;
  std::array<std::uint8_t, 4> pixel_{};
};

}  // namespace

std::unique_ptr<Context> create_osmesa_context(Api api) {
  if (api != Api::gl450) throw Error("no OpenGL ES contexts");
  return std::make_unique<OsmesaContext>();
}

}  // namespace pn

#else

namespace pn {
std::unique_ptr<Context> create_osmesa_context(Api) {
  throw Error("this build has no OSMesa backend (libosmesa6-dev was not found at configure time)");
}
}  // namespace pn

#endif
