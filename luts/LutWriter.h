// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <OpenColorIO/OpenColorIO.h>

#include "luts/LutEncoding.h"
#include "luts/Shaper.h"
#include "spectral/AtomicFile.h"
#include "transforms/Defaults.h"

namespace bandlight
{

/// LUT file formats bandlight writes.
enum class LutFormat
{
    CLF,       ///< Academy/ASC Common LUT Format, through GroupTransform::write
    CTF,       ///< Autodesk Color Transform Format, through GroupTransform::write
    CUBE,      ///< Iridas/Adobe .cube 3D LUT, through OCIO's Baker (iridas_cube)
    SPI3D,     ///< Sony Pictures Imageworks .spi3d (OCIO 2.1 has no writer; see WriteLut)
    THREE_DL,  ///< Autodesk Flame .3dl, through OCIO's Baker (flame): integer values
    // Hosts' own formats, through OCIO's Baker, for display-referred [0, 1]
    // data only (--shaper none): their 1D pre-LUT, as OCIO 2.1 bakes it,
    // cannot carry a log shaper for scene-linear HDR (see WriteLut).
    RESOLVE_CUBE,  ///< DaVinci Resolve .cube, Baker "resolve_cube"
    CINESPACE,     ///< Rising Sun cinespace .csp, Baker "cinespace"
    HOUDINI,       ///< SideFX Houdini .lut, Baker "houdini"
};

/// Who writes a LUT format's files.
enum class LutWriterKind
{
    /// OCIO's GroupTransform::write (CLF, CTF): a matrix stays a matrix, a
    /// lattice carries its shaper inside the same file.
    GROUP,
    /// OCIO's Baker, under the entry's `baker` name.
    BAKER,
    /// bandlight's own writer of the format (SPI 3D: OCIO 2.1 reads it but
    /// has no writer for it).
    OWN_SPI3D,
};

/// How a format holds the log shaper a scene-linear HDR lattice needs.
enum class LutShaperRule
{
    IN_FILE,    ///< in the same file (a CLF/CTF group: shaper, Lut3D, inverse shaper)
    COMPANION,  ///< a companion <name>.shaper.clf applied before and inverted after
    /// Only as the format's own 1D pre-LUT, which OCIO 2.1 bakes too
    /// coarsely for HDR: the format is for display-referred [0, 1] data
    /// (shaper none) or log-encoded LUTs (ACEScct, ACEScc).
    NONE_FOR_HDR,
};

/// A LUT format's one table entry: its names and file extension, who
/// writes it (and the Baker's name for it), how it holds a shaper, and
/// which hosts read it. LutFormats() lists them; nothing else switches on
/// a format.
struct LutFormatEntry
{
    LutFormat format;
    const char* name;                  ///< "clf", "resolve_cube", ...
    std::vector<const char*> aliases;  ///< other names ("cinespace", "resolve-cube")
    const char* extension;             ///< without the dot: "cube"
    /// The format a file of this extension is written in when no format is
    /// named (one per extension: .cube is the Iridas/Adobe cube).
    bool ownsExtension;
    const char* what;  ///< one phrase for help and errors
    LutWriterKind writer;
    /// GROUP: GroupTransform::write's format name; BAKER: OCIO's Baker format name.
    const char* ocioFormat;
    LutShaperRule shaper;
    const char* hosts;  ///< the hosts that read it, for docs and help
};

/// Every LUT format, in the order help lists them.
const std::vector<LutFormatEntry>& LutFormats();

/// The entry of a format.
const LutFormatEntry& FindLutFormat(LutFormat format);

/// "clf", "ctf", "cube", "spi3d", "3dl", "resolve_cube", "csp" (or "cinespace"),
/// "houdini" (case-insensitive); throws Exception listing them otherwise.
LutFormat ParseLutFormat(const std::string& text);
const char* LutExtension(LutFormat format);
/// The names of every format, as help and errors list them.
std::string LutFormatChoices();

/// The format of a LUT file path: `format` when given (its extension must
/// be the file's: a CLF named .cube would be misread by every cube reader),
/// else the format that owns the path's extension. Throws ParameterError
/// naming the path and the extensions otherwise.
LutFormat LutFormatForPath(const std::string& path, const std::string& format);

struct LutOptions
{
    LutFormat format = LutFormat::CLF;
    int size = defaults::TRANSFORM_LUT_SIZE;  ///< lattice points per axis for 3D LUTs (2–129; `lut`: defaults::LUT_SIZE)
    bool forceLattice = false;  ///< bake a 3D LUT even where a matrix fits (CLF/CTF)
    ShaperSpec shaper;          ///< for LutEncoding::LINEAR only
    /// ACEScct or ACEScc: the 3D LUT takes and returns encoded values, no
    /// shaper, in every format (linear methods too: no matrix form).
    LutEncoding encoding = LutEncoding::LINEAR;
    std::string description;  ///< written into formats that carry metadata
};

/// What WriteLut wrote.
struct LutFiles
{
    std::string lut;
    std::string shaper;  ///< companion shaper CLF for 3D-only formats ("" if none)
    bool lattice = false;
    bool outputEncoded = false;  ///< the 3D LUT's output is shaper-encoded: apply the inverse after
    LutEncoding encoding = LutEncoding::LINEAR;  ///< of the LUT's input and output
};

/// A transform given as a function on interleaved linear RGB float triples
/// (in place), for transforms that are not OCIO ops (spectral upsampling).
using PixelFunction = std::function<void(float* rgb, size_t count)>;

/// The same as an OCIO transform applied on the CPU.
PixelFunction PixelFunctionOf(const OCIO::ConstTransformRcPtr& exact);

/// The exact transform sampled on a size³ lattice over the shaper's domain:
/// node (r, g, b) holds exact(decode(node)) — or its shaper encoding when
/// `encodeOutput` — red varying fastest, three floats per node.
std::vector<float> BakeLattice(const PixelFunction& exact, const ShaperSpec& shaper, int size,
                               bool encodeOutput);

/// The same over an encoding's [0, 1] (ACEScct, ACEScc): node (r, g, b)
/// holds encode(exact(decode(node))), decoded and encoded through OCIO's own
/// built-in transforms (LutEncodingTransform).
std::vector<float> BakeLattice(const PixelFunction& exact, LutEncoding encoding, int size);

/// The description a transform carries in its format metadata ("" if none).
std::string TransformDescription(const OCIO::ConstTransformRcPtr& transform);

/// Shaper, 3D LUT (tetrahedral, shaper-encoded in and out), inverse shaper,
/// as one OCIO group: the lattice form of `exact` for scene-linear input.
OCIO::GroupTransformRcPtr LatticeTransform(const PixelFunction& exact, const ShaperSpec& shaper,
                                           int size);
OCIO::GroupTransformRcPtr LatticeTransform(const OCIO::ConstTransformRcPtr& exact,
                                           const ShaperSpec& shaper, int size);

/// Writes `exact` (a transform on linear RGB) to `path` in `options.format`,
/// atomically. CLF/CTF hold a linear transform (`isMatrix`) as the matrix
/// itself, anything else as shaper + 3D LUT in one file. The 3D-only
/// formats hold the lattice over the shaper's domain, shaper-encoded in and
/// out, and get the shaper as a companion `<stem>.shaper.clf`: apply it
/// before the LUT and its inverse after (so 3dl's integer output holds HDR
/// too). spi3d is written here because OCIO 2.1 offers no spi3d writer; OCIO
/// reads it back in the tests.
///
/// With a log encoding (options.encoding) every format holds the 3D LUT
/// over the encoded [0, 1], encoded in and out, with no shaper: CLF and CTF
/// as a lone Lut3D, the hosts' formats through the Baker with no pre-LUT.
///
/// The LUT and its shaper are one set of outputs: with `outputs` they join
/// that set (the caller commits it); without, they are replaced together
/// when both are written, or neither is.
LutFiles WriteLut(const OCIO::ConstTransformRcPtr& exact, bool isMatrix, const LutOptions& options,
                  const std::string& path, OutputSet* outputs = nullptr);

/// What WriteLut wrote, read back as one transform through OCIO's own file
/// readers: the companion shaper (if any), the LUT (tetrahedral), and the
/// inverse shaper when the LUT's output is shaper-encoded. A log-encoded LUT
/// is read alone: it takes and returns encoded values.
OCIO::GroupTransformRcPtr ReadLutFiles(const LutFiles& files);

/// The same for a transform that exists only as a pixel function: always a
/// lattice (CLF/CTF hold shaper + 3D LUT + inverse shaper).
LutFiles WriteLut(const PixelFunction& exact, const LutOptions& options, const std::string& path,
                  OutputSet* outputs = nullptr);

}  // namespace bandlight
