#include "ui/studio/gl_shader.h"

#include <stdexcept>
#include <string>

#include "ui/studio/gl_api.h"

namespace polarform::studio {
namespace {

GLuint compile(GLenum kind, const char* source) {
  const GLuint shader = glCreateShader(kind);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[1024];
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    glDeleteShader(shader);
    throw std::runtime_error(std::string("GLSL compile error: ") + log);
  }
  return shader;
}

}  // namespace

GlShader::GlShader(const char* vertex_source, const char* fragment_source) {
  const GLuint vs = compile(GL_VERTEX_SHADER, vertex_source);
  GLuint fs = 0;
  try {
    fs = compile(GL_FRAGMENT_SHADER, fragment_source);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  program_ = glCreateProgram();
  glAttachShader(program_, vs);
  glAttachShader(program_, fs);
  glLinkProgram(program_);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[1024];
    glGetProgramInfoLog(program_, sizeof log, nullptr, log);
    glDeleteProgram(program_);
    throw std::runtime_error(std::string("GLSL link error: ") + log);
  }
}

GlShader::~GlShader() { glDeleteProgram(program_); }

void GlShader::use() const { glUseProgram(program_); }

void GlShader::set(const char* name, const Eigen::Matrix4f& m) const {
  glUniformMatrix4fv(glGetUniformLocation(program_, name), 1, GL_FALSE, m.data());
}

void GlShader::set(const char* name, float v) const {
  glUniform1f(glGetUniformLocation(program_, name), v);
}

}  // namespace polarform::studio
