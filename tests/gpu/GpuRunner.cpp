// SPDX-License-Identifier: BSD-3-Clause
#include "gpu/GpuRunner.h"

#include "gpu/GlContext.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include <EGL/egl.h>
#include <EGL/eglext.h>
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

namespace bandlight::test
{

namespace
{

bool IsEs(OCIO::GpuLanguage language)
{
    return language == OCIO::GPU_LANGUAGE_GLSL_ES_1_0 || language == OCIO::GPU_LANGUAGE_GLSL_ES_3_0;
}

// ---------------------------------------------------------------------------
// Shader wrappers. The ES headers need their precision lines: sampler3D has
// no default precision, and without highp sampler2D llvmpipe samples the
// float LUT textures at low precision. ES 1.0 reaches 3D textures through
// GL_OES_texture_3D.

struct Wrapper
{
    std::string vertex;  ///< the whole vertex shader ("" for languages not run)
    std::string head;    ///< fragment shader text before OCIO's
    std::string tail;    ///< after OCIO's: the input texture and main()
};

/// The vertex shader: a triangle covering the viewport, one attribute "pos".
std::string VertexShader(const std::string& version, const char* in)
{
    return version + std::string(in) +
           " vec2 pos;\nvoid main()\n{\n    gl_Position = vec4(pos, 0.0, 1.0);\n}\n";
}

// clang-format off
const char* const kFetchTail =
    "uniform sampler2D img;\n"
    "out vec4 fragColor;\n"
    "void main()\n"
    "{\n"
    "    fragColor = OCIOMain(texelFetch(img, ivec2(gl_FragCoord.xy), 0));\n"
    "}\n";
// GLSL 1.2 and ES 1.0 have no texelFetch: sample the texel centre (NEAREST).
const char* const kSampleTail =
    "uniform sampler2D img;\n"
    "uniform vec2 imgSize;\n"
    "void main()\n"
    "{\n"
    "    gl_FragColor = OCIOMain(texture2D(img, gl_FragCoord.xy / imgSize));\n"
    "}\n";
const char* const kHlslTail =
    "Texture2D img;\n"
    "float4 main(float4 pos : SV_Position) : SV_Target\n"
    "{\n"
    "    return OCIOMain(img.Load(int3(pos.xy, 0)));\n"
    "}\n";
const char* const kEsPrecision =
    "precision highp float;\n"
    "precision highp int;\n"
    "precision highp sampler2D;\n"
    "precision highp sampler3D;\n";
// clang-format on

Wrapper WrapperFor(OCIO::GpuLanguage language)
{
    switch (language)
    {
        case OCIO::GPU_LANGUAGE_GLSL_1_2:
            return {VertexShader("#version 120\n", "attribute"), "#version 120\n", kSampleTail};
        case OCIO::GPU_LANGUAGE_GLSL_1_3:
            return {VertexShader("#version 130\n", "in"), "#version 130\n", kFetchTail};
        case OCIO::GPU_LANGUAGE_GLSL_4_0:
            return {VertexShader("#version 400 core\n", "in"), "#version 400 core\n", kFetchTail};
        case OCIO::GPU_LANGUAGE_GLSL_ES_1_0:
            return {
                VertexShader("#version 100\n", "attribute"),
                std::string("#version 100\n#extension GL_OES_texture_3D : enable\n") + kEsPrecision,
                kSampleTail};
        case OCIO::GPU_LANGUAGE_GLSL_ES_3_0:
            return {VertexShader("#version 300 es\n", "in"),
                    std::string("#version 300 es\n") + kEsPrecision, kFetchTail};
        case OCIO::GPU_LANGUAGE_HLSL_DX11:
            return {"", "", kHlslTail};
        default:
            return {"", "", ""};  // Cg, MSL, OSL: OCIO's text alone
    }
}

/// Throws naming `what` and the driver's log when `program` did not link
/// (the program is deleted).
void CheckLinked(GLuint program, const char* what)
{
    GLint ok = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok)
    {
        char log[8192] = {};
        glGetProgramInfoLog(program, sizeof log, nullptr, log);
        glDeleteProgram(program);
        throw std::runtime_error(std::string(what) + " does not link: " + log);
    }
}

GLuint CompileStage(GLenum stage, const std::string& text)
{
    const GLuint s = glCreateShader(stage);
    const char* p = text.c_str();
    glShaderSource(s, 1, &p, nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok)
    {
        char log[8192] = {};
        glGetShaderInfoLog(s, sizeof log, nullptr, log);
        glDeleteShader(s);
        const char* name = stage == GL_VERTEX_SHADER    ? "vertex"
                           : stage == GL_COMPUTE_SHADER ? "compute"
                                                        : "fragment";
        throw std::runtime_error(std::string(name) + " shader does not compile on the GPU: " + log);
    }
    return s;
}

GLuint Program(Context& c, const Wrapper& w, const std::string& fragment)
{
    const auto found = c.programs.find(fragment);
    if (found != c.programs.end())
    {
        return found->second;
    }
    const GLuint vs = CompileStage(GL_VERTEX_SHADER, w.vertex);
    GLuint fs = 0;
    try
    {
        fs = CompileStage(GL_FRAGMENT_SHADER, fragment);
    }
    catch (...)
    {
        glDeleteShader(vs);
        throw;
    }
    const GLuint program = glCreateProgram();
    glAttachShader(program, vs);
    glAttachShader(program, fs);
    glBindAttribLocation(program, 0, "pos");
    glLinkProgram(program);
    glDeleteShader(vs);
    glDeleteShader(fs);
    CheckLinked(program, "shader program");
    c.programs.emplace(fragment, program);
    return program;
}

void SetTextureParameters(GLenum target, GLint filter)
{
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, filter);
    glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    if (target == GL_TEXTURE_3D)
    {
        glTexParameteri(target, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    }
}

/// Binds OCIO's LUTs to texture units 1, 2, ... and points their samplers
/// at them. Returns the texture names (to delete after the draw).
std::vector<GLuint> UploadLuts(const OCIO::GpuShaderDesc& desc, GLuint program, bool es,
                               const LutUpload& upload)
{
    std::vector<GLuint> textures;
    GLint unit = 1;
    auto bindSampler = [&](const char* sampler)
    {
        const GLint location = glGetUniformLocation(program, sampler);
        if (location >= 0)
        {
            glUniform1i(location, unit);
        }
        ++unit;
    };
    for (unsigned i = 0; i < desc.getNum3DTextures(); ++i)
    {
        const char* textureName = nullptr;
        const char* samplerName = nullptr;
        unsigned edge = 0;
        OCIO::Interpolation interpolation = OCIO::INTERP_UNKNOWN;
        desc.get3DTexture(i, textureName, samplerName, edge, interpolation);
        const float* values = nullptr;
        desc.get3DTextureValues(i, values);
        GLuint t = 0;
        glGenTextures(1, &t);
        textures.push_back(t);
        glActiveTexture(GL_TEXTURE0 + GLenum(unit));
        glBindTexture(GL_TEXTURE_3D, t);
        // OCIO's tetrahedral code fetches the nodes itself: no filtering
        // (unless the host's filtering is what is being measured).
        const bool nearest = interpolation == OCIO::INTERP_NEAREST ||
                             upload.filter == LutUpload::Filter::NEAREST ||
                             (upload.filter == LutUpload::Filter::NEAREST_FOR_TETRAHEDRAL &&
                              interpolation == OCIO::INTERP_TETRAHEDRAL);
        SetTextureParameters(GL_TEXTURE_3D, nearest ? GL_NEAREST : GL_LINEAR);
        // edge³ RGB nodes, red varying slowest (OCIO samples with .zyx).
        glTexImage3D(GL_TEXTURE_3D, 0, upload.halfFloat ? GL_RGB16F : GL_RGB32F, GLsizei(edge),
                     GLsizei(edge), GLsizei(edge), 0, GL_RGB, GL_FLOAT, values);
        CheckGl("3D LUT upload");
        bindSampler(samplerName);
    }
    for (unsigned i = 0; i < desc.getNumTextures(); ++i)
    {
        const char* textureName = nullptr;
        const char* samplerName = nullptr;
        unsigned width = 0, height = 0;
        OCIO::GpuShaderDesc::TextureType channel = OCIO::GpuShaderDesc::TEXTURE_RGB_CHANNEL;
        OCIO::Interpolation interpolation = OCIO::INTERP_UNKNOWN;
        desc.getTexture(i, textureName, samplerName, width, height, channel, interpolation);
        const float* values = nullptr;
        desc.getTextureValues(i, values);
        const bool red = channel == OCIO::GpuShaderDesc::TEXTURE_RED_CHANNEL;
        // OCIO declares a one-row LUT as sampler1D in desktop GLSL, sampler2D
        // in GLSL ES (which has no 1D textures); taller ones as sampler2D.
        const GLenum target = height > 1 || es ? GL_TEXTURE_2D : GL_TEXTURE_1D;
        GLuint t = 0;
        glGenTextures(1, &t);
        textures.push_back(t);
        glActiveTexture(GL_TEXTURE0 + GLenum(unit));
        glBindTexture(target, t);
        SetTextureParameters(target,
                             interpolation == OCIO::INTERP_NEAREST ? GL_NEAREST : GL_LINEAR);
        const GLenum internal = red ? GL_R32F : GL_RGB32F;
        const GLenum format = red ? GL_RED : GL_RGB;
        if (target == GL_TEXTURE_1D)
        {
            glTexImage1D(target, 0, GLint(internal), GLsizei(width), 0, format, GL_FLOAT, values);
        }
        else
        {
            glTexImage2D(target, 0, GLint(internal), GLsizei(width), GLsizei(height), 0, format,
                         GL_FLOAT, values);
        }
        CheckGl("1D LUT upload");
        bindSampler(samplerName);
    }
    return textures;
}

/// Dynamic properties (exposure, contrast, gamma, grading) as OCIO lists
/// them. bandlight's transforms have none; set them for completeness.
void SetUniforms(const OCIO::GpuShaderDesc& desc, GLuint program)
{
    for (unsigned i = 0; i < desc.getNumUniforms(); ++i)
    {
        OCIO::GpuShaderDesc::UniformData u;
        const char* name = desc.getUniform(i, u);
        const GLint location = glGetUniformLocation(program, name);
        if (location < 0)
        {
            continue;
        }
        switch (u.m_type)
        {
            case OCIO::UNIFORM_DOUBLE:
                glUniform1f(location, GLfloat(u.m_getDouble()));
                break;
            case OCIO::UNIFORM_BOOL:
                glUniform1i(location, u.m_getBool() ? 1 : 0);
                break;
            case OCIO::UNIFORM_FLOAT3:
            {
                const OCIO::Float3& f = u.m_getFloat3();
                glUniform3f(location, f[0], f[1], f[2]);
                break;
            }
            case OCIO::UNIFORM_VECTOR_FLOAT:
                glUniform1fv(location, GLsizei(u.m_vectorFloat.m_getSize()),
                             u.m_vectorFloat.m_getVector());
                break;
            case OCIO::UNIFORM_VECTOR_INT:
                glUniform1iv(location, GLsizei(u.m_vectorInt.m_getSize()),
                             u.m_vectorInt.m_getVector());
                break;
            default:
                throw std::runtime_error(std::string("uniform of unknown type: ") + name);
        }
    }
    CheckGl("uniforms");
}

}  // namespace

