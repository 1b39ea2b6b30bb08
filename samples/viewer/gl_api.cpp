#include "gl_api.h"

#include <stdexcept>

void load_gl(GlApi& gl, GlProcGetter get) {
#define OCTOCAP_GL(name)                                                              \
  gl.name = reinterpret_cast<decltype(gl.name)>(get("gl" #name));                    \
  if (!gl.name) throw std::runtime_error("the OpenGL context has no gl" #name);
  OCTOCAP_GL(Viewport) OCTOCAP_GL(ClearColor) OCTOCAP_GL(Clear) OCTOCAP_GL(Enable) OCTOCAP_GL(Disable)
  OCTOCAP_GL(DepthFunc) OCTOCAP_GL(LineWidth) OCTOCAP_GL(ReadPixels) OCTOCAP_GL(PixelStorei) OCTOCAP_GL(Finish)
  OCTOCAP_GL(GetError) OCTOCAP_GL(GetString) OCTOCAP_GL(CreateShader) OCTOCAP_GL(ShaderSource)
  OCTOCAP_GL(CompileShader) OCTOCAP_GL(GetShaderiv) OCTOCAP_GL(GetShaderInfoLog) OCTOCAP_GL(CreateProgram)
  OCTOCAP_GL(AttachShader) OCTOCAP_GL(LinkProgram) OCTOCAP_GL(GetProgramiv) OCTOCAP_GL(GetProgramInfoLog)
  OCTOCAP_GL(DeleteShader) OCTOCAP_GL(DeleteProgram) OCTOCAP_GL(UseProgram) OCTOCAP_GL(GetUniformLocation)
  OCTOCAP_GL(UniformMatrix4fv) OCTOCAP_GL(Uniform3fv) OCTOCAP_GL(Uniform1i) OCTOCAP_GL(GenVertexArrays)
  OCTOCAP_GL(BindVertexArray) OCTOCAP_GL(DeleteVertexArrays) OCTOCAP_GL(GenBuffers) OCTOCAP_GL(BindBuffer)
  OCTOCAP_GL(BufferData) OCTOCAP_GL(BufferSubData) OCTOCAP_GL(DeleteBuffers) OCTOCAP_GL(EnableVertexAttribArray)
  OCTOCAP_GL(VertexAttribPointer) OCTOCAP_GL(DrawArrays) OCTOCAP_GL(DrawElements)
#undef OCTOCAP_GL
}
