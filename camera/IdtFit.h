// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The IDT science of `idt`: the lights a camera is characterised under, the
// remittances it is fitted and tested on, and the fits themselves, from the
// camera's spectral sensitivities (transforms/Idt.h's objective per light,
// an as-shot light found from a neutral, a CCT sweep between two lights) or
// from a chart photographed under one light. The job (jobs/IdtJob.cpp) only
// orchestrates: the request checked, these fits, the outputs written.

#include <string>
#include <vector>

#include "farm/Reporter.h"
#include "requests/Idt.h"
#include "transforms/Idt.h"
#include "transforms/Methods.h"

namespace bandlight::jobs
{

/// What every fit of a request shares: the working space, the adaptation of
/// each light's white to the working white, and the observer.
struct FitSetting
{
    const RgbSpace& working;
    AdaptationMethod adaptation;
    Observer observer;

    IdtProblem problem(const SpectralCamera& camera, const Spectrum& light) const
    {
        return IdtProblem(camera, light, working, adaptation, observer);
    }
};

/// The remittances the IDTs are fitted on (training) and also measured on
/// (test), with the names the errors are reported under.
struct RemittanceSets
{
    std::vector<NamedSpectrum> training;
    std::string trainingName;
    std::vector<NamedSpectrum> test;
    std::string testName;
};

/// A light of an IDT or a camera's white balance: a colour temperature
/// ("3200K": daylight from 4000 K, Planckian below, IdtLightForCct), a
/// built-in name or a spectrum file.
Light ResolveIdtLight(const std::string& text, Reporter& reporter);

/// The name a colour temperature's light is known by: "3200K".
std::string KelvinName(double kelvin);

/// {training} (rawtoaces' 190 when empty), then {test_set}.
RemittanceSets ResolveRemittances(const IdtRequest& request, Reporter& reporter);

/// The IDTs of a camera's spectral sensitivities: one per light of
/// {lights} (and {as_shot_neutral}'s light, and the {interpolate} sweep),
/// each with its errors on the training and test sets, into `result`.
void FitFromSensitivities(const IdtRequest& request, const FitSetting& setting,
                          const RemittanceSets& sets, Reporter& reporter, IdtResult& result);

/// The IDT of a chart photographed under one light ({chart_rgb}, {chart},
/// {light}), with its error on the chart's own patches, into `result`.
void FitFromChart(const IdtRequest& request, const FitSetting& setting, Reporter& reporter,
                  IdtResult& result);

}  // namespace bandlight::jobs