// ---------------------------------------------------------------------------

const char* GpuLanguageName(OCIO::GpuLanguage language)
{
    switch (language)
    {
        case OCIO::GPU_LANGUAGE_CG:
            return "CG";
        case OCIO::GPU_LANGUAGE_GLSL_1_2:
            return "GLSL_1_2";
        case OCIO::GPU_LANGUAGE_GLSL_1_3:
            return "GLSL_1_3";
        case OCIO::GPU_LANGUAGE_GLSL_4_0:
            return "GLSL_4_0";
        case OCIO::GPU_LANGUAGE_HLSL_DX11:
            return "HLSL_DX11";
        case OCIO::LANGUAGE_OSL_1:
            return "OSL_1";
        case OCIO::GPU_LANGUAGE_GLSL_ES_1_0:
            return "GLSL_ES_1_0";
        case OCIO::GPU_LANGUAGE_GLSL_ES_3_0:
            return "GLSL_ES_3_0";
        case OCIO::GPU_LANGUAGE_MSL_2_0:
            return "MSL_2_0";
    }
    return "unknown";
}

bool IsRunnable(OCIO::GpuLanguage language)
{
    return !WrapperFor(language).vertex.empty();
}

bool IsValidated(OCIO::GpuLanguage language)
{
    return IsRunnable(language) || language == OCIO::GPU_LANGUAGE_HLSL_DX11;
}

