#include "viewer/gl/offscreen_context.h"

#include <dlfcn.h>

#include <stdexcept>

#include "meshtrace/io/image.h"
#include "viewer/gl/gl_api.h"

namespace meshtrace::gl {

namespace {
// From <GL/osmesa.h>, which cannot be included next to gl_api.h (it pulls
// in <GL/gl.h> and its prototypes).
constexpr int OSMESA_FORMAT = 0x22, OSMESA_DEPTH_BITS = 0x30, OSMESA_PROFILE = 0x33,
              OSMESA_CORE_PROFILE = 0x34, OSMESA_CONTEXT_MAJOR_VERSION = 0x36,
              OSMESA_CONTEXT_MINOR_VERSION = 0x37, OSMESA_RGBA = GL_RGBA;
using OSMesaContext = void*;
using CreateContextAttribs = OSMesaContext (*)(const int*, OSMesaContext);
using MakeCurrent = GLboolean (*)(OSMesaContext, void*, GLenum, GLsizei, GLsizei);
using DestroyContext = void (*)(OSMesaContext);
using GetProcAddress = void* (*)(const char*);

GetProcAddress getProcAddress = nullptr;

void* loadProc(const char* name) { return reinterpret_cast<void*>(getProcAddress(name)); }

template <typename F>
F symbol(void* library, const char* name) {
  void* p = dlsym(library, name);
  if (!p) throw std::runtime_error(std::string("libOSMesa lacks ") + name);
  return reinterpret_cast<F>(p);
}
}  // namespace

OffscreenContext::OffscreenContext(int width, int height)
    : width_(width), height_(height), buffer_(static_cast<std::size_t>(width) * height * 4) {
  library_ = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL);
  if (!library_) library_ = dlopen("libOSMesa.so", RTLD_NOW | RTLD_LOCAL);
  if (!library_) throw std::runtime_error(std::string("cannot load libOSMesa: ") + dlerror());
  const auto create = symbol<CreateContextAttribs>(library_, "OSMesaCreateContextAttribs");
  const auto makeCurrent = symbol<MakeCurrent>(library_, "OSMesaMakeCurrent");
  getProcAddress = symbol<GetProcAddress>(library_, "OSMesaGetProcAddress");
  const int attribs[] = {OSMESA_FORMAT,
                         OSMESA_RGBA,
                         OSMESA_DEPTH_BITS,
                         0,
                         OSMESA_PROFILE,
                         OSMESA_CORE_PROFILE,
                         OSMESA_CONTEXT_MAJOR_VERSION,
                         3,
                         OSMESA_CONTEXT_MINOR_VERSION,
                         3,
                         0};
  context_ = create(attribs, nullptr);
  if (!context_) throw std::runtime_error("OSMesa could not create a GL 3.3 core context");
  if (!makeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width, height))
    throw std::runtime_error("OSMesaMakeCurrent failed");
  if (const char* missing = loadFunctions(&loadProc))
    throw std::runtime_error(std::string("OSMesa lacks the GL function ") + missing);
}

OffscreenContext::~OffscreenContext() {
  if (context_) symbol<DestroyContext>(library_, "OSMesaDestroyContext")(context_);
  // libOSMesa stays loaded: its threads and atexit handlers may outlive us.
}

std::vector<std::uint8_t> readFramebufferRgb(int width, int height) {
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * height * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  // GL rows run bottom-up; alpha is dropped (it may be below 255).
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(width) * height * 3);
  for (int row = 0; row < height; ++row) {
    const std::uint8_t* src = &rgba[static_cast<std::size_t>(flippedRow(row, height)) * width * 4];
    std::uint8_t* dst = &rgb[static_cast<std::size_t>(row) * width * 3];
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c) dst[x * 3 + c] = src[x * 4 + c];
  }
  return rgb;
}

}  // namespace meshtrace::gl
