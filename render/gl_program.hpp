// Small GL helpers: a linked shader program (compile errors become RenderError with the log), and
// RAII owners for buffers, textures and vertex arrays. Needs a current context (gl_context.hpp).
#pragma once

#include <GL/gl.h>
#include <GL/glext.h>

#include <string>

namespace vbim::render {

class GlProgram {
 public:
  GlProgram() = default;
  // `name` appears in error messages ("terrain shader: 0:12(3): error: ...").
  GlProgram(const std::string& name, const char* vertexSource, const char* fragmentSource);
  ~GlProgram();
  GlProgram(GlProgram&& o) noexcept : id_(o.id_) { o.id_ = 0; }
  GlProgram& operator=(GlProgram&& o) noexcept;
  GlProgram(const GlProgram&) = delete;
  GlProgram& operator=(const GlProgram&) = delete;

  GLuint id() const { return id_; }
  GLint uniform(const char* name) const { return glGetUniformLocation(id_, name); }

 private:
  GLuint id_ = 0;
};

// Owns one GL object name; `Deleter` is glDeleteBuffers, glDeleteTextures, ...
template <void (*Deleter)(GLsizei, const GLuint*)>
class GlName {
 public:
  GlName() = default;
  explicit GlName(GLuint id) : id_(id) {}
  ~GlName() {
    if (id_ != 0) Deleter(1, &id_);
  }
  GlName(GlName&& o) noexcept : id_(o.id_) { o.id_ = 0; }
  GlName& operator=(GlName&& o) noexcept {
    if (this != &o) {
      if (id_ != 0) Deleter(1, &id_);
      id_ = o.id_;
      o.id_ = 0;
    }
    return *this;
  }
  GlName(const GlName&) = delete;
  GlName& operator=(const GlName&) = delete;
  GLuint id() const { return id_; }

 private:
  GLuint id_ = 0;
};

inline void deleteBuffers(GLsizei n, const GLuint* ids) {
  glDeleteBuffers(n, ids);
}
inline void deleteTextures(GLsizei n, const GLuint* ids) {
  glDeleteTextures(n, ids);
}
inline void deleteVertexArrays(GLsizei n, const GLuint* ids) {
  glDeleteVertexArrays(n, ids);
}
inline void deleteFramebuffers(GLsizei n, const GLuint* ids) {
  glDeleteFramebuffers(n, ids);
}
inline void deleteRenderbuffers(GLsizei n, const GLuint* ids) {
  glDeleteRenderbuffers(n, ids);
}

using GlBuffer = GlName<deleteBuffers>;
using GlTexture = GlName<deleteTextures>;
using GlVertexArray = GlName<deleteVertexArrays>;
using GlFramebuffer = GlName<deleteFramebuffers>;
using GlRenderbuffer = GlName<deleteRenderbuffers>;

GlBuffer makeBuffer();
GlTexture makeTexture();
GlVertexArray makeVertexArray();

// Throws RenderError naming `what` if glGetError reports anything.
void checkGl(const char* what);

}  // namespace vbim::render
