// SPDX-License-Identifier: BSD-3-Clause
#include "imaging/RelightForms.h"

#include <memory>

#include "plugin/NativeKernels.h"
#include "plugin/OcioTransforms.h"
#include "plugin/SceneLinearEvidence.h"
#include "spectral/Exception.h"

namespace bandlight::jobs
{

RelightForm MakeRelightForm(const RelightRequest& relight, Reporter& reporter)
{
    RelightForm f;
    const MethodSpec method = relight.methodSpec(reporter);
    const Observer observer = ParseObserver(relight.observer);
    if (method.entry().appliesNatively())
    {
        const auto relighter = std::make_shared<Relighter>(relight.src, relight.dst, method,
                                                           relight.working(), observer);
        f.native = [relighter](float* rgb, size_t n) { relighter->apply(rgb, n, 1); };
        f.applied = LookName(method.name, relight.src.name, relight.dst.name) + " (native)";
    }
    else
    {
        OCIO::GroupTransformRcPtr t = IlluminantChangeTransform(relight.src, relight.dst, method,
                                                                relight.working(), observer);
        f.processor = OCIO::Config::CreateRaw()->getProcessor(t);
        f.applied = t->getFormatMetadata().getName();
        // The linear methods: their guarded 3×3, natively.
        f.kernel = NativeClampMatrix(f.processor);
    }
    return f;
}

std::string LookSpace(const ApplyRequest& r, const OCIO::ConstConfigRcPtr& config)
{
    const std::string space =
        r.colorspace.empty() ? std::string(OCIO::ROLE_SCENE_LINEAR) : r.colorspace;
    if (!config->getColorSpace(space.c_str()))
    {
        throw Exception("colour space '" + space + "' is not in " + r.config);
    }
    return space;
}

RelightForm MakeLookForm(const ApplyRequest& r, const OCIO::ConstConfigRcPtr& config,
                         const std::string& look)
{
    if (!config->getLook(look.c_str()))
    {
        throw Exception("look '" + look + "' is not in " + r.config);
    }
    const std::string space = LookSpace(r, config);
    OCIO::LookTransformRcPtr t = OCIO::LookTransform::Create();
    t->setSrc(space.c_str());
    t->setDst(space.c_str());
    t->setLooks(look.c_str());
    RelightForm f;
    f.processor = config->getProcessor(t);
    f.kernel = NativeClampMatrix(f.processor);
    f.applied = "look " + look;
    return f;
}

const RgbSpace* LookWorkingSpace(const ApplyRequest& r, const OCIO::ConstConfigRcPtr& config,
                                 std::string& unknown)
{
    if (!r.colorspace.empty())
    {
        return nullptr;
    }
    try
    {
        return IdentifySceneLinear(config).space;
    }
    catch (const Exception& e)
    {
        unknown = "the primaries of " + r.config +
                  "'s scene_linear are unknown, so the image goes to the look as it is; name its "
                  "colour space in the config with {colorspace} (" +
                  std::string(e.what()) + ")";
        return nullptr;
    }
}
}  // namespace bandlight::jobs
