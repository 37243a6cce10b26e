#pragma once
// OpenGL through function pointers resolved at run time, so one binary draws
// into a GLFW window (pointers from glfwGetProcAddress) or offscreen through
// OSMesa (pointers from OSMesaGetProcAddress) without linking libGL, whose
// symbols would win over OSMesa's. The ImGui OpenGL3 backend is compiled
// with this header forced in (IMGUI_IMPL_OPENGL_LOADER_CUSTOM).
#include <GL/glcorearb.h>

#define MESHTRACE_GL_FUNCTIONS(X)                                \
  X(PFNGLACTIVETEXTUREPROC, glActiveTexture)                     \
  X(PFNGLATTACHSHADERPROC, glAttachShader)                       \
  X(PFNGLBINDBUFFERPROC, glBindBuffer)                           \
  X(PFNGLBINDSAMPLERPROC, glBindSampler)                         \
  X(PFNGLBINDTEXTUREPROC, glBindTexture)                         \
  X(PFNGLBINDVERTEXARRAYPROC, glBindVertexArray)                 \
  X(PFNGLBLENDEQUATIONPROC, glBlendEquation)                     \
  X(PFNGLBLENDEQUATIONSEPARATEPROC, glBlendEquationSeparate)     \
  X(PFNGLBLENDFUNCSEPARATEPROC, glBlendFuncSeparate)             \
  X(PFNGLBUFFERDATAPROC, glBufferData)                           \
  X(PFNGLBUFFERSUBDATAPROC, glBufferSubData)                     \
  X(PFNGLCLEARPROC, glClear)                                     \
  X(PFNGLCLEARCOLORPROC, glClearColor)                           \
  X(PFNGLCLIPCONTROLPROC, glClipControl)                         \
  X(PFNGLCOMPILESHADERPROC, glCompileShader)                     \
  X(PFNGLCREATEPROGRAMPROC, glCreateProgram)                     \
  X(PFNGLCREATESHADERPROC, glCreateShader)                       \
  X(PFNGLDELETEBUFFERSPROC, glDeleteBuffers)                     \
  X(PFNGLDELETEPROGRAMPROC, glDeleteProgram)                     \
  X(PFNGLDELETESHADERPROC, glDeleteShader)                       \
  X(PFNGLDELETETEXTURESPROC, glDeleteTextures)                   \
  X(PFNGLDELETEVERTEXARRAYSPROC, glDeleteVertexArrays)           \
  X(PFNGLDETACHSHADERPROC, glDetachShader)                       \
  X(PFNGLDISABLEPROC, glDisable)                                 \
  X(PFNGLDRAWELEMENTSPROC, glDrawElements)                       \
  X(PFNGLDRAWELEMENTSBASEVERTEXPROC, glDrawElementsBaseVertex)   \
  X(PFNGLENABLEPROC, glEnable)                                   \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, glEnableVertexAttribArray) \
  X(PFNGLFINISHPROC, glFinish)                                   \
  X(PFNGLGENBUFFERSPROC, glGenBuffers)                           \
  X(PFNGLGENTEXTURESPROC, glGenTextures)                         \
  X(PFNGLGENVERTEXARRAYSPROC, glGenVertexArrays)                 \
  X(PFNGLGETATTRIBLOCATIONPROC, glGetAttribLocation)             \
  X(PFNGLGETERRORPROC, glGetError)                               \
  X(PFNGLGETINTEGERVPROC, glGetIntegerv)                         \
  X(PFNGLGETPROGRAMINFOLOGPROC, glGetProgramInfoLog)             \
  X(PFNGLGETPROGRAMIVPROC, glGetProgramiv)                       \
  X(PFNGLGETSHADERINFOLOGPROC, glGetShaderInfoLog)               \
  X(PFNGLGETSHADERIVPROC, glGetShaderiv)                         \
  X(PFNGLGETSTRINGPROC, glGetString)                             \
  X(PFNGLGETSTRINGIPROC, glGetStringi)                           \
  X(PFNGLGETUNIFORMLOCATIONPROC, glGetUniformLocation)           \
  X(PFNGLISENABLEDPROC, glIsEnabled)                             \
  X(PFNGLLINKPROGRAMPROC, glLinkProgram)                         \
  X(PFNGLPIXELSTOREIPROC, glPixelStorei)                         \
  X(PFNGLPOLYGONMODEPROC, glPolygonMode)                         \
  X(PFNGLREADPIXELSPROC, glReadPixels)                           \
  X(PFNGLSCISSORPROC, glScissor)                                 \
  X(PFNGLSHADERSOURCEPROC, glShaderSource)                       \
  X(PFNGLTEXIMAGE2DPROC, glTexImage2D)                           \
  X(PFNGLTEXPARAMETERIPROC, glTexParameteri)                     \
  X(PFNGLTEXSUBIMAGE2DPROC, glTexSubImage2D)                     \
  X(PFNGLUNIFORM1IPROC, glUniform1i)                             \
  X(PFNGLUNIFORMMATRIX4FVPROC, glUniformMatrix4fv)               \
  X(PFNGLUSEPROGRAMPROC, glUseProgram)                           \
  X(PFNGLVERTEXATTRIBPOINTERPROC, glVertexAttribPointer)         \
  X(PFNGLVIEWPORTPROC, glViewport)

