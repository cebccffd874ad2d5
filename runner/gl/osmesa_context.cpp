// OSMesa backend: Mesa's off-screen renderer, for machines whose EGL cannot
// give a core context. Optional at build time (Mesa 25.1 removed OSMesa).
// Desktop GL only: OSMesa makes no OpenGL ES contexts.
#include "core/error.h"
#include "gl/context.h"

#ifdef PENUMBRA_HAVE_OSMESA
#include <GL/osmesa.h>
#include <dlfcn.h>

#include <array>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace pn {
namespace {

// libOSMesa is opened when an OSMesa context is made, not linked: it pulls in libLLVM, whose
// relocation cost every start of the tool ~0.1 s (docs/reliability.md, the suite's time) though
// only this backend uses it. The four entry points the context calls, from the library.
struct OsmesaEntryPoints {
  decltype(&OSMesaCreateContextAttribs) create_context_attribs = nullptr;
  decltype(&OSMesaMakeCurrent) make_current = nullptr;
  decltype(&OSMesaGetProcAddress) get_proc_address = nullptr;
  decltype(&OSMesaDestroyContext) destroy_context = nullptr;
};

OsmesaEntryPoints open_osmesa() {
  void* library = nullptr;
  std::string tried;
  for (const char* name : {"libOSMesa.so.8", "libOSMesa.so", PENUMBRA_OSMESA_LIBRARY}) {
    library = dlopen(name, RTLD_NOW | RTLD_LOCAL);  // never closed: Mesa's own state lives as long as the process
    if (library != nullptr) break;
    tried += (tried.empty() ? "" : ", ") + std::string(name);
  }
  if (library == nullptr) throw Error("OSMesa: no libOSMesa could be opened (tried " + tried + ")");
  OsmesaEntryPoints e;
  const auto symbol = [&](const char* name) {
    void* f = dlsym(library, name);
    if (f == nullptr) throw Error(std::string("OSMesa: libOSMesa has no ") + name);
    return f;
  };
  e.create_context_attribs = reinterpret_cast<decltype(e.create_context_attribs)>(symbol("OSMesaCreateContextAttribs"));
  e.make_current = reinterpret_cast<decltype(e.make_current)>(symbol("OSMesaMakeCurrent"));
  e.get_proc_address = reinterpret_cast<decltype(e.get_proc_address)>(symbol("OSMesaGetProcAddress"));
  e.destroy_context = reinterpret_cast<decltype(e.destroy_context)>(symbol("OSMesaDestroyContext"));
  return e;
}

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
  // The driver's name refused before the library is opened, as before Mesa sees it.
  OsmesaContext() : Context(Backend::osmesa), osmesa_((require_software_gallium_driver(), open_osmesa())) {
    const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0,
                              OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION, 4, OSMESA_CONTEXT_MINOR_VERSION, 5, 0};
    context_ = osmesa_.create_context_attribs(attributes, nullptr);
    if (context_ == nullptr) throw Error("OSMesaCreateContextAttribs for OpenGL 4.5 core failed");
    // OSMesa needs a colour buffer to be current; all real work goes to FBOs.
    if (!osmesa_.make_current(context_, pixel_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
      osmesa_.destroy_context(context_);
      throw Error("OSMesaMakeCurrent failed");
    }
    try {
      load(reinterpret_cast<GLADloadfunc>(osmesa_.get_proc_address));
    } catch (...) {
      osmesa_.destroy_context(context_);
      throw;
    }
  }
  ~OsmesaContext() override { osmesa_.destroy_context(context_); }

 private:
  OsmesaEntryPoints osmesa_;
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
