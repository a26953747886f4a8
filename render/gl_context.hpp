// The one place that knows how a GL context is made. The renderer only needs "a current GL 4.5 core
// context"; it draws into its own framebuffer object and reads that back, so the context needs no
// window and no default framebuffer of a particular size. OSMesa (llvmpipe) makes it today; EGL
// surfaceless can replace it (Mesa 25.1 removed OSMesa, docs/dependencies.md#osmesa-removal) by adding
// another factory here, without touching the renderer.
#pragma once

#include <functional>
#include <memory>
#include <string>

namespace vbim::render {

// A GL context, current on the calling thread while the object lives.
class GlContext {
 public:
  virtual ~GlContext() = default;
  // "4.5 (Core Profile) Mesa 22.3.6 / llvmpipe (LLVM 15.0.6, 256 bits)"
  virtual std::string describe() const = 0;
  // Makes this context current on the calling thread again (several renderers may share a thread).
  virtual void makeCurrent() = 0;
};

// Makes a current context or throws RenderError saying why not.
using GlContextFactory = std::function<std::unique_ptr<GlContext>()>;

// OSMesa, GL 4.5 core (the highest Mesa 22.3 offers; 4.6 returns NULL), tried down to 3.3.
std::unique_ptr<GlContext> createOsmesaContext();

// The default factory: OSMesa.
GlContextFactory defaultContextFactory();

}  // namespace vbim::render
