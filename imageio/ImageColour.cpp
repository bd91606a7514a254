// SPDX-License-Identifier: BSD-3-Clause
#include "imageio/ImageColour.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "plugin/ConfigBuilder.h"
#include "plugin/OcioTransforms.h"
#include "spectral/Exception.h"
#include "spectral/TextFile.h"

namespace bandlight
{

namespace
{

const char* kOptions =
    "say what the file holds with {colorspace} (a built-in space such as "
    "acescg or rec709, or srgb), or choose the space the work runs in with "
    "{working_space}";

/// The built-in space whose Color Interop Forum ID (colorInteropID) is `id`
/// (lower case), with the ID's entry; nullptr when no space has it.
const RgbSpace* SpaceOfInteropId(const std::string& id, InteropId& found)
{
    for (const RgbSpace& s : BuiltinRgbSpaces())
    {
        for (const InteropId& k : s.interopIds)
        {
            if (k.id == id)
            {
                found = k;
                return &s;
            }
        }
    }
    return nullptr;
}

bool SameChromaticities(const Chromaticities& a, const Chromaticities& b)
{
    const double d[] = {a.rx - b.rx, a.ry - b.ry, a.gx - b.gx, a.gy - b.gy,
                        a.bx - b.bx, a.by - b.by, a.wx - b.wx, a.wy - b.wy};
    return std::all_of(std::begin(d), std::end(d), [](double v) { return std::abs(v) < 2e-3; });
}

std::string Describe(const Chromaticities& c)
{
    std::ostringstream o;
    o.precision(4);
    o << "R (" << c.rx << ", " << c.ry << ") G (" << c.gx << ", " << c.gy << ") B (" << c.bx << ", "
      << c.by << ") white (" << c.wx << ", " << c.wy << ")";
    return o.str();
}

/// A built-in space of these chromaticities, or a space of the file's own.
RgbSpace SpaceOf(const Chromaticities& c)
{
    for (const RgbSpace& s : BuiltinRgbSpaces())
    {
        if (SameChromaticities(s.chromaticities, c))
        {
            return s;
        }
    }
    RgbSpace own;
    own.name = "file";
    own.displayName = "the file's primaries " + Describe(c);
    own.chromaticities = c;
    return own;
}

/// A built-in space by bandlight's name or the name its configs give it.
const RgbSpace* SpaceNamed(const std::string& name)
{
    for (const RgbSpace& s : BuiltinRgbSpaces())
    {
        if (ToLower(ColorSpaceName(s)) == ToLower(name))
        {
            return &s;
        }
    }
    try
    {
        return &FindRgbSpace(name);
    }
    catch (const Exception&)
    {
        return nullptr;
    }
}

/// "0.64, 0.33, ..." (OIIO's text of a float[8]) → chromaticities.
std::optional<Chromaticities> ParseChromaticities(const std::string& text)
{
    double v[8];
    const char* p = text.c_str();
    for (double& x : v)
    {
        while (*p == ' ' || *p == ',' || *p == '(' || *p == '{')
        {
            ++p;
        }
        char* end = nullptr;
        x = std::strtod(p, &end);
        if (end == p || !std::isfinite(x))
        {
            return std::nullopt;
        }
        p = end;
    }
    return Chromaticities{v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]};
}

bool IntegerChannels(const ImageData& header)
{
    return !header.channelTypes.empty() &&
           std::all_of(header.channelTypes.begin(), header.channelTypes.end(),
                       [](const std::string& t)
                       { return t.rfind("uint", 0) == 0 || t.rfind("int", 0) == 0; });
}

}  // namespace

std::string SpaceLabel(const RgbSpace& space)
{
    return space.label.empty() ? space.displayName : space.label;
}

std::string ImageEncoding::describe() const
{
    std::ostringstream g;
    g << "gamma " << gamma << "-encoded ";
    return (srgbCurve     ? std::string("sRGB-encoded ")
            : gamma > 0.0 ? g.str()
                          : "linear ") +
           SpaceLabel(space);
}

ImageEncoding NamedEncoding(const std::string& name)
{
    ImageEncoding e;
    e.evidence = "as given";
    if (ToLower(name) == "srgb")
    {
        e.space = Rec709Space();
        e.srgbCurve = true;
        return e;
    }
    const RgbSpace* s = SpaceNamed(name);
    if (!s)
    {
        throw ParameterError("{colorspace} '" + OneLine(name, 80) +
                             "' is not a built-in RGB space (" + RgbSpaceChoices() + ") or srgb");
    }
    e.space = *s;
    return e;
}

bool IsDisplayReferred(const ImageData& header)
{
    return IntegerChannels(header) || header.format == "png" || header.format == "jpeg";
}

