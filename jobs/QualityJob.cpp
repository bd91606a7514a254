// SPDX-License-Identifier: BSD-3-Clause
#include "jobs/QualityJob.h"

#include <filesystem>

#include "report/Gnuplot.h"
#include "report/LightQualityPlot.h"
#include "requests/Inputs.h"
#include "spectral/Colorimetry.h"
#include "spectral/ColourFidelity.h"
#include "spectral/Exception.h"
#include "spectral/Parallel.h"

namespace bandlight::jobs
{

namespace
{

/// `s` scaled to the luminance (CIE 1931 Y) of `like`.
Spectrum SameLuminance(Spectrum s, const Spectrum& like)
{
    const double y = IntegrateXyz(s, Observer::CIE1931_2DEG).y();
    s *= y > 0.0 ? IntegrateXyz(like, Observer::CIE1931_2DEG).y() / y : 1.0;
    return s;
}

/// The plot's row of each light: the light, CIE 224's reference at its
/// CCT and the user's reference (each at the light's luminance), and
/// TM-30's bins as its calculator computes them.
std::vector<QualityPlotRow> QualityPlotRows(const std::vector<Light>& lights,
                                            const Light& reference)
{
    std::vector<QualityPlotRow> rows;
    for (const Light& l : lights)
    {
        QualityPlotRow row;
        row.light = l.name;
        row.spectrum = l.spectrum;
        try
        {
            const ColourFidelity f = ComputeColourFidelity(l.spectrum, FidelityMethod::TM_30);
            row.references.push_back({"CIE 224 / TM-30 reference",
                                      SameLuminance(ColourFidelityReference(f.cctK), l.spectrum)});
            row.note = f.referenceName;
            row.vectors = true;
            row.referenceAb = f.referenceBinAb;
            row.testAb = f.testBinAb;
            row.rf = f.rf;
            row.rg = f.rg;
        }
        catch (const Exception&)
        {
            // No TM-30 value (a CCT outside its range): the table's warning
            // says why; the row shows the spectrum alone.
        }
        if (!reference.name.empty())
        {
            row.references.push_back(
                {reference.name + " (--reference)", SameLuminance(reference.spectrum, l.spectrum)});
        }
        rows.push_back(std::move(row));
    }
    return rows;
}

}  // namespace

QualityResult MakeQuality(const QualityRequest& request, Reporter& reporter)
{
    if (request.lights.empty())
    {
        throw ParameterError(
            "quality needs at least one light (a name such as D65 or 3200K, "
            "or a spectrum file)");
    }
    if (request.reference && request.reference->empty())
    {
        throw ParameterError("--reference is empty: name a light (D65, 3200K) or a spectrum file");
    }
    if (request.plot)
    {
        CheckPlotPath(*request.plot);
        if (request.lights.size() > QUALITY_PLOT_MAX_LIGHTS)
        {
            throw ParameterError("--plot draws " + std::to_string(QUALITY_PLOT_MAX_LIGHTS) +
                                 " lights at most (a row each), not " +
                                 std::to_string(request.lights.size()) +
                                 ": plot fewer, or use --json/--csv for the scores of many");
        }
    }
    for (const std::string& l : request.lights)
    {
        std::error_code ec;
        if (request.plot && std::filesystem::equivalent(l, *request.plot, ec))
        {
            throw ParameterError("--plot " + *request.plot + " is the light " + l +
                                 ": the plot would overwrite it; give another file");
        }
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
        request.reference ? ResolveIlluminant(*request.reference, reporter) : Light();
    QualityResult result;
    result.lights = ScoreLights(lights, reference, request.threads);
    if (request.plot)
    {
        DrawQualityPlot(QualityPlotRows(lights, reference), *request.plot);
        result.plot = *request.plot;
    }
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
