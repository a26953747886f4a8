#include "render/gl_program.hpp"

#include <string>
#include <vector>

#include "render/error.hpp"

namespace vbim::render {

namespace {

// The info log of a shader or a program (the two GL calls differ only in name).
template <class GetIv, class GetLog>
std::string infoLog(GLuint id, GetIv getIv, GetLog getLog) {
  GLint len = 0;
  getIv(id, GL_INFO_LOG_LENGTH, &len);
  std::vector<char> log(static_cast<std::size_t>(len) + 1, '\0');
  getLog(id, len, nullptr, log.data());
  return log.data();
}

GLuint compile(const std::string& name, GLenum type, const char* source) {
  const GLuint s = glCreateShader(type);
  glShaderSource(s, 1, &source, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    const std::string log = infoLog(s, glGetShaderiv, glGetShaderInfoLog);
    glDeleteShader(s);
    throw RenderError(name + (type == GL_VERTEX_SHADER ? " vertex" : " fragment") + " shader does not compile: " + log);
  }
  return s;
}

}  // namespace

GlProgram::GlProgram(const std::string& name, const char* vertexSource, const char* fragmentSource) {
  const GLuint vs = compile(name, GL_VERTEX_SHADER, vertexSource);
  GLuint fs = 0;
  try {
    fs = compile(name, GL_FRAGMENT_SHADER, fragmentSource);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  id_ = glCreateProgram();
  glAttachShader(id_, vs);
  glAttachShader(id_, fs);
  glLinkProgram(id_);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (!ok) {
    const std::string log = infoLog(id_, glGetProgramiv, glGetProgramInfoLog);
    glDeleteProgram(id_);
    id_ = 0;
    throw RenderError(name + " shader does not link: " + log);
  }
}

GlProgram::~GlProgram() {
  if (id_ != 0) glDeleteProgram(id_);
}

GlProgram& GlProgram::operator=(GlProgram&& o) noexcept {
  if (this != &o) {
    if (id_ != 0) glDeleteProgram(id_);
    id_ = o.id_;
    o.id_ = 0;
  }
  return *this;
}

GlBuffer makeBuffer() {
  GLuint id = 0;
  glGenBuffers(1, &id);
  return GlBuffer(id);
}

GlTexture makeTexture() {
  GLuint id = 0;
  glGenTextures(1, &id);
  return GlTexture(id);
}

GlVertexArray makeVertexArray() {
  GLuint id = 0;
  glGenVertexArrays(1, &id);
  return GlVertexArray(id);
}

void checkGl(const char* what) {
  const GLenum e = glGetError();
  if (e != GL_NO_ERROR) throw RenderError(std::string("GL error 0x") + std::to_string(e) + " in " + what);
}

}  // namespace vbim::render
