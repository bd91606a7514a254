// SPDX-License-Identifier: BSD-3-Clause
// The method registry: every illuminant-change method in one table, and the
// name parsing, descriptions and default lists read from it.
#include "transforms/Methods.h"

#include <algorithm>
#include <cctype>
#include <sstream>

#include "spectral/Exception.h"
#include "spectral/TextFile.h"
#include "transforms/detail/MethodFits.h"

namespace bandlight
{

// The entries of the methods in files of their own (transforms/methods/List.h).
#define BANDLIGHT_METHOD(KEY, MAKE) MethodEntry MAKE(ChangeMethod key);
#include "transforms/methods/List.h"
#undef BANDLIGHT_METHOD

namespace
{

/// A method with one name.
template <ChangeMethod M>
bool ParseExact(const std::string& name, MethodSpec& spec, const char* canonical)
{
    if (name != canonical)
    {
        return false;
    }
    spec.method = M;
    return true;
}

#define BANDLIGHT_EXACT(M, NAME) \
    [](const std::string& n, MethodSpec& s) { return ParseExact<ChangeMethod::M>(n, s, NAME); }

/// rootpoly / rootpoly2 / rootpoly3, with `suffix` ("" or "-camera").
bool ParseRootPoly(const std::string& n, MethodSpec& m, ChangeMethod method,
                   const std::string& suffix)
{
    for (const int degree : {2, 3})
    {
        const std::string plain = "rootpoly" + suffix;
        const std::string numbered = "rootpoly" + std::to_string(degree) + suffix;
        if (n == numbered || (degree == 2 && n == plain))
        {
            m.method = method;
            m.degree = degree;
            m.name = degree == 3 ? numbered : plain;
            return true;
        }
    }
    return false;
}

/// band3, bandN, bandN-wp, bands380-480-560-780[-wp].
bool ParseBand(const std::string& n, MethodSpec& m)
{
    if (n.rfind("bands", 0) == 0 && n.size() > 5 && std::isdigit((unsigned char)n[5]))
    {
        // Any band set, written into the name so it can name looks:
        // "bands380-480-560-780" (edges in nm), "-wp" for the white-preserving form.
        std::string edges = n.substr(5);
        m.method = ChangeMethod::BAND;
        if (edges.size() > 3 && edges.compare(edges.size() - 3, 3, "-wp") == 0)
        {
            m.method = ChangeMethod::BAND_WP;
            m.whitePreserving = true;
            edges = edges.substr(0, edges.size() - 3);
        }
        std::replace(edges.begin(), edges.end(), '-', ',');
        m.bands = BandSet::Parse(edges);
        if (m.bands.size() < 3)
        {
            throw Exception("method '" + n + "': a band set needs at least three bands");
        }
        return true;
    }
    if (n.rfind("band", 0) != 0)
    {
        return false;
    }
    std::string rest = n.substr(4);
    m.method = ChangeMethod::BAND;
    const size_t dash = rest.find("-wp");
    if (dash != std::string::npos && dash + 3 == rest.size())
    {
        m.method = ChangeMethod::BAND_WP;
        m.whitePreserving = true;
        rest = rest.substr(0, dash);
    }
    const bool digits =
        !rest.empty() && rest.size() <= 3 && std::all_of(rest.begin(), rest.end(), ::isdigit);
    const int count = digits ? std::stoi(rest) : 0;
    if (count < 3 || count > 300)
    {
        throw Exception("unknown method '" + n +
                        "': band methods are bandN or bandN-wp with 3 <= N <= 300");
    }
    m.bands = count == 3 ? BandSet::Lecture() : BandSet::Equal(size_t(count), 400.0, 700.0);
    return true;
}

std::string DescribeBand(const MethodSpec& m)
{
    std::ostringstream s;
    if (!m.whitePreserving)
    {
        s << "The lecture's " << m.bands.size() << "-band model: each band (" << m.bands.describe()
          << " nm) scaled by the ratio of the lights' band means, white luminance kept; "
             "not exact on white, wrong where lights and surfaces are spiky.";
    }
    else
    {
        s << m.bands.size() << "-band model (" << m.bands.describe()
          << " nm) with ratios from the band coordinates of the two whites: exact on white, "
             "a diagonal in band space for colours.";
    }
    return s.str();
}

#define BANDLIGHT_TEXT(TEXT) [](const MethodSpec&) -> std::string { return TEXT; }

/// An entry with its name, exactness, parser and description; the rest is
/// set field by field below.
MethodEntry Entry(ChangeMethod method, const char* syntax, MethodExactness exactness,
                  bool (*parse)(const std::string&, MethodSpec&),
                  std::string (*describe)(const MethodSpec&))
{
    MethodEntry e;
    e.methods = {method};
    e.syntax = syntax;
    e.exactness = exactness;
    e.parse = parse;
    e.describe = describe;
    return e;
}

const std::vector<NamedSpectrum>& Fit3x3Training()
{
    return TrainingSet().samples;
}

std::string DescribeRootPoly(const MethodSpec& m)
{
    return std::string("Root-polynomial regression of degree ") + (m.degree == 3 ? "3" : "2") +
           " (Finlayson, Mackiewicz & Hurlbert 2015) fitted in CIELAB on 205 measured "
           "remittances (rawtoaces' 190 and the 15 TCS), exact on white and exposure "
           "invariant: not linear, baked into a 3D LUT with a log2 shaper.";
}

std::string DescribeRootPolyCamera(const MethodSpec& m)
{
    return std::string("For plates made with one fixed ") + m.idtLightName + " IDT of camera " +
           (m.camera ? m.camera->name() : std::string("(none)")) +
           " and white-balance gains: that IDT inverted, then a root polynomial of degree " +
           (m.degree == 3 ? "3" : "2") +
           " fitted from the camera's record under the source light to the target (205 "
           "measured remittances): not linear, baked into a 3D LUT with a log2 shaper.";
}

/// The methods that are one 3×3: the von Kries family, the band model and
/// the fitted matrices.
void AddMatrixMethods(std::vector<MethodEntry>& all)
{
    using K = MethodExactness;

    MethodEntry none = Entry(ChangeMethod::NONE, "none", K::LINEAR, BANDLIGHT_EXACT(NONE, "none"),
                             BANDLIGHT_TEXT("Identity: the image is left as it is (the baseline "
                                            "every method is compared with)."));
    none.litMatrix = &detail::IdentityFit;
    none.identity = true;
    none.configDefaults = {"none"};
    none.accuracyDefaults = {"none"};
    all.push_back(none);

    MethodEntry vonKries =
        Entry(ChangeMethod::VON_KRIES, "vonkries", K::LINEAR, BANDLIGHT_EXACT(VON_KRIES, "vonkries"),
              BANDLIGHT_TEXT("von Kries scaling of XYZ by the ratio of the two white points: "
                             "exact on white, the crudest chromatic adaptation for colours."));
    vonKries.litMatrix = &detail::AdaptationFit;
    vonKries.adaptation = AdaptationMethod::XYZ_SCALING;
    vonKries.configDefaults = {"vonkries"};
    vonKries.accuracyDefaults = {"vonkries"};
    all.push_back(vonKries);

    MethodEntry bradford =
        Entry(ChangeMethod::BRADFORD, "bradford", K::LINEAR, BANDLIGHT_EXACT(BRADFORD, "bradford"),
              BANDLIGHT_TEXT("Bradford chromatic adaptation (linearised): exact on white; the "
                             "usual white-balance matrix, good for broadband lights."));
    bradford.litMatrix = &detail::AdaptationFit;
    bradford.adaptation = AdaptationMethod::BRADFORD;
    bradford.configDefaults = {"bradford"};
    bradford.accuracyDefaults = {"bradford"};
    bradford.lightGroupDefaults = {"bradford"};
    bradford.packageDefaults = {"bradford"};
    bradford.packageRank = 2;
    all.push_back(bradford);

    MethodEntry cat02 =
        Entry(ChangeMethod::CAT02, "cat02", K::LINEAR, BANDLIGHT_EXACT(CAT02, "cat02"),
              BANDLIGHT_TEXT("CAT02 chromatic adaptation (CIECAM02): exact on white; similar to "
                             "Bradford."));
    cat02.litMatrix = &detail::AdaptationFit;
    cat02.adaptation = AdaptationMethod::CAT02;
    cat02.configDefaults = {"cat02"};
    cat02.accuracyDefaults = {"cat02"};
    cat02.lightGroupDefaults = {"cat02"};
    all.push_back(cat02);

    MethodEntry band = Entry(ChangeMethod::BAND,
                             "band3, band3-wp, bandN, bandN-wp, bandsE0-E1-...-En[-wp]", K::LINEAR,
                             &ParseBand, &DescribeBand);
    band.methods.push_back(ChangeMethod::BAND_WP);
    band.litMatrix = &detail::BandFit;
    band.usesBands = true;
    band.configDefaults = {"band3", "band3-wp"};
    band.accuracyDefaults = {"band3", "band3-wp", "band6", "band6-wp"};
    band.packageDefaults = {"band3"};
    band.packageRank = 1;
    all.push_back(band);

    MethodEntry fit3x3 =
        Entry(ChangeMethod::FIT3X3, "fit3x3", K::LINEAR, BANDLIGHT_EXACT(FIT3X3, "fit3x3"),
              BANDLIGHT_TEXT("3x3 fitted by least squares on training remittances (TCS01-08 and "
                             "100 smooth random ones), exact on white."));
    fit3x3.litMatrix = &detail::LeastSquaresFit;
    fit3x3.defaultTraining = &Fit3x3Training;
    fit3x3.takesTraining = true;
    fit3x3.accuracyDefaults = {"fit3x3"};
    fit3x3.lightGroupDefaults = {"fit3x3"};
    all.push_back(fit3x3);

    MethodEntry prefilter =
        Entry(ChangeMethod::PREFILTER, "prefilter", K::LINEAR,
              BANDLIGHT_EXACT(PREFILTER, "prefilter"),
              BANDLIGHT_TEXT("von Kries in the sharpened primaries of spectral prefiltering (Ward "
                             "& Eydelberg-Vileshin 2002, Sharp sensors): exact on white."));
    prefilter.litMatrix = &detail::AdaptationFit;
    prefilter.adaptation = AdaptationMethod::SHARP;
    prefilter.accuracyDefaults = {"prefilter"};
    all.push_back(prefilter);

    MethodEntry metamer =
        Entry(ChangeMethod::METAMER, "metamer", K::LINEAR, BANDLIGHT_EXACT(METAMER, "metamer"),
              BANDLIGHT_TEXT("The smoothest remittance that reproduces the pixel under the first "
                             "light, re-lit under the second: one 3x3, exact on white."));
    metamer.litMatrix = &detail::MetamerFit;
    metamer.accuracyDefaults = {"metamer"};
    all.push_back(metamer);
}

/// The methods that are not one 3×3, and the spectral reference.
void AddPixelMethods(std::vector<MethodEntry>& all)
{
    using K = MethodExactness;

    MethodEntry upsample =
        Entry(ChangeMethod::UPSAMPLE, "upsample", K::NONLINEAR, BANDLIGHT_EXACT(UPSAMPLE, "upsample"),
              BANDLIGHT_TEXT("A smooth remittance in [0, 1] fitted to the pixel (Jakob & Hanika "
                             "2019 sigmoid polynomial), re-lit spectrally: not linear, baked into "
                             "a 3D LUT with a log2 shaper."));
    upsample.makeOp = &detail::UpsampleOp;
    upsample.sharedPerLight = &detail::UpsampleShared;
    upsample.directForm = DirectForm::DIRECT_FIT;
    upsample.accuracyDefaults = {"upsample"};
    all.push_back(upsample);

    MethodEntry rootpoly = Entry(
        ChangeMethod::ROOTPOLY, "rootpoly, rootpoly3", K::NONLINEAR,
        [](const std::string& n, MethodSpec& s)
        { return ParseRootPoly(n, s, ChangeMethod::ROOTPOLY, ""); },
        &DescribeRootPoly);
    rootpoly.makeOp = &detail::RootPolyOp;
    rootpoly.native = true;
    rootpoly.defaultTraining = &RootPolynomialTraining;
    rootpoly.takesTraining = true;
    rootpoly.directForm = DirectForm::NATIVE;
    rootpoly.accuracyDefaults = {"rootpoly", "rootpoly3"};
    rootpoly.lightGroupDefaults = {"rootpoly"};
    all.push_back(rootpoly);

    MethodEntry rootpolyCamera = Entry(
        ChangeMethod::ROOTPOLY_CAMERA, "rootpoly-camera, rootpoly3-camera", K::NONLINEAR,
        [](const std::string& n, MethodSpec& s)
        { return ParseRootPoly(n, s, ChangeMethod::ROOTPOLY_CAMERA, "-camera"); },
        &DescribeRootPolyCamera);
    rootpolyCamera.makeOp = &detail::RootPolyCameraOp;
    rootpolyCamera.native = true;
    rootpolyCamera.defaultTraining = &RootPolynomialTraining;
    rootpolyCamera.needsCamera = true;
    rootpolyCamera.directForm = DirectForm::NATIVE;
    rootpolyCamera.cameraDefaults = {"rootpoly-camera"};
    rootpolyCamera.wallComparisonDefaults = {"rootpoly-camera"};
    all.push_back(rootpolyCamera);

}

/// The exact spectral answer, last.
void AddReference(std::vector<MethodEntry>& all)
{
    MethodEntry spectral = Entry(ChangeMethod::SPECTRAL, "spectral", MethodExactness::REFERENCE,
                                 BANDLIGHT_EXACT(SPECTRAL, "spectral"),
                                 BANDLIGHT_TEXT("The exact spectral answer for known remittances: "
                                                "the reference."));
    all.push_back(spectral);
}

std::vector<MethodEntry> MakeMethods()
{
    std::vector<MethodEntry> all;
    AddMatrixMethods(all);
    AddPixelMethods(all);
#define BANDLIGHT_METHOD(KEY, MAKE) all.push_back(MAKE(ChangeMethod::KEY));
#include "transforms/methods/List.h"
#undef BANDLIGHT_METHOD
    AddReference(all);
    return all;
}

std::vector<std::string> Collect(std::vector<const char*> MethodEntry::*list)
{
    std::vector<std::string> names;
    for (const MethodEntry& e : Methods())
    {
        names.insert(names.end(), (e.*list).begin(), (e.*list).end());
    }
    return names;
}

}  // namespace

const std::vector<MethodEntry>& Methods()
{
    static const std::vector<MethodEntry> methods = MakeMethods();
    return methods;
}

const MethodEntry& FindMethod(ChangeMethod method)
{
    for (const MethodEntry& e : Methods())
    {
        if (std::find(e.methods.begin(), e.methods.end(), method) != e.methods.end())
        {
            return e;
        }
    }
    throw Exception("method " + std::to_string(int(method)) + " is not in the registry");
}

const MethodEntry& MethodSpec::entry() const
{
    return FindMethod(method);
}

bool MethodSpec::usesBands() const
{
    return entry().usesBands;
}

bool MethodSpec::isLinear() const noexcept
{
    for (const MethodEntry& e : Methods())
    {
        if (std::find(e.methods.begin(), e.methods.end(), method) != e.methods.end())
        {
            return e.exactness == MethodExactness::LINEAR;
        }
    }
    return false;
}

const MethodEntry& FindMethod(const std::string& name)
{
    return FindMethod(ParseMethod(name).method);
}

std::string ReferenceMethodName()
{
    for (const MethodEntry& e : Methods())
    {
        if (e.isReference())
        {
            return e.syntax;
        }
    }
    throw Exception("the method registry has no reference method");
}

void RequireCamera(const MethodSpec& method, bool haveCamera)
{
    if (method.entry().needsCamera && !haveCamera)
    {
        throw ParameterError("method '" + method.name +
                             "' needs the camera that shot the plates ({camera=}FILE)");
    }
}

void RequireCamera(const MethodSpec& method)
{
    RequireCamera(method, bool(method.camera));
}

MethodSpec WithCamera(MethodSpec method, const std::shared_ptr<const SpectralCamera>& camera,
                      const Light& idtLight)
{
    method.camera = camera;
    if (method.entry().needsCamera)
    {
        RequireCamera(method);
        method.idtLightName = idtLight.name;
        method.idtLight = idtLight.spectrum;
    }
    return method;
}

const std::vector<NamedSpectrum>& TrainingOf(const MethodSpec& method)
{
    static const std::vector<NamedSpectrum> none;
    if (!method.training.empty())
    {
        return method.training;
    }
    const MethodEntry& e = method.entry();
    return e.defaultTraining ? e.defaultTraining() : none;
}

MethodSpec ParseMethod(const std::string& name)
{
    const std::string n = ToLower(name);
    MethodSpec m;
    m.name = n;
    for (const MethodEntry& e : Methods())
    {
        if (e.parse(n, m))
        {
            if (e.methods.size() == 1)
            {
                m.method = e.methods.front();  // an entry of one method: its key
            }
            return m;
        }
    }
    std::string choices;
    for (const MethodEntry& e : Methods())
    {
        choices += (choices.empty() ? "" : ", ") + std::string(e.syntax);
    }
    throw Exception("unknown method '" + name + "' (" + choices + ")");
}

const std::vector<std::string>& LinearMethodNames()
{
    static const std::vector<std::string> names = Collect(&MethodEntry::configDefaults);
    return names;
}

const std::vector<std::string>& AllMethodNames()
{
    static const std::vector<std::string> names = Collect(&MethodEntry::accuracyDefaults);
    return names;
}

const std::vector<std::string>& CameraMethodNames()
{
    static const std::vector<std::string> names = Collect(&MethodEntry::cameraDefaults);
    return names;
}

const std::vector<std::string>& LightGroupMethodNames()
{
    static const std::vector<std::string> names = Collect(&MethodEntry::lightGroupDefaults);
    return names;
}

const std::string& WallLookMethodName()
{
    static const std::string name = Collect(&MethodEntry::wallLookDefaults).at(0);
    return name;
}

const std::string& WallComparisonMethodName()
{
    static const std::string name = Collect(&MethodEntry::wallComparisonDefaults).at(0);
    return name;
}

const char* MethodExactnessName(MethodExactness exactness)
{
    switch (exactness)
    {
        case MethodExactness::LINEAR:
            return "linear";
        case MethodExactness::NONLINEAR:
            return "non-linear";
        case MethodExactness::REFERENCE:
            return "reference";
    }
    return "?";
}

const std::vector<std::string>& PackageMethodNames()
{
    static const std::vector<std::string> names = []
    {
        std::vector<const MethodEntry*> ranked;
        for (const MethodEntry& e : Methods())
        {
            if (!e.packageDefaults.empty())
            {
                ranked.push_back(&e);
            }
        }
        std::stable_sort(ranked.begin(), ranked.end(), [](const MethodEntry* a, const MethodEntry* b)
                         { return a->packageRank < b->packageRank; });
        std::vector<std::string> out;
        for (const MethodEntry* e : ranked)
        {
            out.insert(out.end(), e->packageDefaults.begin(), e->packageDefaults.end());
        }
        return out;
    }();
    return names;
}

std::string MethodSyntax()
{
    std::string out;
    for (const MethodEntry& e : Methods())
    {
        if (e.isReference())
        {
            continue;  // the reference, not an image method
        }
        out += (out.empty() ? "" : ", ") + std::string(e.syntax) +
               (e.needsCamera ? " (with {camera})" : "");
    }
    return out;
}

std::string DescribeMethod(const MethodSpec& m)
{
    return FindMethod(m.method).describe(m);
}

}  // namespace bandlight
