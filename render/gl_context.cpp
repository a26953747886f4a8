#include "render/gl_context.hpp"

#include <GL/osmesa.h>

#include <vector>

#include "render/error.hpp"

namespace vbim::render {

namespace {

class OsmesaContext : public GlContext {
 public:
  OsmesaContext() {
    // Versions from high to low: Mesa 22.3 gives 4.5 core; older ones may stop at 3.3.
    const int versions[][2] = {{4, 5}, {4, 3}, {3, 3}};
    for (const auto& v : versions) {
      const int attribs[] = {OSMESA_FORMAT,
                             OSMESA_RGBA,
                             OSMESA_DEPTH_BITS,
                             0,
                             OSMESA_STENCIL_BITS,
                             0,
                             OSMESA_PROFILE,
                             OSMESA_CORE_PROFILE,
                             OSMESA_CONTEXT_MAJOR_VERSION,
                             v[0],
                             OSMESA_CONTEXT_MINOR_VERSION,
                             v[1],
                             0};
      ctx_ = OSMesaCreateContextAttribs(attribs, nullptr);
      if (ctx_ != nullptr) break;
    }
    if (ctx_ == nullptr) {
      throw RenderError("no GL context available: OSMesa could not create a 3.3+ core profile context");
    }
    // The context draws into our FBO; OSMesa still wants a buffer to make it current.
    buffer_.assign(std::size_t{4} * 4 * 4, 0);
    if (!OSMesaMakeCurrent(ctx_, buffer_.data(), GL_UNSIGNED_BYTE, 4, 4)) {
      OSMesaDestroyContext(ctx_);
      throw RenderError("no GL context available: OSMesaMakeCurrent failed");
    }
  }

  void makeCurrent() override {
    if (OSMesaGetCurrentContext() != ctx_ && !OSMesaMakeCurrent(ctx_, buffer_.data(), GL_UNSIGNED_BYTE, 4, 4)) {
      throw RenderError("OSMesaMakeCurrent failed");
    }
  }
  ~OsmesaContext() override { OSMesaDestroyContext(ctx_); }

  std::string describe() const override {
    auto str = [](GLenum e) {
      const GLubyte* s = glGetString(e);
      return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
    };
    return str(GL_VERSION) + " / " + str(GL_RENDERER);
  }

 private:
  OSMesaContext ctx_ = nullptr;
  std::vector<unsigned char> buffer_;
};

}  // namespace

std::unique_ptr<GlContext> createOsmesaContext() {
  return std::make_unique<OsmesaContext>();
}

GlContextFactory defaultContextFactory() {
  return [] { return createOsmesaContext(); };
}

}  // namespace vbim::render
