// SPDX-License-Identifier: BSD-3-Clause
#include "jobs/QualityJob.h"

#include "report/Gnuplot.h"
#include "requests/Inputs.h"
#include "spectral/Exception.h"
#include "spectral/Parallel.h"

namespace bandlight::jobs
{

QualityResult MakeQuality(const QualityRequest& request, Reporter& reporter)
{
    if (request.lights.empty())
    {
        throw ParameterError(
            "quality needs at least one light (a name such as D65 or 3200K, "
            "or a spectrum file)");
    }
    if (!request.plot.empty())
    {
        CheckPlotPath(request.plot);
    }
    // Every light read before any is scored: a bad one costs no work.
    std::vector<Light> lights;
    for (const std::string& l : request.lights)
    {
        // Named as the user gave it: a file's spectrum is often called "1".
        lights.push_back(ResolveIlluminant(l, reporter));
        lights.back().name = l;
    }
    const Light reference =
        request.reference.empty() ? Light() : ResolveIlluminant(request.reference, reporter);
    QualityResult result;
    result.lights = ScoreLights(lights, reference, request.threads);
    return result;
}

std::vector<LightQuality> ScoreLights(const std::vector<Light>& lights, const Light& reference,
                                      int threads)
{
    ScoreContext context;
    if (!reference.name.empty())
    {
        context.reference = reference.spectrum;
        context.referenceName = reference.name;
    }
    std::vector<LightQuality> scored(lights.size());
    std::vector<std::string> errors(lights.size());
    ParallelFor(lights.size(), threads,
                [&](size_t a, size_t b)
                {
                    for (size_t i = a; i < b; ++i)
                    {
                        try
                        {
                            scored[i] = ScoreLight(lights[i].name, lights[i].spectrum, context);
                        }
                        catch (const Exception& e)
                        {
                            errors[i] = e.what();
                        }
                    }
                });
    for (const std::string& e : errors)
    {
        if (!e.empty())
        {
            throw Exception(e);
        }
    }
    return scored;
}

}  // namespace bandlight::jobs