GpuShader GpuRunner::Extract(const OCIO::ConstGPUProcessorRcPtr& processor,
                             OCIO::GpuLanguage language)
{
    GpuShader s;
    s.desc = OCIO::GpuShaderDesc::CreateShaderDesc();
    s.desc->setLanguage(language);
    s.desc->setFunctionName("OCIOMain");
    s.desc->setPixelName("outColor");
    s.desc->setResourcePrefix("ocio_");
    processor->extractGpuShaderInfo(s.desc);
    s.ocioText = s.desc->getShaderText();
    const Wrapper w = WrapperFor(language);
    s.fragmentText = w.head + s.ocioText + "\n" + w.tail;
    return s;
}

bool GpuRunner::Available(OCIO::GpuLanguage language, std::string* why)
{
    if (!IsRunnable(language))
    {
        if (why)
        {
            *why = std::string(GpuLanguageName(language)) + " is not an OpenGL language";
        }
        return false;
    }
    return ContextFor(IsEs(language), why) != nullptr;
}

std::string GpuRunner::Renderer(OCIO::GpuLanguage language)
{
    const Context* c = IsRunnable(language) ? ContextFor(IsEs(language), nullptr) : nullptr;
    return c ? c->renderer : std::string();
}

std::vector<float> GpuRunner::Run(const OCIO::ConstGPUProcessorRcPtr& processor,
                                  OCIO::GpuLanguage language, const std::vector<float>& rgba,
                                  int width, int height, const LutUpload& upload)
{
    if (width <= 0 || height <= 0 || rgba.size() != size_t(width) * size_t(height) * 4)
    {
        throw std::invalid_argument("GpuRunner::Run: rgba must hold width x height RGBA pixels");
    }
    std::string why;
    Context* c = Available(language, &why) ? ContextFor(IsEs(language), &why) : nullptr;
    if (!c)
    {
        throw std::runtime_error("no GPU context for " + std::string(GpuLanguageName(language)) +
                                 ": " + why);
    }
    const GpuShader shader = Extract(processor, language);
    const GLuint program = Program(*c, WrapperFor(language), shader.fragmentText);
    glUseProgram(program);

    // The image on unit 0: RGBA32F, fetched texel by texel.
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, c->input);
    SetTextureParameters(GL_TEXTURE_2D, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, rgba.data());
    CheckGl("input texture");
    glUniform1i(glGetUniformLocation(program, "img"), 0);
    const GLint size = glGetUniformLocation(program, "imgSize");
    if (size >= 0)
    {
        glUniform2f(size, GLfloat(width), GLfloat(height));
    }
    const std::vector<GLuint> luts = UploadLuts(*shader.desc, program, IsEs(language), upload);
    SetUniforms(*shader.desc, program);

    // An RGBA32F render target of the image's size.
    glBindFramebuffer(GL_FRAMEBUFFER, c->fbo);
    if (c->width != width || c->height != height)
    {
        glActiveTexture(GL_TEXTURE0 + GLenum(1 + luts.size()));
        glBindTexture(GL_TEXTURE_2D, c->target);
        SetTextureParameters(GL_TEXTURE_2D, GL_NEAREST);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
        glBindTexture(GL_TEXTURE_2D, 0);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, c->target, 0);
        c->width = width;
        c->height = height;
    }
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    {
        throw std::runtime_error("the RGBA32F framebuffer is incomplete");
    }
    glViewport(0, 0, width, height);
    glBindVertexArray(c->vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    CheckGl("draw");

    std::vector<float> out(rgba.size());
    glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, out.data());
    CheckGl("glReadPixels");
    glDeleteTextures(GLsizei(luts.size()), luts.data());
    return out;
}

