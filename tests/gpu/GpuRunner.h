// SPDX-License-Identifier: BSD-3-Clause
// Runs OpenColorIO GPU processors on Mesa's llvmpipe through a headless EGL
// context, and validates their shaders with glslangValidator.
#pragma once

#include <string>
#include <vector>

#include <OpenColorIO/OpenColorIO.h>

namespace bandlight::test
{
namespace OCIO = OCIO_NAMESPACE;

/// "GLSL_4_0", "HLSL_DX11", ...: the enum value's name without its prefix.
const char* GpuLanguageName(OCIO::GpuLanguage language);

/// The languages GpuRunner can render with: desktop GLSL 1.2, 1.3, 4.0 (an
/// OpenGL 4.5 compatibility context) and GLSL ES 1.0, 3.0 (an OpenGL ES 3
/// context).
bool IsRunnable(OCIO::GpuLanguage language);

/// The languages glslangValidator checks: the GLSL and GLSL ES ones and
/// HLSL DX11. OCIO 2.1 also writes Cg, MSL 2.0 and OSL 1, for which Debian
/// 12 has no compiler.
bool IsValidated(OCIO::GpuLanguage language);

/// What one OCIO processor became for one language: OCIO's shader function
/// "OCIOMain" and the complete fragment shader GpuRunner compiles.
struct GpuShader
{
    OCIO::GpuShaderDescRcPtr desc;  ///< with its textures and uniforms
    std::string ocioText;           ///< OCIO's text only
    std::string fragmentText;       ///< header + OCIO's text + main()
};

/// How a host uploads OCIO's 3D LUT textures. OCIO 2.1's tetrahedral code
/// fetches the lattice nodes itself, at texel centres, so NEAREST is what it
/// needs; OCIO's own apps (oglapphelpers) and Blender set GL_LINEAR on every
/// 3D LUT that is not INTERP_NEAREST, and Blender uploads them as RGB16F.
struct LutUpload
{
    enum class Filter
    {
        NEAREST_FOR_TETRAHEDRAL,  ///< NEAREST for tetrahedral and nearest LUTs, else LINEAR
        LINEAR,                   ///< GL_LINEAR on every 3D LUT except INTERP_NEAREST ones
        NEAREST,                  ///< GL_NEAREST on every 3D LUT
    };
    Filter filter = Filter::NEAREST_FOR_TETRAHEDRAL;
    bool halfFloat = false;  ///< 3D LUTs as RGB16F (the driver rounds), else RGB32F
};

/// "nearest for tetrahedral, float", "GL_LINEAR, half", ...
std::string Describe(const LutUpload& upload);

/// Headless GPU rendering of OCIO processors, one EGL display and context
/// per API (desktop OpenGL, OpenGL ES) created on first use and kept for the
/// life of the process, and shader validation. Everything is static: there
/// is one GPU.
///
/// The fragment shader wraps OCIO's function as a host would: it reads the
/// pixel from an RGBA32F texture (texelFetch; texture2D at the texel centre
/// for the languages without it), calls OCIOMain and writes an RGBA32F
/// framebuffer, which is read back.
class GpuRunner
{
public:
    /// Extracts `processor`'s shader for `language` (function OCIOMain,
    /// pixel variable outColor, resource prefix ocio_) and wraps it in a
    /// complete fragment shader (HLSL: a pixel-shader entry point "main").
    /// Throws what OCIO throws.
    static GpuShader Extract(const OCIO::ConstGPUProcessorRcPtr& processor,
                             OCIO::GpuLanguage language);

    /// Whether a context for `language` exists (created on first call). If
    /// not, `why` says what failed.
    static bool Available(OCIO::GpuLanguage language, std::string* why = nullptr);

    /// `rgba` (width × height interleaved RGBA float, row 0 first) through
    /// `processor`'s shader in `language` on the GPU; the same layout back.
    /// Compiled programs are cached by their text, so a shader that differs
    /// only in its LUT textures is compiled once. Throws std::runtime_error
    /// with the GL or compiler message when anything fails.
    static std::vector<float> Run(const OCIO::ConstGPUProcessorRcPtr& processor,
                                  OCIO::GpuLanguage language, const std::vector<float>& rgba,
                                  int width, int height, const LutUpload& upload = {});

    /// The same through a compute shader (GLSL 4.30 around OCIO's GLSL 4.0
    /// function, one invocation per pixel, the pixels in a shader storage
    /// buffer): no rasteriser, no framebuffer, no input texture.
    static std::vector<float> RunCompute(const OCIO::ConstGPUProcessorRcPtr& processor,
                                         const std::vector<float>& rgba,
                                         const LutUpload& upload = {});

    /// The renderer's name and version ("llvmpipe (LLVM 15.0.6, 256 bits) |
    /// OpenGL 4.5 ..."), "" if there is no context for `language`.
    static std::string Renderer(OCIO::GpuLanguage language);

    /// Whether glslangValidator was found when the tests were configured.
    static bool HasValidator();

    /// Validates a complete fragment shader (GpuShader::fragmentText) with
    /// glslangValidator: "" when it compiles, else the compiler's messages.
    /// Throws std::logic_error when there is no validator and
    /// std::runtime_error when it cannot be run.
    static std::string Compile(const std::string& shaderText, OCIO::GpuLanguage language);

    /// The same for many shaders of one language, in as few validator runs
    /// as the language allows (GLSL: one per 64 files; HLSL is linked by the
    /// validator, so one run each). Results in the order of `shaderTexts`.
    static std::vector<std::string> Compile(const std::vector<std::string>& shaderTexts,
                                            OCIO::GpuLanguage language);
};

}  // namespace bandlight::test
