// SPDX-License-Identifier: BSD-3-Clause
// The headless EGL contexts GpuRunner renders in: surfaceless Mesa, one
// desktop OpenGL 4.5 compatibility context and one OpenGL ES 3 context,
// created on first use and kept.
#pragma once

#include <map>
#include <string>

#include <EGL/egl.h>
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>

namespace bandlight::test
{

/// "GL error 0x0502".
std::string GlErrorText(GLenum e);

/// Throws naming `where` when GL has an error to report.
void CheckGl(const char* where);

/// One EGL context (desktop OpenGL or OpenGL ES) and what it keeps between runs.
struct Context
{
    EGLContext context = EGL_NO_CONTEXT;
    std::string why;  ///< why there is no context
    std::string renderer;
    GLuint vao = 0, vbo = 0, input = 0, fbo = 0, target = 0;
    int width = 0, height = 0;               ///< of the render target
    std::map<std::string, GLuint> programs;  ///< by fragment shader text
};

/// The ES or the desktop context, current; nullptr (and `why`) if there is
/// none.
Context* ContextFor(bool es, std::string* why);

}  // namespace bandlight::test
