// A linked GLSL 3.30 program from vertex and fragment source, with uniform setters by name. Used
// by the 3D views' point, line and shaded-mesh drawing. Needs a current OpenGL 3.3 context.
#pragma once

#include <Eigen/Core>

namespace polarform::studio {

class GlShader {
 public:
  // Throws std::runtime_error with the compiler's log when compiling or linking fails.
  GlShader(const char* vertex_source, const char* fragment_source);
  ~GlShader();
  GlShader(const GlShader&) = delete;
  GlShader& operator=(const GlShader&) = delete;

  void use() const;
  void set(const char* name, const Eigen::Matrix4f& m) const;
  void set(const char* name, float v) const;

 private:
  unsigned program_ = 0;
};

}  // namespace polarform::studio
