// SPDX-License-Identifier: BSD-3-Clause
#include "jobs/WallJob.h"

#include "camera/IdtFit.h"
#include "camera/Wall.h"
#include "plugin/OcioTransforms.h"
#include "plugin/WallConfig.h"
#include "requests/Inputs.h"
#include "spectral/AtomicFile.h"
#include "spectral/CameraFile.h"
#include "spectral/Exception.h"
#include "transforms/Plates.h"

namespace bandlight::jobs
{

namespace
{

/// The white balances (in the order given), then the depicted lights of
/// defaults::WALL_DEPICTED_K that are not among them. Two white balances
/// whose names make one context value are refused.
std::vector<Light> DepictedLights(const WallRequest& r, Reporter& reporter)
{
    std::vector<Light> lights;
    for (const std::string& text : r.whiteBalances)
    {
        Light l = ResolveIdtLight(text, reporter);
        for (const Light& other : lights)
        {
            if (SafeName(other.name) == SafeName(l.name))
            {
                throw ParameterError("the white balances '" + other.name + "' and '" + l.name +
                                     "' would both be " +
                                     std::string(defaults::WALL_CONTEXT_VARIABLE) + "=" +
                                     SafeName(l.name) + " ({white_balance}): give each once");
            }
        }
        lights.push_back(std::move(l));
    }
    for (const double kelvin : defaults::WALL_DEPICTED_K)
    {
        const std::string name = KelvinName(kelvin);
        bool known = false;
        for (const Light& l : lights)
        {
            known = known || l.name == name;
        }
        if (!known)
        {
            lights.push_back({name, IdtLightForCct(kelvin)});
        }
    }
    return lights;
}

/// How the config carries the drive: RGB, RGBA, or not at all (why, in the
/// report and on stderr).
void ConfigForm(size_t emitters, WallResult& result, Reporter& reporter)
{
    const std::string n = std::to_string(emitters);
    if (emitters == 3)
    {
        result.drives = "RGB";
        return;
    }
    if (emitters == 4)
    {
        result.drives = "RGBA";
        result.configNote =
            "4 emitters: the config's drive spaces carry the fourth emitter's drive in alpha "
            "(4x4 matrices, written as OCIO CTF files since CLF holds no alpha): render them to "
            "RGBA images.";
    }
    else
    {
        result.configNote =
            n +
            " emitters: OpenColorIO images have at most four channels (RGBA), so the config "
            "holds no in-frustum transform and no pre-correction for this wall: a transform of "
            "four of its " +
            n + " drives would light it wrongly. The " + n + "x3 drive matrix and the " + n + "x" +
            n +
            " pre-correction are in report.json; the IDT and the post-camera look are in the "
            "config.";
    }
    reporter.note(result.configNote);
}

/// The config (its files) and report.json, committed together.
void WriteOutputs(const WallRequest& r, WallResult& result)
{
    WallConfigOptions o;
    o.workingSpace = result.workingSpace;
    o.contentSpace = result.contentSpace;
    o.camera = result.camera;
    o.variable = result.contextVariable;
    o.description = DescribeWallConfig(result);
    for (const WallBalance& b : result.balances)
    {
        const WallDescriptions d = DescribeWallBalance(result, b);
        WallConfigBalance c;
        c.key = b.key;
        c.idt = b.idt.rawToWorking();
        if (!result.drives.empty())
        {
            c.inFrustum = b.inFrustum.drive;
            c.preCorrection = b.preCorrection;
        }
        c.post = b.post;
        // The op's own OCIO form, as every non-linear look of a config.
        c.postNonLinear = IlluminantChangeTransform(
            b.postFrom, b.postTo, b.postMethod, FindRgbSpace(result.workingSpace),
            ParseObserver(r.observer), defaults::CONFIG_LUT_SIZE);
        c.postNonLinearDescription = d.postRootPolynomial;
        c.idtDescription = d.idt;
        c.inFrustumDescription = d.inFrustum;
        c.preDescription = d.preCorrection;
        c.postDescription = d.postCamera;
        o.balances.push_back(std::move(c));
    }
    const ConfigPackage package = BuildWallConfig(o);
    OutputSet outputs;
    WriteConfigPackage(package, r.out, &outputs);
    const std::string document = WallDocument(result);
    outputs.write(r.out + "/report.json", [&](std::ostream& os) { os << document << "\n"; });
    outputs.commit();
    result.written = {r.out + "/config.ocio", r.out + "/report.json"};
    for (const auto& file : package.lutFiles)
    {
        result.written.push_back(r.out + "/" + file.first);
    }
}

}  // namespace

WallResult MakeWall(const WallRequest& r, Reporter& reporter)
{
    CheckWallRequest(r);
    const std::vector<NamedSpectrum> emitters = ReadEmitters(r, reporter);
    const SpectralCamera camera(ReadCameraFile(r.camera));
    const std::vector<Light> depicted = DepictedLights(r, reporter);
    const std::vector<NamedSpectrum> training =
        r.training.empty() ? Rawtoaces190() : ResolveReflectances(r.training, reporter);
    const std::vector<NamedSpectrum> test = ResolveReflectances(r.testSet, reporter);

    WallResult result;
    result.camera = camera.name();
    result.emitters = r.emitters;
    result.contentSpace = FindRgbSpace(r.contentSpace).name;
    result.workingSpace = FindRgbSpace(r.workingSpace).name;
    const AdaptationMethod adaptation = ParsePlates("balanced", r.adaptation).adaptation;
    result.adaptation = AdaptationName(adaptation);
    result.trainingName = r.training.empty() ? "rawtoaces 190" : r.training;
    result.trainingCount = int(training.size());
    result.testName = r.testSet;
    result.testCount = int(test.size());
    for (const Light& l : depicted)
    {
        result.depicted.push_back(l.name);
    }
    ConfigForm(emitters.size(), result, reporter);

    WallSetup setup{camera,
                    {},
                    RemittancesOnGrid({}),
                    FindRgbSpace(r.contentSpace),
                    FindRgbSpace(r.workingSpace),
                    adaptation,
                    ParseObserver(r.observer),
                    training,
                    {{result.trainingName, RemittancesOnGrid(training)},
                     {result.testName, RemittancesOnGrid(test)}},
                    depicted,
                    r.whiteBalances.size(),
                    {}};
    setup.emitters.resize(SurfaceRenderer::kSamples, Eigen::Index(emitters.size()));
    for (size_t k = 0; k < emitters.size(); ++k)
    {
        setup.names.push_back(emitters[k].name);
        setup.emitters.col(Eigen::Index(k)) = EmissionOnGrid(emitters[k].spectrum);
        setup.emitterSpectra.push_back(emitters[k].spectrum);
    }
    for (size_t b = 0; b < setup.balances; ++b)
    {
        result.balances.push_back(SolveWallBalance(setup, b));
    }
    WriteOutputs(r, result);
    return result;
}

}  // namespace bandlight::jobs
