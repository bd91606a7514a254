// SPDX-License-Identifier: BSD-3-Clause
// `accuracy`'s request resolved: its outputs checked, then the lights, plates,
// methods, sets and exposures it measures.
#include "measure/AccuracyRun.h"

#include <algorithm>
#include <cmath>

#include "farm/Frames.h"
#include "farm/OutputPaths.h"
#include "report/Gnuplot.h"
#include "plugin/OcioTransforms.h"
#include "spectral/Exception.h"

namespace bandlight::jobs
{

namespace
{
namespace OCIO = OCIO_NAMESPACE;

/// Every output before the measurement: a run of minutes must not fail at
/// its end for a folder that does not exist.
void CheckOutputs(const AccuracyRequest& r)
{
    OutputPlan plan;
    if (!r.json.empty())
    {
        plan.file("{json}", r.json);
    }
    if (!r.plot.empty())
    {
        CheckPlotPath(r.plot);
        plan.file("{plot}", r.plot);
    }
    if (!r.heatmaps.empty())
    {
        plan.folder("{heatmaps}", r.heatmaps);
    }
    for (const std::string& image : r.images)
    {
        CheckImageInput(image);
        plan.input(image);
    }
    plan.check();
}

/// The working space, the observer and the pairs of lights: those given,
/// the change of light an image was given for, or the defaults.
void ChooseLights(const AccuracyRequest& r, AccuracyOptions& options)
{
    options.workingSpace = r.workingSpace;
    FindRgbSpace(r.workingSpace);
    options.observer = ParseObserver(r.observer);
    if (!r.images.empty() && r.lights.empty())
    {
        if (r.imageOptions.from.spectrum.empty() || r.imageOptions.to.spectrum.empty())
        {
            throw ParameterError(
                "{image} is measured for one change of light: give {src=}S1 and "
                "{dst=}S2 (or {illuminants})");
        }
        options.lights = {r.imageOptions.from, r.imageOptions.to};
        options.forwardOnly = true;  // the change of light the image was given for
    }
    if (!r.heatmaps.empty() && r.images.empty())
    {
        throw ParameterError("{heatmaps} maps the error over a spectral image: give {image}");
    }
    if (!r.lights.empty())
    {
        options.lights = r.lights;
        if (options.lights.size() < 2)
        {
            throw Exception("accuracy needs at least two illuminants");
        }
    }
}

/// The plate conventions, the camera that shoots them (with its methods
/// when none are named) and the methods, the reference always among them.
void ChoosePlatesAndMethods(const AccuracyRequest& r, Reporter& reporter, AccuracyResult& result)
{
    AccuracyOptions& options = result.options;
    if (!r.methods.empty())
    {
        options.methods = r.methods;
    }
    options.plates = r.plates.all();
    options.camera = r.plates.loadCamera();
    result.cameraFile = r.plates.camera;
    if (options.camera)
    {
        const Light idt = r.plates.idt(reporter);
        options.idtLightName = idt.name;
        options.idtLight = idt.spectrum;
        if (r.methods.empty())
        {
            const std::vector<std::string>& camera = CameraMethodNames();
            options.methods.insert(options.methods.end(), camera.begin(), camera.end());
        }
    }
    if (std::find(options.methods.begin(), options.methods.end(), ReferenceMethodName()) ==
        options.methods.end())
    {
        options.methods.push_back(ReferenceMethodName());
    }
    for (const std::string& m : options.methods)
    {
        RequireCamera(ParseMethod(m), bool(options.camera));
    }
}


/// The sets of remittances: the default sets (unless left out), the files
/// given, and each image's pixels.
void ChooseSets(const AccuracyRequest& r, Reporter& reporter, AccuracyOptions& options)
{
    if (!r.defaultSets)
    {
        options.sets.clear();
    }
    for (const ReflectanceSet& s : r.sets)
    {
        options.sets.push_back(s);
    }
    const SpectralOptions imageOptions = AccuracyImageOptions(r);
    for (const std::string& image : r.images)
    {
        options.sets.push_back(
            ReflectanceSetFromSpectralImage(image, imageOptions, kMaxImageSamples, reporter));
    }
    if (options.sets.empty())
    {
        throw ParameterError(
            "no reflectance sets to measure: give {reflectances}, or keep the default sets");
    }
}

void ChooseExposures(const AccuracyRequest& r, AccuracyOptions& options)
{
    if (r.exposures.empty())
    {
        return;
    }
    for (const double k : r.exposures)
    {
        if (!(k > 0.0) || !std::isfinite(k))
        {
            throw ParameterError("{exposures} must be positive and finite");
        }
    }
    options.exposures = r.exposures;
}

/// The shipped form: the OCIO processor of the transform a config's look
/// holds (guard + matrix, or shaper + 3D LUT + inverse shaper).
ShippedFactory ShippedForms(const AccuracyOptions& options, int lutSize)
{
    const RgbSpace& working = FindRgbSpace(options.workingSpace);
    const Observer observer = options.observer;
    return [&working, observer, lutSize](const Light& from, const Light& to,
                                         const MethodSpec& method) -> PixelBatch
    {
        const OCIO::ConstCPUProcessorRcPtr cpu =
            OCIO::Config::CreateRaw()
                ->getProcessor(
                    IlluminantChangeTransform(from, to, method, working, observer, lutSize))
                ->getOptimizedCPUProcessor(OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32,
                                           OCIO::OPTIMIZATION_DEFAULT);
        return [cpu](float* rgb, size_t n)
        {
            OCIO::PackedImageDesc desc(rgb, long(n), 1, 3);
            cpu->apply(desc);
        };
    };
}

}  // namespace

SpectralOptions AccuracyImageOptions(const AccuracyRequest& r)
{
    SpectralOptions imageOptions = r.imageOptions;
    imageOptions.workingSpace = r.workingSpace;
    imageOptions.observer = r.observer;
    return imageOptions;
}

void ResolveAccuracyRequest(const AccuracyRequest& r, Reporter& reporter, AccuracyResult& result)
{
    CheckOutputs(r);
    AccuracyOptions& options = result.options;
    options = DefaultAccuracyOptions();
    ChooseLights(r, options);
    ChoosePlatesAndMethods(r, reporter, result);
    ChooseSets(r, reporter, options);
    ChooseExposures(r, options);
    const int lutSize = CheckedLutSize(r.lutSize, "lut_size");
    if (!r.plot.empty() && !r.cost)
    {
        throw ParameterError("{plot} needs the cost measurement (drop {no_cost})");
    }
    if (!r.idealOnly)
    {
        options.shipped = ShippedForms(options, lutSize);
    }
}

ReflectanceSet ReflectanceSetFromFile(const std::string& path)
{
    return {path, ReadSpectraFile(path)};
}

}  // namespace bandlight::jobs
