// SPDX-License-Identifier: BSD-3-Clause
#include "gpu/GlContext.h"

#include <cstdio>
#include <stdexcept>

#include <EGL/eglext.h>
#include <GL/glext.h>

namespace bandlight::test
{

std::string GlErrorText(GLenum e)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "GL error 0x%04x", unsigned(e));
    return buf;
}

void CheckGl(const char* where)
{
    const GLenum e = glGetError();
    if (e != GL_NO_ERROR)
    {
        throw std::runtime_error(GlErrorText(e) + " at " + where);
    }
}

namespace
{

/// The EGL display and both contexts. Created once, never destroyed: GL
/// calls in static destructors would race Mesa's own clean-up at exit.
struct Gpu
{
    EGLDisplay display = EGL_NO_DISPLAY;
    std::string why;  ///< why there is no display
    Context desktop, es;
    bool triedDesktop = false, triedEs = false;
    const Context* current = nullptr;
};

Gpu& TheGpu()
{
    static Gpu* gpu = []
    {
        Gpu* g = new Gpu();
        // Surfaceless Mesa: no window system, no DISPLAY, no pbuffer; the
        // contexts render into framebuffer objects only.
        auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
            eglGetProcAddress("eglGetPlatformDisplayEXT"));
        if (!getPlatformDisplay)
        {
            g->why = "EGL has no eglGetPlatformDisplayEXT";
            return g;
        }
        g->display =
            getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        EGLint major = 0, minor = 0;
        if (g->display == EGL_NO_DISPLAY || !eglInitialize(g->display, &major, &minor))
        {
            g->why =
                "eglInitialize failed on EGL_PLATFORM_SURFACELESS_MESA (is libegl-mesa0 "
                "installed?)";
            g->display = EGL_NO_DISPLAY;
        }
        return g;
    }();
    return *gpu;
}

/// Sets up the context's triangle, input texture and framebuffer object.
void PrepareContext(Context& c)
{
    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    c.renderer = std::string(renderer ? renderer : "?") + " | " + (version ? version : "?");
    glGenVertexArrays(1, &c.vao);
    glBindVertexArray(c.vao);
    const float triangle[] = {-1.0f, -1.0f, 3.0f, -1.0f, -1.0f, 3.0f};
    glGenBuffers(1, &c.vbo);
    glBindBuffer(GL_ARRAY_BUFFER, c.vbo);
    glBufferData(GL_ARRAY_BUFFER, sizeof triangle, triangle, GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
    glGenTextures(1, &c.input);
    glGenTextures(1, &c.target);
    glGenFramebuffers(1, &c.fbo);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    CheckGl("context set-up");
}

}  // namespace

Context* ContextFor(bool es, std::string* why)
{
    Gpu& gpu = TheGpu();
    if (gpu.display == EGL_NO_DISPLAY)
    {
        if (why)
        {
            *why = gpu.why;
        }
        return nullptr;
    }
    Context& c = es ? gpu.es : gpu.desktop;
    bool& tried = es ? gpu.triedEs : gpu.triedDesktop;
    if (!tried)
    {
        tried = true;
        // Desktop: a 4.5 compatibility profile, which compiles GLSL 1.20 and
        // 1.30 as well as 4.00 (a core profile rejects the old versions).
        // ES: 3.2, falling back to 3.0; it runs "#version 100" shaders too.
        const EGLint desktop[] = {EGL_CONTEXT_MAJOR_VERSION,
                                  4,
                                  EGL_CONTEXT_MINOR_VERSION,
                                  5,
                                  EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                  EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT,
                                  EGL_NONE};
        const EGLint es32[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 2,
                               EGL_NONE};
        const EGLint es30[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 0,
                               EGL_NONE};
        if (!eglBindAPI(es ? EGL_OPENGL_ES_API : EGL_OPENGL_API))
        {
            c.why =
                es ? "eglBindAPI(EGL_OPENGL_ES_API) failed" : "eglBindAPI(EGL_OPENGL_API) failed";
        }
        else
        {
            // EGL_KHR_no_config_context: no config is needed without a surface.
            c.context = eglCreateContext(gpu.display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT,
                                         es ? es32 : desktop);
            if (c.context == EGL_NO_CONTEXT && es)
            {
                c.context = eglCreateContext(gpu.display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, es30);
            }
            if (c.context == EGL_NO_CONTEXT)
            {
                char buf[128];
                std::snprintf(buf, sizeof buf, "eglCreateContext (%s) failed: EGL error 0x%04x",
                              es ? "OpenGL ES 3.x" : "OpenGL 4.5 compatibility",
                              unsigned(eglGetError()));
                c.why = buf;
            }
            else if (!eglMakeCurrent(gpu.display, EGL_NO_SURFACE, EGL_NO_SURFACE, c.context))
            {
                c.why = "eglMakeCurrent without a surface failed";
                c.context = EGL_NO_CONTEXT;
            }
            else
            {
                gpu.current = &c;
                PrepareContext(c);
            }
        }
    }
    if (c.context == EGL_NO_CONTEXT)
    {
        if (why)
        {
            *why = c.why;
        }
        return nullptr;
    }
    if (gpu.current != &c)
    {
        eglBindAPI(es ? EGL_OPENGL_ES_API : EGL_OPENGL_API);
        if (!eglMakeCurrent(gpu.display, EGL_NO_SURFACE, EGL_NO_SURFACE, c.context))
        {
            throw std::runtime_error("eglMakeCurrent failed");
        }
        gpu.current = &c;
    }
    return &c;
}

}  // namespace bandlight::test
