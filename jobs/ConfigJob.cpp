// SPDX-License-Identifier: BSD-3-Clause
#include "jobs/ConfigJob.h"

#include "spectral/Exception.h"

namespace bandlight::jobs
{

ConfigResult MakeConfig(const ConfigRequest& r, Reporter& reporter)
{
    ConfigResult result;
    ConfigOptions& options = result.options;
    options.plates = r.plates.parsed();
    options.camera = r.plates.loadCamera();
    {
        const Light idt = r.plates.idt(reporter);
        options.idtLightName = idt.name;
        options.idtLight = idt.spectrum;
    }
    options.observer = ParseObserver(r.observer);
    if (r.lights.empty())
    {
        for (const std::string& name : SplitList(defaults::CONFIG_ILLUMINANTS))
        {
            options.lights.push_back(ResolveIlluminant(name, reporter));
        }
    }
    else
    {
        options.lights = r.lights;
    }
    options.methods = r.methods.empty() ? LinearMethodNames() : r.methods;
    options.workingSpace = r.workingSpace.empty() ? defaults::WORKING_SPACE : r.workingSpace;
    options.outputDir = r.out;
    options.lutSize = CheckedLutSize(r.lutSize, "lut_size");
    if (r.basePaths != "relative" && r.basePaths != "absolute")
    {
        throw ParameterError("{base_paths} must be 'relative' or 'absolute', not '" +
                             OneLine(r.basePaths, 80) + "'");
    }
    options.absoluteBasePaths = r.basePaths == "absolute";

    if (!r.baseConfig && r.base.empty())
    {
        result.package = BuildConfig(options);
        result.identified = FindRgbSpace(options.workingSpace).name;
    }
    else
    {
        // ExtendConfig checks the base's references itself (once: each check
        // looks up every colour space by name, which OCIO 2.1 does in linear time).
        const OCIO_NAMESPACE::ConstConfigRcPtr base =
            r.baseConfig ? r.baseConfig : ReadConfigFile(r.base, false);
        if (!r.baseConfig)
        {
            options.baseName = r.base;
        }
        result.package = ExtendConfig(base, options, r.workingSpace.empty(), &result.identified);
    }
    if (!r.out.empty())
    {
        WriteConfigPackage(result.package, r.out);
        // Its LUT-file looks resolve from the folder they were written to.
        result.package.config->setWorkingDir(r.out.c_str());
    }
    else if (!result.package.lutFiles.empty())
    {
        throw ParameterError(std::to_string(result.package.lutFiles.size()) +
                             " looks of this config are LUT files (upsample, rootpoly; every "
                             "look of an OCIO v1 base): give {out=}DIR to write them with "
                             "config.ocio");
    }
    return result;
}

}  // namespace bandlight::jobs
