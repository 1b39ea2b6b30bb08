// The OpenGL 3.3 core functions the viewer uses, loaded through the context's own proc-address function
// (OSMesaGetProcAddress or glfwGetProcAddress). Nothing is linked against libGL: OSMesa exports gl* symbols of
// its own, so a direct call could reach the wrong implementation when a GLFW window is current.
#pragma once
#include <GL/glcorearb.h>

#include <string>

struct GlApi {
  PFNGLVIEWPORTPROC Viewport;
  PFNGLCLEARCOLORPROC ClearColor;
  PFNGLCLEARPROC Clear;
  PFNGLENABLEPROC Enable;
  PFNGLDISABLEPROC Disable;
  PFNGLDEPTHFUNCPROC DepthFunc;
  PFNGLLINEWIDTHPROC LineWidth;
  PFNGLREADPIXELSPROC ReadPixels;
  PFNGLPIXELSTOREIPROC PixelStorei;
  PFNGLFINISHPROC Finish;
  PFNGLGETERRORPROC GetError;
  PFNGLGETSTRINGPROC GetString;
  PFNGLCREATESHADERPROC CreateShader;
  PFNGLSHADERSOURCEPROC ShaderSource;
  PFNGLCOMPILESHADERPROC CompileShader;
  PFNGLGETSHADERIVPROC GetShaderiv;
  PFNGLGETSHADERINFOLOGPROC GetShaderInfoLog;
  PFNGLCREATEPROGRAMPROC CreateProgram;
  PFNGLATTACHSHADERPROC AttachShader;
  PFNGLLINKPROGRAMPROC LinkProgram;
  PFNGLGETPROGRAMIVPROC GetProgramiv;
  PFNGLGETPROGRAMINFOLOGPROC GetProgramInfoLog;
  PFNGLDELETESHADERPROC DeleteShader;
  PFNGLDELETEPROGRAMPROC DeleteProgram;
  PFNGLUSEPROGRAMPROC UseProgram;
  PFNGLGETUNIFORMLOCATIONPROC GetUniformLocation;
  PFNGLUNIFORMMATRIX4FVPROC UniformMatrix4fv;
  PFNGLUNIFORM3FVPROC Uniform3fv;
  PFNGLUNIFORM1IPROC Uniform1i;
  PFNGLGENVERTEXARRAYSPROC GenVertexArrays;
  PFNGLBINDVERTEXARRAYPROC BindVertexArray;
  PFNGLDELETEVERTEXARRAYSPROC DeleteVertexArrays;
  PFNGLGENBUFFERSPROC GenBuffers;
  PFNGLBINDBUFFERPROC BindBuffer;
  PFNGLBUFFERDATAPROC BufferData;
  PFNGLBUFFERSUBDATAPROC BufferSubData;
  PFNGLDELETEBUFFERSPROC DeleteBuffers;
  PFNGLENABLEVERTEXATTRIBARRAYPROC EnableVertexAttribArray;
  PFNGLVERTEXATTRIBPOINTERPROC VertexAttribPointer;
  PFNGLDRAWARRAYSPROC DrawArrays;
  PFNGLDRAWELEMENTSPROC DrawElements;
};

using GlProcGetter = void* (*)(const char* name);
// Fills every entry; throws std::runtime_error naming the first function the context does not provide.
void load_gl(GlApi& gl, GlProcGetter get);