std::string Describe(const LutUpload& upload)
{
    const char* filter = upload.filter == LutUpload::Filter::LINEAR    ? "GL_LINEAR"
                         : upload.filter == LutUpload::Filter::NEAREST ? "GL_NEAREST"
                                                                       : "nearest for tetrahedral";
    return std::string(filter) + ", " + (upload.halfFloat ? "RGB16F" : "RGB32F");
}

std::vector<float> GpuRunner::RunCompute(const OCIO::ConstGPUProcessorRcPtr& processor,
                                         const std::vector<float>& rgba, const LutUpload& upload)
{
    if (rgba.empty() || rgba.size() % 4 != 0)
    {
        throw std::invalid_argument("GpuRunner::RunCompute: rgba must hold RGBA pixels");
    }
    std::string why;
    Context* c = ContextFor(false, &why);
    if (!c)
    {
        throw std::runtime_error("no desktop OpenGL context for compute shaders: " + why);
    }
    const GpuShader shader = Extract(processor, OCIO::GPU_LANGUAGE_GLSL_4_0);
    const std::string text = "#version 430 core\n" + shader.ocioText +
                             "\nlayout(local_size_x = 64) in;\n"
                             "layout(std430, binding = 0) buffer Pixels { vec4 px[]; };\n"
                             "uniform uint count;\n"
                             "void main()\n"
                             "{\n"
                             "    uint i = gl_GlobalInvocationID.x;\n"
                             "    if (i < count)\n"
                             "    {\n"
                             "        px[i] = OCIOMain(px[i]);\n"
                             "    }\n"
                             "}\n";
    GLuint program = 0;
    const auto found = c->programs.find(text);
    if (found != c->programs.end())
    {
        program = found->second;
    }
    else
    {
        const GLuint cs = CompileStage(GL_COMPUTE_SHADER, text);
        program = glCreateProgram();
        glAttachShader(program, cs);
        glLinkProgram(program);
        glDeleteShader(cs);
        CheckLinked(program, "compute program");
        c->programs.emplace(text, program);
    }
    glUseProgram(program);
    const std::vector<GLuint> luts = UploadLuts(*shader.desc, program, false, upload);
    SetUniforms(*shader.desc, program);
    const GLuint count = GLuint(rgba.size() / 4);
    glUniform1ui(glGetUniformLocation(program, "count"), count);
    GLuint buffer = 0;
    glGenBuffers(1, &buffer);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer);
    glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(rgba.size() * sizeof(float)), rgba.data(),
                 GL_DYNAMIC_COPY);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffer);
    glDispatchCompute((count + 63) / 64, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<float> out(rgba.size());
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(out.size() * sizeof(float)),
                       out.data());
    CheckGl("compute dispatch");
    glDeleteBuffers(1, &buffer);
    glDeleteTextures(GLsizei(luts.size()), luts.data());
    return out;
}

}  // namespace bandlight::test
