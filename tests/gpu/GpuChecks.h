// SPDX-License-Identifier: BSD-3-Clause
// The GPU checks the shader tests share (tests/gpu/GpuShaderTest.cpp): every
// transform of a config as a case, generated and compiled in every language
// OCIO 2.1 offers, run on llvmpipe and compared with OCIO's CPU processor.
#pragma once

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <set>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "gpu/GpuRunner.h"
#include "plugin/ConfigBuilder.h"

namespace bandlight::test
{

// ---------------------------------------------------------------------------
// Languages.

/// The languages glslangValidator checks (GLSL 1.2/1.3/4.0, GLSL ES 1.0/3.0
/// as fragment shaders; HLSL DX11 translated to SPIR-V).
const std::vector<OCIO::GpuLanguage>& ValidatedLanguages();
/// The languages OCIO 2.1 writes but Debian 12 packages no compiler for (Cg,
/// Metal 2.0, OSL 1): only checked to generate.
const std::vector<OCIO::GpuLanguage>& GeneratedOnlyLanguages();
/// The languages run on llvmpipe and compared with the CPU: the five OpenGL ones.
const std::vector<OCIO::GpuLanguage>& RunLanguages();

// ---------------------------------------------------------------------------
// Cases.

/// What a processor's ops are, which decides the tolerance.
enum class Kind
{
    MATRIX,  ///< ranges and matrices only: the same float arithmetic on both sides
    CURVE,   ///< analytic curves too (the sRGB encoding's pow): GPU pow differs in the last bits
    LUT,     ///< 1D or 3D LUTs: texture fetches and interpolation
};

const char* KindName(Kind k);

/// GPU vs CPU agreement required of each kind:
/// |gpu − cpu| ≤ relative · scale + absolute, per channel, where scale is
/// the largest |channel| of the CPU's output pixel. A pixel's scale rather
/// than the channel's own value because a 3×3 with negative entries
/// cancels: a channel near zero carries the rounding of its large
/// neighbours, on either processor.
struct Tolerance
{
    double relative;
    double absolute;
};

Tolerance ToleranceOf(Kind kind);

/// One transform to check: a processor, named, with its kind.
struct Case
{
    std::string name;  ///< "look bradford_A_to_D65", "colour space sRGB -> scene_linear"
    OCIO::ConstProcessorRcPtr processor;
    Kind kind = Kind::MATRIX;
};

Case MakeCase(std::string name, const OCIO::ConstProcessorRcPtr& processor);

/// Every transform a config offers: each look (scene_linear in and out),
/// each named transform, each colour space to and from scene_linear (only
/// from it for the spaces in `oneWay`: an LED wall's four-emitter drive, a
/// 3 → 4 map with no inverse), each display/view from scene_linear.
std::vector<Case> ConfigCases(const OCIO::ConstConfigRcPtr& config,
                              const std::set<std::string>& oneWay = {});

/// A built-in illuminant as a Light.
Light L(const std::string& name);

/// The default package config (`bandlight package`), built once.
const OCIO::ConstConfigRcPtr& PackageConfig();

/// A fresh folder under $TMPDIR, removed with what it holds.
class TempDir
{
public:
    explicit TempDir(const std::string& tag)
    {
        const char* tmp = std::getenv("TMPDIR");
        std::string pattern =
            std::string(tmp && *tmp ? tmp : "/tmp") + "/bandlight_gpu_" + tag + "_XXXXXX";
        REQUIRE(mkdtemp(pattern.data()) != nullptr);
        m_path = pattern;
    }
    ~TempDir()
    {
        std::error_code ignored;
        std::filesystem::remove_all(m_path, ignored);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    const std::string& path() const { return m_path; }

private:
    std::string m_path;
};

// ---------------------------------------------------------------------------
// The test image and the measurements.

constexpr int kWidth = 64;
constexpr int kHeight = 64;

/// 64×64 RGBA: greys, saturated colours, negatives and random colours over
/// 2^-10 … 2^16; alpha varies and must come through.
const std::vector<float>& TestImage();

/// The image through the processor's CPU form.
std::vector<float> ApplyCpu(const OCIO::ConstProcessorRcPtr& processor,
                            const std::vector<float>& rgba, int width, int height);

using Clock = std::chrono::steady_clock;

/// The worst disagreement of one comparison: absolute, and relative to the
/// pixel's scale (see Tolerance).
struct Difference
{
    double absolute = 0.0;
    double relative = 0.0;
    bool pass = true;
    std::string worst;  ///< the pixel that needed the most of its tolerance
};

/// GPU against CPU output for the same input, within `tol`; pixels marked in
/// `denormal` may come out 0 on the GPU (GLSL flushes denormals).
Difference Compare(const std::vector<float>& input, const std::vector<float>& cpu,
                   const std::vector<float>& gpu, const Tolerance& tol,
                   const std::vector<bool>* denormal = nullptr);

/// The largest differences seen, by kind and language, printed per test case.
class Report
{
public:
    void add(Kind kind, OCIO::GpuLanguage language, const Difference& d)
    {
        Difference& m = m_max[{kind, language}];
        m.absolute = std::max(m.absolute, d.absolute);
        m.relative = std::max(m.relative, d.relative);
        ++m_count[{kind, language}];
    }
    /// Notes how long a phase took, for the printout.
    void time(const std::string& phase, Clock::time_point since)
    {
        std::ostringstream s;
        s << std::fixed << std::setprecision(1)
          << std::chrono::duration<double>(Clock::now() - since).count();
        m_times += (m_times.empty() ? "" : ", ") + phase + " " + s.str() + " s";
    }
    void print(const std::string& title) const
    {
        std::ostringstream s;
        s << "[gpu] " << title << " (" << m_times << "): max |gpu - cpu| on llvmpipe"
          << (m_max.empty() ? ": no GPU runs\n" : "\n");
        s << std::defaultfloat << std::setprecision(3);
        for (const auto& [key, m] : m_max)
        {
            s << "  " << std::left << std::setw(7) << KindName(key.first) << std::setw(12)
              << GpuLanguageName(key.second) << std::right << std::setw(4) << m_count.at(key)
              << " transforms: absolute " << m.absolute << ", relative to the pixel " << m.relative
              << "\n";
        }
        std::cout << s.str() << std::flush;
    }

private:
    std::map<std::pair<Kind, OCIO::GpuLanguage>, Difference> m_max;
    std::map<std::pair<Kind, OCIO::GpuLanguage>, int> m_count;
    std::string m_times;
};

// ---------------------------------------------------------------------------
// The checks.

/// Whether the GPU can run `language`. Without a context the tests warn and
/// skip, or fail when BANDLIGHT_REQUIRE_GPU=1.
bool GpuFor(OCIO::GpuLanguage language);

/// Every case's shader is generated in every language OCIO 2.1 offers, and
/// compiles where a compiler exists.
void CheckShadersCompile(const std::vector<Case>& cases);

/// Every case on llvmpipe in each runnable language against the CPU.
void CheckGpuMatchesCpu(const std::vector<Case>& cases, Report& report);

/// Both checks above on `cases`, timed into `report`, which is printed
/// under `title`.
void CheckCasesOnGpu(const std::vector<Case>& cases, const std::string& title, Report& report);

/// Writes the config `options` describe, reads it back from its file (so
/// that the looks' FileTransforms find luts/), and runs every transform's
/// shaders: compiled in every language, run on llvmpipe against the CPU.
/// Returns how many of them are LUTs.
long CheckConfigOnGpu(const ConfigOptions& options, const std::string& name);

}  // namespace bandlight::test
