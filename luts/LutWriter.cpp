// SPDX-License-Identifier: BSD-3-Clause
#include "luts/LutWriter.h"

#include <algorithm>
#include <filesystem>
#include <cctype>
#include <iomanip>

#include "spectral/AtomicFile.h"
#include "spectral/Exception.h"

namespace bandlight
{

namespace
{

/// `t` as a group; a group is copied whole, keeping its name and description.
OCIO::GroupTransformRcPtr AsGroup(const OCIO::ConstTransformRcPtr& t)
{
    if (auto g = OCIO::DynamicPtrCast<const OCIO::GroupTransform>(t))
    {
        return OCIO::DynamicPtrCast<OCIO::GroupTransform>(g->createEditableCopy());
    }
    OCIO::GroupTransformRcPtr g = OCIO::GroupTransform::Create();
    g->appendTransform(t->createEditableCopy());
    return g;
}

/// Runs `t` over a buffer of RGB floats in place.
void Apply(const OCIO::ConstTransformRcPtr& t, std::vector<float>& rgb)
{
    OCIO::ConstConfigRcPtr raw = OCIO::Config::CreateRaw();
    OCIO::ConstCPUProcessorRcPtr cpu = raw->getProcessor(t)->getOptimizedCPUProcessor(
        OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32, OCIO::OPTIMIZATION_NONE);
    // In rows of at most 4096 pixels: OCIO allocates (and zeroes) scratch
    // buffers as wide as the row for every apply, which for a 65^3 lattice
    // as one row cost more than the transform.
    const size_t pixels = rgb.size() / 3, row = 4096;
    for (size_t begin = 0; begin < pixels; begin += row)
    {
        OCIO::PackedImageDesc desc(rgb.data() + 3 * begin, long(std::min(row, pixels - begin)), 1,
                                   3);
        cpu->apply(desc);
    }
}

void WriteGroup(const OCIO::GroupTransformRcPtr& group, LutFormat format, const std::string& path,
                const std::string& description, OutputSet& outputs)
{
    const char* ocioFormat = FindLutFormat(format).ocioFormat;
    if (!description.empty() && !group->getFormatMetadata().getNumChildrenElements())
    {
        group->getFormatMetadata().addChildElement(OCIO::METADATA_DESCRIPTION, description.c_str());
    }
    OCIO::ConstConfigRcPtr raw = OCIO::Config::CreateRaw();
    outputs.write(path, [&](std::ostream& os) { group->write(raw, ocioFormat, os); });
}

/// A config for OCIO's Baker: "lut_in" is the lattice's (encoded) input,
/// "lut_out" the lattice applied to it, so the Baker resamples the lattice
/// at its own nodes (the same nodes: the values pass through unchanged).
OCIO::ConfigRcPtr BakerConfig(const OCIO::Lut3DTransformRcPtr& lut)
{
    OCIO::ConfigRcPtr config = OCIO::Config::CreateRaw()->createEditableCopy();
    OCIO::ColorSpaceRcPtr in = OCIO::ColorSpace::Create();
    in->setName("lut_in");
    config->addColorSpace(in);
    OCIO::ColorSpaceRcPtr out = OCIO::ColorSpace::Create();
    out->setName("lut_out");
    out->setTransform(lut, OCIO::COLORSPACE_DIR_FROM_REFERENCE);
    config->addColorSpace(out);
    return config;
}

/// Copies a red-fastest lattice into a Lut3DTransform.
void SetLattice(OCIO::Lut3DTransform& lut, const std::vector<float>& lattice, int size)
{
    for (int b = 0; b < size; ++b)
    {
        for (int g = 0; g < size; ++g)
        {
            for (int r = 0; r < size; ++r)
            {
                const size_t i = (size_t(b) * size_t(size) + size_t(g)) * size_t(size) + size_t(r);
                lut.setValue(unsigned(r), unsigned(g), unsigned(b), lattice[3 * i],
                             lattice[3 * i + 1], lattice[3 * i + 2]);
            }
        }
    }
}

/// Writes a lattice through OCIO's Baker in `o.format`: the Baker samples a
/// config's processor, so it is given the lattice as a Lut3D from the
/// (shaper-encoded) input space to the output space, at the same nodes.
void BakeThroughOcio(const std::vector<float>& lattice, const LutOptions& o,
                     const std::string& path, OutputSet& set)
{
    const char* format = FindLutFormat(o.format).ocioFormat;
    OCIO::Lut3DTransformRcPtr lut = OCIO::Lut3DTransform::Create(unsigned(o.size));
    lut->setInterpolation(OCIO::INTERP_TETRAHEDRAL);
    SetLattice(*lut, lattice, o.size);
    OCIO::BakerRcPtr baker = OCIO::Baker::Create();
    baker->setConfig(BakerConfig(lut));
    baker->setFormat(format);
    baker->setInputSpace("lut_in");
    baker->setTargetSpace("lut_out");
    baker->setCubeSize(o.size);
    if (!o.description.empty())
    {
        baker->getFormatMetadata().addChildElement(OCIO::METADATA_DESCRIPTION,
                                                   o.description.c_str());
    }
    set.write(path, [&](std::ostream& os) { baker->bake(os); });
}

void WriteSpi3d(const std::vector<float>& lattice, int size, const std::string& path,
                OutputSet& outputs)
{
    // SPI 3D LUT: "SPILUT 1.0", "3 3", the grid size, then one line per node
    // "i j k r g b"; OCIO's reader (FileFormatSpi3D) takes the indices as given.
    outputs.write(path,
                  [&](std::ostream& os)
                  {
                      os << "SPILUT 1.0\n3 3\n" << size << " " << size << " " << size << "\n";
                      os << std::setprecision(9);
                      for (int r = 0; r < size; ++r)
                      {
                          for (int g = 0; g < size; ++g)
                          {
                              for (int b = 0; b < size; ++b)
                              {
                                  const size_t i =
                                      (size_t(b) * size_t(size) + size_t(g)) * size_t(size) +
                                      size_t(r);
                                  os << r << ' ' << g << ' ' << b << ' ' << lattice[3 * i] << ' '
                                     << lattice[3 * i + 1] << ' ' << lattice[3 * i + 2] << '\n';
                              }
                          }
                      }
                  });
}

/// The exact transform sampled on a size³ lattice over [0, 1] of an
/// encoding (linear → [0, 1], nullptr for none): nodes decoded through its
/// inverse, the transform applied, and (`encodeOutput`) encoded again.
std::vector<float> BakeOver(const PixelFunction& exact, const OCIO::TransformRcPtr& encoding,
                            int size, bool encodeOutput)
{
    if (size < 2 || size > 129)
    {
        throw Exception("3D LUT size must be 2 to 129, got " + std::to_string(size));
    }
    const size_t n = size_t(size) * size_t(size) * size_t(size);
    std::vector<float> rgb(3 * n);
    for (size_t i = 0; i < n; ++i)
    {
        const size_t r = i % size_t(size);
        const size_t g = (i / size_t(size)) % size_t(size);
        const size_t b = i / (size_t(size) * size_t(size));
        rgb[3 * i] = float(double(r) / double(size - 1));
        rgb[3 * i + 1] = float(double(g) / double(size - 1));
        rgb[3 * i + 2] = float(double(b) / double(size - 1));
    }
    if (encoding)
    {
        OCIO::TransformRcPtr decode = encoding->createEditableCopy();
        decode->setDirection(OCIO::GetInverseTransformDirection(encoding->getDirection()));
        Apply(decode, rgb);
    }
    exact(rgb.data(), n);
    if (encoding && encodeOutput)
    {
        Apply(encoding, rgb);
    }
    return rgb;
}

std::string ShaperCompanionPath(const std::string& path)
{
    const size_t slash = path.find_last_of('/');
    const size_t dot = path.find_last_of('.');
    const bool hasExt = dot != std::string::npos && (slash == std::string::npos || dot > slash);
    return (hasExt ? path.substr(0, dot) : path) + ".shaper.clf";
}

/// A log-encoded 3D LUT (ACEScct, ACEScc in and out) in any format: the
/// lattice over the encoded [0, 1] needs no shaper, so the hosts' formats
/// hold it through the Baker without a pre-LUT, and CLF/CTF as a lone Lut3D.
void WriteEncodedLut(const PixelFunction& exact, const LutOptions& o, const std::string& path,
                     OutputSet& set)
{
    // Bake into memory first, so a failure leaves no file behind.
    const std::vector<float> lattice = BakeLattice(exact, o.encoding, o.size);
    std::string description = o.description;
    if (description.find("Input and output:") == std::string::npos)
    {
        description += (description.empty() ? "" : " ") +
                       DescribeLutEncoding(o.encoding, "the working space's");
    }
    switch (FindLutFormat(o.format).writer)
    {
        case LutWriterKind::GROUP:
        {
            OCIO::Lut3DTransformRcPtr lut = OCIO::Lut3DTransform::Create(unsigned(o.size));
            lut->setInterpolation(OCIO::INTERP_TETRAHEDRAL);
            lut->setFileOutputBitDepth(OCIO::BIT_DEPTH_F32);
            SetLattice(*lut, lattice, o.size);
            OCIO::GroupTransformRcPtr group = OCIO::GroupTransform::Create();
            group->appendTransform(lut);
            WriteGroup(group, o.format, path, description, set);
            return;
        }
        case LutWriterKind::OWN_SPI3D:
            WriteSpi3d(lattice, o.size, path, set);
            return;
        case LutWriterKind::BAKER:
        {
            LutOptions withDescription = o;
            withDescription.description = description;
            BakeThroughOcio(lattice, withDescription, path, set);
            return;
        }
    }
}

}  // namespace

const std::vector<LutFormatEntry>& LutFormats()
{
    using W = LutWriterKind;
    using S = LutShaperRule;
    // clang-format off
    static const std::vector<LutFormatEntry> formats = {
        {LutFormat::CLF, "clf", {}, "clf", true, "Academy/ASC Common LUT Format (XML)",
         W::GROUP, "Academy/ASC Common LUT Format", S::IN_FILE,
         "OCIO 2 hosts (Nuke, Blender, Resolve 18+, oiiotool), ACES tools"},
        {LutFormat::CTF, "ctf", {}, "ctf", true, "Autodesk Color Transform Format (XML)",
         W::GROUP, "Color Transform Format", S::IN_FILE, "OCIO 2 hosts, Autodesk Flame and Maya"},
        {LutFormat::CUBE, "cube", {}, "cube", true, "Iridas/Adobe .cube 3D LUT",
         W::BAKER, "iridas_cube", S::COMPANION, "almost every grading and compositing host"},
        {LutFormat::SPI3D, "spi3d", {}, "spi3d", true, "Sony Pictures Imageworks 3D LUT",
         W::OWN_SPI3D, "", S::COMPANION, "OCIO 1 and 2 hosts"},
        {LutFormat::THREE_DL, "3dl", {}, "3dl", true, "Autodesk Flame 3D LUT (integer values)",
         W::BAKER, "flame", S::COMPANION, "Autodesk Flame and Lustre, Nuke"},
        {LutFormat::RESOLVE_CUBE, "resolve_cube", {"resolve-cube"}, "cube", false,
         "DaVinci Resolve .cube with a 1D pre-LUT",
         W::BAKER, "resolve_cube", S::NONE_FOR_HDR, "DaVinci Resolve"},
        {LutFormat::CINESPACE, "csp", {"cinespace"}, "csp", true, "Rising Sun cinespace",
         W::BAKER, "cinespace", S::NONE_FOR_HDR, "cineSpace, Nuke"},
        {LutFormat::HOUDINI, "houdini", {"lut"}, "lut", true, "SideFX Houdini .lut",
         W::BAKER, "houdini", S::NONE_FOR_HDR, "SideFX Houdini"},
    };
    // clang-format on
    return formats;
}

namespace
{
std::string LowerText(std::string t)
{
    std::transform(t.begin(), t.end(), t.begin(), [](unsigned char c) { return std::tolower(c); });
    return t;
}

}  // namespace

const LutFormatEntry& FindLutFormat(LutFormat format)
{
    for (const LutFormatEntry& e : LutFormats())
    {
        if (e.format == format)
        {
            return e;
        }
    }
    throw Exception("LUT format " + std::to_string(int(format)) + " is not in the table");
}

std::string LutFormatChoices()
{
    std::string out;
    for (const LutFormatEntry& e : LutFormats())
    {
        out += (out.empty() ? "" : ", ") + std::string(e.name);
    }
    return out;
}

LutFormat ParseLutFormat(const std::string& text)
{
    const std::string t = LowerText(text);
    for (const LutFormatEntry& e : LutFormats())
    {
        if (t == e.name || std::find(e.aliases.begin(), e.aliases.end(), t) != e.aliases.end())
        {
            return e.format;
        }
    }
    throw Exception("unknown LUT format '" + OneLine(text, 40) + "' (" + LutFormatChoices() + ")");
}

const char* LutExtension(LutFormat format)
{
    return FindLutFormat(format).extension;
}

LutFormat LutFormatForPath(const std::string& path, const std::string& format)
{
    const std::string name = std::filesystem::path(path).filename().string();
    const size_t dot = name.find_last_of('.');
    const std::string ext = dot == std::string::npos || dot == 0 ? "" : LowerText(name.substr(dot + 1));
    std::string extensions;
    for (const LutFormatEntry& e : LutFormats())
    {
        if (e.ownsExtension)
        {
            extensions += (extensions.empty() ? "." : ", .") + std::string(e.extension);
        }
    }
    if (!format.empty())
    {
        const LutFormat f = ParseLutFormat(format);
        if (ext != FindLutFormat(f).extension)
        {
            throw ParameterError("{out} '" + OneLine(path, 200) + "': a " + FindLutFormat(f).name +
                                 " LUT file is named ." + FindLutFormat(f).extension +
                                 " (hosts choose the reader by the extension)");
        }
        return f;
    }
    for (const LutFormatEntry& e : LutFormats())
    {
        if (e.ownsExtension && ext == e.extension)
        {
            return e.format;
        }
    }
    throw ParameterError("{out} '" + OneLine(path, 200) + "': " +
                         (ext.empty() ? std::string("no extension")
                                      : "the extension ." + OneLine(ext, 20) + " is no LUT format") +
                         " bandlight writes (" + extensions + "); or name the {format}");
}

PixelFunction PixelFunctionOf(const OCIO::ConstTransformRcPtr& exact)
{
    OCIO::ConstCPUProcessorRcPtr cpu =
        OCIO::Config::CreateRaw()->getProcessor(exact)->getOptimizedCPUProcessor(
            OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32, OCIO::OPTIMIZATION_NONE);
    return [cpu](float* rgb, size_t count)
    {
        OCIO::PackedImageDesc desc(rgb, long(count), 1, 3);
        cpu->apply(desc);
    };
}

std::vector<float> BakeLattice(const PixelFunction& exact, const ShaperSpec& requested, int size,
                               bool encodeOutput)
{
    const ShaperSpec shaper = requested.alignedTo(size);
    // Nodes → linear through OCIO's own shaper, so the lattice matches the
    // shaper the LUT file is applied with, bit for bit.
    return BakeOver(exact, shaper.transform(), size, encodeOutput);
}

std::vector<float> BakeLattice(const PixelFunction& exact, LutEncoding encoding, int size)
{
    return BakeOver(exact, LutEncodingTransform(encoding), size, true);
}

std::string TransformDescription(const OCIO::ConstTransformRcPtr& transform)
{
    std::string description;
    if (auto g = OCIO::DynamicPtrCast<const OCIO::GroupTransform>(transform))
    {
        const OCIO::FormatMetadata& md = g->getFormatMetadata();
        for (int i = 0; i < md.getNumChildrenElements(); ++i)
        {
            if (std::string(md.getChildElement(i).getElementName()) == OCIO::METADATA_DESCRIPTION)
            {
                description = md.getChildElement(i).getElementValue();
            }
        }
    }
    return description;
}

OCIO::GroupTransformRcPtr LatticeTransform(const OCIO::ConstTransformRcPtr& exact,
                                           const ShaperSpec& shaper, int size)
{
    return LatticeTransform(PixelFunctionOf(exact), shaper, size);
}

OCIO::GroupTransformRcPtr LatticeTransform(const PixelFunction& exact, const ShaperSpec& requested,
                                           int size)
{
    const ShaperSpec shaper = requested.alignedTo(size);
    // Shaper-encoded out as well as in: along any ray from black the exact
    // transform is then linear in the LUT's coordinates in the log segment
    // (and affine in the linear one), which is what tetrahedral
    // interpolation reproduces exactly; linear output would be exponential.
    const std::vector<float> lattice = BakeLattice(exact, shaper, size, true);
    OCIO::Lut3DTransformRcPtr lut = OCIO::Lut3DTransform::Create(unsigned(size));
    lut->setInterpolation(OCIO::INTERP_TETRAHEDRAL);
    lut->setFileOutputBitDepth(OCIO::BIT_DEPTH_F32);
    SetLattice(*lut, lattice, size);
    OCIO::GroupTransformRcPtr group = OCIO::GroupTransform::Create();
    if (OCIO::TransformRcPtr s = shaper.transform())
    {
        group->appendTransform(s);
    }
    group->appendTransform(lut);
    if (OCIO::TransformRcPtr s = shaper.transform())
    {
        s->setDirection(OCIO::TRANSFORM_DIR_INVERSE);
        group->appendTransform(s);
    }
    return group;
}

LutFiles WriteLut(const OCIO::ConstTransformRcPtr& exact, bool isMatrix, const LutOptions& o,
                  const std::string& path, OutputSet* outputs)
{
    if (FindLutFormat(o.format).writer == LutWriterKind::GROUP && isMatrix && !o.forceLattice &&
        o.encoding == LutEncoding::LINEAR)
    {
        LutFiles files;
        files.lut = path;
        OutputSet own;
        WriteGroup(AsGroup(exact), o.format, path, o.description, outputs ? *outputs : own);
        own.commit();
        return files;
    }
    LutOptions withDescription = o;
    if (withDescription.description.empty())
    {
        withDescription.description = TransformDescription(exact);
    }
    return WriteLut(PixelFunctionOf(exact), withDescription, path, outputs);
}

LutFiles WriteLut(const PixelFunction& exact, const LutOptions& requested, const std::string& path,
                  OutputSet* outputs)
{
    // The LUT and its companion shaper are one set: replaced together or not at all.
    OutputSet own;
    OutputSet& set = outputs ? *outputs : own;
    LutOptions o = requested;
    o.shaper = requested.shaper.alignedTo(requested.size);
    LutFiles files;
    files.lut = path;
    files.lattice = true;
    if (o.encoding != LutEncoding::LINEAR)
    {
        WriteEncodedLut(exact, o, path, set);
        own.commit();
        files.encoding = o.encoding;
        return files;
    }
    const LutFormatEntry& entry = FindLutFormat(o.format);
    if (entry.shaper == LutShaperRule::IN_FILE)
    {
        WriteGroup(LatticeTransform(exact, o.shaper, o.size), o.format, path, o.description, set);
        own.commit();
        return files;
    }
    if (entry.shaper == LutShaperRule::NONE_FOR_HDR)
    {
        // OCIO 2.1's Baker samples these formats' 1D pre-LUT uniformly over
        // the linear input range (resolve_cube, houdini: 4096 points 32 apart
        // over -0.0005..131072, so everything below 32 shares one segment)
        // or prints its input points with 6 decimals (cinespace: the points
        // below 1e-3 collapse): a log shaper for scene-linear HDR cannot be
        // carried. They are offered for display-referred [0, 1] data, where
        // no pre-LUT is needed.
        if (o.shaper.kind != ShaperSpec::Kind::NONE)
        {
            throw ParameterError(
                path + ": " + LutExtension(o.format) +
                " files carry their shaper as a 1D pre-LUT that OpenColorIO 2.1 samples too "
                "coarsely for scene-linear HDR; use {shaper=}none for display-referred [0, 1] "
                "data, {encoding=}acescct (or acescc) for a LUT that takes and returns "
                "log-encoded values, or {format=}cube (or spi3d, 3dl) with its companion shaper "
                "CLF");
        }
        BakeThroughOcio(BakeLattice(exact, o.shaper, o.size, false), o, path, set);
        own.commit();
        return files;
    }
    files.outputEncoded = o.shaper.kind != ShaperSpec::Kind::NONE;
    if (files.outputEncoded)
    {
        // A host that reads this file alone must learn from it that it is
        // only the middle of a chain (where the format holds a comment).
        const std::string name = ShaperCompanionPath(path);
        o.description += std::string(o.description.empty() ? "" : " ") +
                         "Shaper-encoded in and out: apply " +
                         name.substr(name.find_last_of('/') + 1) +
                         " before this LUT and its inverse after; alone, this file is not "
                         "the transform.";
    }
    // Bake into memory first, so a failure leaves no file behind.
    const std::vector<float> lattice = BakeLattice(exact, o.shaper, o.size, files.outputEncoded);
    if (entry.writer == LutWriterKind::OWN_SPI3D)
    {
        WriteSpi3d(lattice, o.size, path, set);
    }
    else
    {
        BakeThroughOcio(lattice, o, path, set);
    }
    if (OCIO::TransformRcPtr s = o.shaper.transform())
    {
        files.shaper = ShaperCompanionPath(path);
        OCIO::GroupTransformRcPtr g = OCIO::GroupTransform::Create();
        g->appendTransform(s);
        WriteGroup(g, LutFormat::CLF, files.shaper, "bandlight shaper, " + o.shaper.describe(),
                   set);
    }
    own.commit();
    return files;
}

OCIO::GroupTransformRcPtr ReadLutFiles(const LutFiles& files)
{
    OCIO::GroupTransformRcPtr chain = OCIO::GroupTransform::Create();
    if (!files.shaper.empty())
    {
        OCIO::FileTransformRcPtr s = OCIO::FileTransform::Create();
        s->setSrc(files.shaper.c_str());
        chain->appendTransform(s);
    }
    OCIO::FileTransformRcPtr l = OCIO::FileTransform::Create();
    l->setSrc(files.lut.c_str());
    l->setInterpolation(OCIO::INTERP_TETRAHEDRAL);
    chain->appendTransform(l);
    if (files.outputEncoded && !files.shaper.empty())
    {
        OCIO::FileTransformRcPtr inv = OCIO::FileTransform::Create();
        inv->setSrc(files.shaper.c_str());
        inv->setDirection(OCIO::TRANSFORM_DIR_INVERSE);
        chain->appendTransform(inv);
    }
    return chain;
}

}  // namespace bandlight
