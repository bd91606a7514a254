// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// The illuminant-change methods, one entry each: its name, whether it is one
// 3×3, how it is fitted, how it is applied, what it says about itself. Adding
// a method is one entry here and the function that fits it, as OpenColorIO
// keeps an op in one folder.

#include <string>
#include <vector>

#include "transforms/IlluminantChange.h"

namespace bandlight
{

/// How a method's pixels are computed.
enum class MethodKernel
{
    MATRIX,    ///< one 3×3 in the working space (with the pixel guard)
    UPSAMPLE,  ///< a smooth remittance fitted per pixel, re-lit spectrally
    ROOTPOLY,  ///< the native root polynomial (rootpoly, rootpoly-camera)
    SPECTRAL,  ///< spectra, not pixels: the reference
};

/// The lit 3×3 of a linear method: working RGB under `from` → under `to`.
using LitMatrixFit = Mat3 (*)(const Light& from, const Light& to, const MethodSpec& method,
                              const RgbSpace& working, Observer observer);

struct MethodEntry
{
    /// The methods of this entry: one, or a family (band and band-wp).
    std::vector<ChangeMethod> methods;
    /// How the entry's names read in help ("bandN, bandN-wp, ...").
    const char* syntax;
    MethodKernel kernel;
    bool fitted;       ///< takes training remittances (fit3x3, rootpoly)
    bool needsCamera;  ///< needs the camera that shot the plates
    /// Parses a lower-case name into `spec`; false when the name is not of
    /// this entry (throws Exception when it is, but malformed).
    bool (*parse)(const std::string& name, MethodSpec& spec);
    /// One sentence on what the method does and how accurate it is.
    std::string (*describe)(const MethodSpec& spec);
    /// MATRIX kernels: the fit (nullptr otherwise).
    LitMatrixFit litMatrix;
    /// The names this entry gives a config's default looks and the
    /// accuracy report's default methods.
    std::vector<const char*> configDefaults;
    std::vector<const char*> accuracyDefaults;
};

/// Every method, in the order help texts and default lists give them.
const std::vector<MethodEntry>& Methods();

/// The entry of a method.
const MethodEntry& FindMethod(ChangeMethod method);

}  // namespace bandlight