void RequireNamedChannels(const std::string& path, const std::string& layers)
{
    const size_t dot = path.find_last_of('.');
    const size_t slash = path.find_last_of('/');
    const bool hasExtension = dot != std::string::npos && (slash == std::string::npos || dot > slash);
    const std::string ext = hasExtension ? ToLower(path.substr(dot + 1)) : "";
    if (ext != "exr" && ext != "sxr")
    {
        throw ParameterError(PathInMessage(path) + ": " + layers +
                             " are named layers, and only an EXR keeps channel names (in this "
                             "format they would become anonymous channels): write an .exr");
    }
}

bool IsDisplayReferredFile(const std::string& path)
{
    const size_t dot = path.find_last_of('.');
    const size_t slash = path.find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
    {
        return false;
    }
    const std::string ext = ToLower(path.substr(dot + 1));
    for (const char* e : {"png", "jpg", "jpeg", "jpe", "jfif", "gif", "bmp", "webp", "ppm", "pgm",
                          "pnm", "tga", "ico"})
    {
        if (ext == e)
        {
            return true;
        }
    }
    return false;
}

namespace
{

/// What the tags of one image say so far: each tag read must agree with
/// those before it, or the file contradicts itself.
struct TagEvidence
{
    std::string what;  ///< "FILE: "
    std::optional<ImageEncoding> found;

    void agree(const ImageEncoding& e)
    {
        if (found && (found->srgbCurve != e.srgbCurve || found->gamma != e.gamma ||
                      !SameChromaticities(found->space.chromaticities, e.space.chromaticities)))
        {
            throw ParameterError(what + "says it is " + found->describe() + " (" + found->evidence +
                                 ") and " + e.describe() + " (" + e.evidence + "); " + kOptions);
        }
        if (!found)
        {
            found = e;
        }
    }
};

/// colorInteropID: the Color Interop Forum's name of the encoding.
void ReadInteropId(const std::string& interop, TagEvidence& tags)
{
    const std::string id = ToLower(interop);
    InteropId known;
    const RgbSpace* space = SpaceOfInteropId(id, known);
    if (!space)
    {
        throw ParameterError(tags.what + "has colorInteropID '" + OneLine(interop, 60) +
                             "', which bandlight does not convert; " + kOptions);
    }
    ImageEncoding e;
    e.space = *space;
    e.srgbCurve = known.srgbEncoded;
    e.evidence = "colorInteropID " + known.id;
    tags.agree(e);
}

/// chromaticities: the primaries; the curve is what the tags before said,
/// or the format's.
void ReadChromaticities(const std::string& chroma, const ImageData& header, TagEvidence& tags)
{
    const std::optional<Chromaticities> c = ParseChromaticities(chroma);
    if (!c)
    {
        throw Exception(tags.what + "its chromaticities attribute '" + OneLine(chroma, 80) +
                        "' is not 8 numbers");
    }
    ImageEncoding e;
    e.space = SpaceOf(*c);
    e.evidence = "chromaticities";
    e.srgbCurve = tags.found ? tags.found->srgbCurve : IsDisplayReferred(header);
    e.gamma = tags.found ? tags.found->gamma : 0.0;
    tags.agree(e);
}

/// bandlight:colorSpace: the name bandlight wrote (OpenImageIO 2.4 drops
/// oiio:ColorSpace from the EXRs it writes).
void ReadBandlightName(const std::string& named, TagEvidence& tags)
{
    const RgbSpace* s = SpaceNamed(named);
    if (!s)
    {
        throw ParameterError(tags.what + "has bandlight:colorSpace '" + OneLine(named, 60) +
                             "': not colour bandlight converts; " + kOptions);
    }
    ImageEncoding e;
    e.space = *s;
    e.evidence = "bandlight:colorSpace";
    tags.agree(e);
}

/// oiio:ColorSpace, read only when nothing else spoke: OpenImageIO's own
/// guess from the format (sRGB, a PNG gamma, "Linear" for every EXR).
std::optional<ImageEncoding> ReadOiioColorSpace(const std::string& oiio, const ImageData& header,
                                                const std::string& what)
{
    const std::string v = ToLower(oiio);
    ImageEncoding e;
    e.evidence = "oiio:ColorSpace " + oiio;
    double gamma = 0.0;
    char tail = 0;
    if (v == "srgb" || v == "srgb_rec709_scene")
    {
        e.space = Rec709Space();
        e.srgbCurve = true;
        return e;
    }
    if (std::sscanf(v.c_str(), "gamma%lf%c", &gamma, &tail) == 1 && gamma >= 0.1 && gamma <= 10.0)
    {
        // PNG's gAMA chunk as OpenImageIO reports it: Rec.709 primaries.
        e.space = Rec709Space();
        e.gamma = gamma;
        return e;
    }
    if (v == "linear" || v == "scene_linear" || v == "lin_srgb")
    {
        // OpenImageIO calls every EXR "Linear": the primaries are not
        // said. Integer formats without primaries are Rec.709 (the sRGB
        // chunk's and TIFF's default).
        if (IntegerChannels(header))
        {
            e.space = Rec709Space();
            return e;
        }
        return std::nullopt;
    }
    if (const RgbSpace* s = SpaceNamed(oiio))
    {
        e.space = *s;
        return e;
    }
    throw ParameterError(what + "has oiio:ColorSpace '" + OneLine(oiio, 60) +
                         "', an encoding bandlight does not convert; " + kOptions);
}

}  // namespace

