// SPDX-License-Identifier: BSD-3-Clause
#include "jobs/IdtJob.h"

#include <sstream>

#include "camera/IdtFit.h"
#include "report/IdtReport.h"
#include "requests/Config.h"
#include "requests/Inputs.h"
#include "spectral/AtomicFile.h"
#include "spectral/ColourRendering.h"
#include "spectral/Exception.h"

namespace bandlight::jobs
{

namespace
{

/// The config (a new one in {config}, or {base} extended into {out}), each
/// IDT an input colour space named in `result`, and the JSON document:
/// committed together.
void WriteOutputs(const IdtRequest& r, const OCIO_NAMESPACE::ConstConfigRcPtr& base,
                  Reporter& reporter, IdtResult& result)
{
    OutputSet outputs;
    if (!r.config.empty() || !r.out.empty())
    {
        ConfigRequest c;
        c.out = r.config.empty() ? r.out : r.config;
        const std::string existing = ExistingIdtConfig(r);
        c.base = existing.empty() ? r.base : existing;
        c.extendInPlace = !existing.empty();
        c.baseConfig = base;
        c.workingSpace = c.base.empty() ? result.workingSpace : r.baseSpace;
        c.observer = r.observer;
        c.looks = false;
        for (IdtEntry& e : result.idts)
        {
            e.colorSpace = IdtColorSpaceName(result.camera, e.light);
            if (c.extendInPlace && base->getColorSpace(e.colorSpace.c_str()))
            {
                throw ParameterError(existing + " already has the colour space '" +
                                     e.colorSpace +
                                     "' (this camera under this light, added before): nothing "
                                     "was written; give {config} another folder, or remove the "
                                     "space from the config");
            }
            c.inputSpaces.push_back({e.colorSpace, IdtDescription(e, result.camera, result),
                                     e.fit.rawToWorking(), result.workingSpace});
        }
        BuildRequestedConfig(c, reporter, &outputs);
        result.written.push_back(*c.out + "/config.ocio");
        if (c.extendInPlace)
        {
            std::string added;
            for (const IdtEntry& e : result.idts)
            {
                added += (added.empty() ? "" : ", ") + e.colorSpace;
            }
            reporter.note(existing + ": held a config already; its colour spaces are kept and " +
                          std::to_string(result.idts.size()) + " input spaces added: " + added);
        }
    }
    if (!r.json.empty())
    {
        const std::string document = IdtDocument(result);
        outputs.write(r.json, [&](std::ostream& os) { os << document << "\n"; });
        result.written.push_back(r.json);
    }
    outputs.commit();
}

}  // namespace

IdtResult MakeIdt(const IdtRequest& r, Reporter& reporter)
{
    CheckIdtRequest(r);
    const RgbSpace& working = FindRgbSpace(r.workingSpace);
    const OCIO_NAMESPACE::ConstConfigRcPtr base = ReadIdtBase(r);
    const FitSetting setting{working, ParsePlates("balanced", r.adaptation).adaptation,
                             ParseObserver(r.observer)};

    IdtResult result;
    result.workingSpace = working.name;
    result.adaptation = AdaptationName(setting.adaptation);
    const RemittanceSets sets = ResolveRemittances(r, reporter);
    result.trainingName = sets.trainingName;
    result.trainingCount = int(sets.training.size());
    result.testName = sets.testName;
    result.testCount = int(sets.test.size());
    switch (SourceOf(r))
    {
        case IdtSource::CHART:
            FitFromChart(r, setting, reporter, result);
            break;
        case IdtSource::SENSITIVITIES:
            FitFromSensitivities(r, setting, sets, reporter, result);
            break;
    }
    WriteOutputs(r, base, reporter, result);
    return result;
}

}  // namespace bandlight::jobs