#define MESHTRACE_GL_DECLARE(type, name) extern type meshtrace_##name;
MESHTRACE_GL_FUNCTIONS(MESHTRACE_GL_DECLARE)
#undef MESHTRACE_GL_DECLARE

#define glActiveTexture meshtrace_glActiveTexture
#define glAttachShader meshtrace_glAttachShader
#define glBindBuffer meshtrace_glBindBuffer
#define glBindSampler meshtrace_glBindSampler
#define glBindTexture meshtrace_glBindTexture
#define glBindVertexArray meshtrace_glBindVertexArray
#define glBlendEquation meshtrace_glBlendEquation
#define glBlendEquationSeparate meshtrace_glBlendEquationSeparate
#define glBlendFuncSeparate meshtrace_glBlendFuncSeparate
#define glBufferData meshtrace_glBufferData
#define glBufferSubData meshtrace_glBufferSubData
#define glClear meshtrace_glClear
#define glClearColor meshtrace_glClearColor
#define glClipControl meshtrace_glClipControl
#define glCompileShader meshtrace_glCompileShader
#define glCreateProgram meshtrace_glCreateProgram
#define glCreateShader meshtrace_glCreateShader
#define glDeleteBuffers meshtrace_glDeleteBuffers
#define glDeleteProgram meshtrace_glDeleteProgram
#define glDeleteShader meshtrace_glDeleteShader
#define glDeleteTextures meshtrace_glDeleteTextures
#define glDeleteVertexArrays meshtrace_glDeleteVertexArrays
#define glDetachShader meshtrace_glDetachShader
#define glDisable meshtrace_glDisable
#define glDrawElements meshtrace_glDrawElements
#define glDrawElementsBaseVertex meshtrace_glDrawElementsBaseVertex
#define glEnable meshtrace_glEnable
#define glEnableVertexAttribArray meshtrace_glEnableVertexAttribArray
#define glFinish meshtrace_glFinish
#define glGenBuffers meshtrace_glGenBuffers
#define glGenTextures meshtrace_glGenTextures
#define glGenVertexArrays meshtrace_glGenVertexArrays
#define glGetAttribLocation meshtrace_glGetAttribLocation
#define glGetError meshtrace_glGetError
#define glGetIntegerv meshtrace_glGetIntegerv
#define glGetProgramInfoLog meshtrace_glGetProgramInfoLog
#define glGetProgramiv meshtrace_glGetProgramiv
#define glGetShaderInfoLog meshtrace_glGetShaderInfoLog
#define glGetShaderiv meshtrace_glGetShaderiv
#define glGetString meshtrace_glGetString
#define glGetStringi meshtrace_glGetStringi
#define glGetUniformLocation meshtrace_glGetUniformLocation
#define glIsEnabled meshtrace_glIsEnabled
#define glLinkProgram meshtrace_glLinkProgram
#define glPixelStorei meshtrace_glPixelStorei
#define glPolygonMode meshtrace_glPolygonMode
#define glReadPixels meshtrace_glReadPixels
#define glScissor meshtrace_glScissor
#define glShaderSource meshtrace_glShaderSource
#define glTexImage2D meshtrace_glTexImage2D
#define glTexParameteri meshtrace_glTexParameteri
#define glTexSubImage2D meshtrace_glTexSubImage2D
#define glUniform1i meshtrace_glUniform1i
#define glUniformMatrix4fv meshtrace_glUniformMatrix4fv
#define glUseProgram meshtrace_glUseProgram
#define glVertexAttribPointer meshtrace_glVertexAttribPointer
#define glViewport meshtrace_glViewport

namespace meshtrace::gl {

using ProcLoader = void* (*)(const char* name);

// Resolves every function with `load`; returns the name of the first one
// missing, or nullptr when all were found.
const char* loadFunctions(ProcLoader load);

}  // namespace meshtrace::gl
