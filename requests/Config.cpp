// SPDX-License-Identifier: BSD-3-Clause
#include "requests/Config.h"

#include <filesystem>

#include "farm/OutputPaths.h"
#include "spectral/Exception.h"

namespace bandlight::jobs
{

namespace
{
/// The output folder, before any work: writable, and not the base's own
/// folder (its config.ocio would be replaced by the extended one).
void CheckOutputFolder(const ConfigRequest& r)
{
    if (!r.out)
    {
        return;
    }
    if (r.out->empty())
    {
        OutputPlan().folder("{out}", "").check();  // refused: an empty path
    }
    if (!r.base.empty() && !r.extendInPlace)
    {
        std::filesystem::path baseFolder = std::filesystem::path(r.base).parent_path();
        if (baseFolder.empty())
        {
            baseFolder = ".";
        }
        if (SameFile(*r.out, baseFolder.string()))
        {
            throw ParameterError("{out} " + ShowPath(*r.out) + " is the folder of {base} " +
                                 ShowPath(r.base) +
                                 ": the extended config would replace the studio's own; write "
                                 "it into a folder of its own");
        }
    }
    OutputPlan plan;
    plan.folder("{out}", *r.out, {"config.ocio"});
    if (!r.base.empty() && !r.extendInPlace)
    {
        plan.input(r.base);
    }
    plan.check();
}
}  // namespace

ConfigResult BuildRequestedConfig(const ConfigRequest& r, Reporter& reporter, OutputSet* outputs)
{
    CheckOutputFolder(r);
    if (r.basePaths == "absolute" && r.base.empty() && !r.baseConfig)
    {
        throw ParameterError("{base_paths} rewrites the search paths of a {base}: give the base "
                             "config, or leave {base_paths} out");
    }
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
    if (!r.looks)
    {
        // Input spaces alone: no lights, no methods, no looks.
    }
    else if (r.lights.empty())
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
    options.methods = !r.looks ? std::vector<std::string>{}
                      : r.methods.empty() ? LinearMethodNames()
                                          : r.methods;
    options.inputSpaces = r.inputSpaces;
    options.workingSpace = r.workingSpace.empty() ? defaults::WORKING_SPACE : r.workingSpace;
    options.outputDir = r.out.value_or("");
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
    if (r.out)
    {
        WriteConfigPackage(result.package, *r.out, outputs);
        // Its LUT-file looks resolve from the folder they were written to.
        result.package.config->setWorkingDir(r.out->c_str());
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
