// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// bandlight's public value types: what a host asks for and what it gets
// back, in the standard library's types only. A field left empty is "not
// given": bandlight's default, the same the command and Python use
// (`bandlight lut --help` names each).

#include <cstddef>
#include <string>
#include <vector>

namespace bandlight
{

/// A change of light, as every face names one.
struct ChangeOfLight
{
    /// The lights: a built-in name (A, D65, F11, 3200K, D5600, ...) or a
    /// spectrum file (its first spectrum).
    std::string from;
    std::string to;
    std::string method;        ///< a method of ListMethods(); empty: bradford
    std::string workingSpace;  ///< a built-in RGB space (acescg, rec709, ...); empty: acescg
    std::string observer;      ///< "1931" or "1964"; empty: CIE 1931 2°
    /// What the images are: "balanced" (white-balanced to the working
    /// white) or "lit" (lit by `from`); empty: balanced.
    std::string plates;
    std::string adaptation;  ///< of balanced plates: "cat02" or "bradford"; empty: cat02
    /// Camera methods: the camera's sensitivities file, and the light of
    /// its one fixed IDT (empty: D55).
    std::string camera;
    std::string idtLight;
    /// Fitted methods: remittances to fit on (TCS01–TCS15, TCS, or a
    /// spectrum file); empty: the method's own set.
    std::string training;
};

/// How a LUT file is written (WriteLut).
struct LutSettings
{
    /// clf, ctf, cube, spi3d, 3dl, resolve_cube, csp, houdini; empty: the
    /// format that owns the path's extension.
    std::string format;
    int size = 0;          ///< 3D LUT points per axis; 0: bandlight's default
    std::string shaper;    ///< "log2" or "none"; empty: log2
    std::string encoding;  ///< "linear", "acescct" or "acescc"; empty: linear
};

/// The files a LUT was written as.
struct WrittenLut
{
    std::string lut;
    std::string shaper;    ///< a companion shaper CLF for 3D-only formats; empty: none
    int size = 0;          ///< 3D LUT points per axis (0: the exact matrix, no lattice)
    std::string encoding;  ///< what the LUT takes and returns, one sentence
};

/// An OCIO config of bandlight's looks (WriteConfig).
struct ConfigSettings
{
    std::string out;   ///< the folder config.ocio and its LUT files are written into
    std::string base;  ///< a studio config to extend (folder or .ocio file); empty: a new one
    std::vector<std::string> lights;   ///< built-in names or files; empty: A, C, D65, F2, F11
    std::vector<std::string> methods;  ///< empty: the linear methods
    std::string workingSpace;  ///< empty: acescg, or with a base its scene_linear's primaries
    std::string observer;
    std::string plates;
    std::string adaptation;
};

/// What a config was written as.
struct WrittenConfig
{
    std::string file;                   ///< {out}/config.ocio
    std::vector<std::string> looks;     ///< every look's name, in the config's order
    std::vector<std::string> lutFiles;  ///< the files beside it its looks read
    std::string workingSpace;           ///< the working space's built-in name
};

/// Images written by RelightImages or ApplyLook.
struct WrittenImages
{
    std::string applied;  ///< what was applied: a look's name
    size_t frames = 0;    ///< frames written (1 for one image)
    double seconds = 0.0;
    bool native = false;  ///< applied by bandlight's own kernel, not an OCIO processor
};

/// One method of the registry, as `bandlight methods` lists it.
struct MethodInfo
{
    std::string names;      ///< its names as help gives them: "rootpoly, rootpoly3"
    std::string exactness;  ///< "linear" (one 3x3), "non-linear" (an op per pixel) or "reference"
    bool native = false;    ///< `apply` runs its op itself, not its OCIO form
    bool needsCamera = false;            ///< needs the camera that shot the plates
    bool takesTraining = false;          ///< a user's training set may replace its own
    size_t trainingSize = 0;             ///< its default training set's size (0: not fitted)
    std::vector<std::string> defaultIn;  ///< "config", "accuracy", "camera accuracy"
    std::string description;             ///< its own sentence, for its first name
};

}  // namespace bandlight