ImageEncoding IdentifyImageEncoding(const ImageData& header, const std::string& file,
                                    const RgbSpace& fallback)
{
    const auto get = [&](const char* key) -> const std::string*
    {
        const auto it = header.attributes.find(key);
        return it == header.attributes.end() || it->second.empty() ? nullptr : &it->second;
    };
    TagEvidence tags{file + ": ", std::nullopt};
    if (const std::string* interop = get("colorInteropID"))
    {
        ReadInteropId(*interop, tags);
    }
    if (const std::string* chroma = get("chromaticities"))
    {
        ReadChromaticities(*chroma, header, tags);
    }
    if (const std::string* named = get("bandlight:colorSpace"))
    {
        ReadBandlightName(*named, tags);
    }
    if (const std::string* oiio = get("oiio:ColorSpace"); oiio && !tags.found)
    {
        tags.found = ReadOiioColorSpace(*oiio, header, tags.what);
    }
    if (tags.found)
    {
        return *tags.found;
    }
    if (IsDisplayReferred(header))
    {
        ImageEncoding e;
        e.space = Rec709Space();
        e.srgbCurve = true;
        e.evidence = "an untagged " + header.format + " of integer code values";
        return e;
    }
    ImageEncoding e;
    e.space = fallback;
    e.assumed = true;
    e.evidence = "untagged";
    return e;
}

namespace
{
OCIO::ConstCPUProcessorRcPtr Cpu(const OCIO::GroupTransformRcPtr& g)
{
    if (g->getNumTransforms() == 0)
    {
        return nullptr;
    }
    // The curves in full precision: OCIO's fast pow approximation is off by
    // up to 1e-4 of the value, a code value of a 16-bit file.
    const auto optimisation =
        OCIO::OptimizationFlags(OCIO::OPTIMIZATION_DEFAULT & ~OCIO::OPTIMIZATION_FAST_LOG_EXP_POW);
    return OCIO::Config::CreateRaw()->getProcessor(g)->getOptimizedCPUProcessor(
        OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32, optimisation);
}

/// A pure power curve, encoded → linear (v^gamma; negative values mirrored).
OCIO::TransformRcPtr GammaDecode(double gamma)
{
    OCIO::ExponentTransformRcPtr t = OCIO::ExponentTransform::Create();
    const double g[4] = {gamma, gamma, gamma, 1.0};
    t->setValue(g);
    t->setNegativeStyle(OCIO::NEGATIVE_MIRROR);
    return t;
}
}  // namespace

OCIO::ConstCPUProcessorRcPtr EncodingToLinear(const ImageEncoding& from, const RgbSpace& to)
{
    OCIO::GroupTransformRcPtr g = OCIO::GroupTransform::Create();
    if (from.srgbCurve)
    {
        g->appendTransform(SrgbDecode());
    }
    else if (from.gamma > 0.0)
    {
        g->appendTransform(GammaDecode(from.gamma));
    }
    if (!SameChromaticities(from.space.chromaticities, to.chromaticities))
    {
        g->appendTransform(GuardedMatrixTransform(SpaceToSpace(from.space, to)));
    }
    return Cpu(g);
}

OCIO::ConstCPUProcessorRcPtr LinearToEncoding(const RgbSpace& from, const ImageEncoding& to)
{
    OCIO::GroupTransformRcPtr g = OCIO::GroupTransform::Create();
    if (!SameChromaticities(from.chromaticities, to.space.chromaticities))
    {
        g->appendTransform(GuardedMatrixTransform(SpaceToSpace(from, to.space)));
    }
    if (to.srgbCurve || to.gamma > 0.0)
    {
        OCIO::TransformRcPtr encode = to.srgbCurve ? SrgbDecode() : GammaDecode(to.gamma);
        encode->setDirection(OCIO::TRANSFORM_DIR_INVERSE);
        g->appendTransform(encode);
    }
    return Cpu(g);
}

}  // namespace bandlight
