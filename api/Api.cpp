// SPDX-License-Identifier: BSD-3-Clause
// The public API (include/bandlight/bandlight.h): each entry point fills the
// request of its verb from the public types and calls it, as the command's
// and the Python module's faces do. Nothing is resolved or checked here
// that the requests do not already resolve and check for every face.
#include <bandlight/bandlight.h>

#include "jobs/ApplyJob.h"
#include "jobs/ConfigJob.h"
#include "jobs/LutJob.h"
#include "jobs/MethodsJob.h"
#include "plugin/OcioTransforms.h"
#include "requests/Inputs.h"
#include "spectral/CieData.h"
#include "transforms/Version.h"

namespace bandlight
{

namespace
{

/// `value` when given, else `fallback` (the request's own default).
std::string Given(const std::string& value, const std::string& fallback)
{
    return value.empty() ? fallback : value;
}

jobs::PlatesRequest PlatesOf(const std::string& plates, const std::string& adaptation,
                             const std::string& camera = "", const std::string& idtLight = "")
{
    jobs::PlatesRequest p;
    p.plates = Given(plates, p.plates);
    p.adaptation = Given(adaptation, p.adaptation);
    p.camera = camera;
    p.idtLight = Given(idtLight, p.idtLight);
    return p;
}

jobs::RelightRequest RelightOf(const ChangeOfLight& change)
{
    jobs::RelightRequest r;
    r.src = jobs::ResolveIlluminant(change.from);
    r.dst = jobs::ResolveIlluminant(change.to);
    r.method = Given(change.method, r.method);
    r.workingSpace = Given(change.workingSpace, r.workingSpace);
    r.observer = Given(change.observer, r.observer);
    r.plates = PlatesOf(change.plates, change.adaptation, change.camera, change.idtLight);
    if (!change.training.empty())
    {
        r.training = jobs::ResolveReflectances(change.training);
    }
    return r;
}

WrittenImages Written(const jobs::ApplyResult& result)
{
    WrittenImages w;
    w.applied = result.applied;
    w.frames = result.frames;
    w.seconds = result.seconds;
    w.native = result.native;
    return w;
}

}  // namespace

std::string Version()
{
    return BANDLIGHT_VERSION;
}

std::vector<MethodInfo> ListMethods()
{
    return jobs::ListMethods();
}

OCIO_NAMESPACE::ConstTransformRcPtr MakeTransform(const ChangeOfLight& change)
{
    const jobs::RelightRequest r = RelightOf(change);
    return IlluminantChangeTransform(r.src, r.dst, r.methodSpec(), r.working(),
                                     ParseObserver(r.observer));
}

WrittenLut WriteLut(const ChangeOfLight& change, const std::string& path,
                    const LutSettings& settings)
{
    jobs::LutRequest request;
    request.relight = RelightOf(change);
    request.out = path;
    request.format = settings.format;
    if (settings.size != 0)
    {
        request.size = settings.size;
    }
    request.shaper = Given(settings.shaper, request.shaper);
    request.encoding = Given(settings.encoding, request.encoding);
    const jobs::LutResult result = jobs::MakeLut(request);
    WrittenLut w;
    w.lut = result.files.lut;
    w.shaper = result.files.shaper;
    w.size = result.files.lattice ? result.size : 0;
    w.encoding = result.encodingDescription;
    return w;
}

WrittenConfig WriteConfig(const ConfigSettings& settings)
{
    jobs::ConfigRequest request;
    request.out = settings.out;
    request.base = settings.base;
    request.workingSpace = settings.workingSpace;
    for (const std::string& light : settings.lights)
    {
        request.lights.push_back(jobs::ResolveIlluminant(light));
    }
    request.methods = settings.methods;
    request.observer = Given(settings.observer, request.observer);
    request.plates = PlatesOf(settings.plates, settings.adaptation);
    const jobs::ConfigResult result = jobs::MakeConfig(request);
    WrittenConfig w;
    w.file = settings.out + "/config.ocio";
    const OCIO_NAMESPACE::ConstConfigRcPtr& config = result.package.config;
    for (int i = 0; i < config->getNumLooks(); ++i)
    {
        w.looks.push_back(config->getLookNameByIndex(i));
    }
    for (const auto& file : result.package.lutFiles)
    {
        w.lutFiles.push_back(file.first);
    }
    w.workingSpace = result.options.workingSpace;
    return w;
}

WrittenImages RelightImages(const std::string& input, const std::string& output,
                            const ChangeOfLight& change, const std::string& frames)
{
    jobs::ApplyRequest request;
    request.input = input;
    request.output = output;
    request.frames = frames;
    request.relight = RelightOf(change);
    return Written(jobs::ApplyImages(request));
}

WrittenImages ApplyLook(const std::string& input, const std::string& output,
                        const std::string& config, const std::string& look,
                        const std::string& colorspace, const std::string& frames)
{
    jobs::ApplyRequest request;
    request.input = input;
    request.output = output;
    request.frames = frames;
    request.config = config;
    request.look = look;
    request.colorspace = colorspace;
    return Written(jobs::ApplyImages(request));
}

}  // namespace bandlight
