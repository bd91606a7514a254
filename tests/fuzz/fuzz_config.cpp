// SPDX-License-Identifier: BSD-3-Clause
// Fuzzes `bandlight config --base`: OpenColorIO parses the base config, then
// bandlight identifies its scene_linear space and adds its looks. A base
// either extends or is refused with an exception; nothing crashes.
#include <sstream>

#include <OpenColorIO/OpenColorIO.h>

#include "FuzzCheck.h"
#include "plugin/ConfigBuilder.h"
#include "plugin/ConfigReferences.h"
#include "spectral/Illuminants.h"

namespace OCIO = OCIO_NAMESPACE;
using namespace bandlight;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    static const bool quiet = []
    {
        OCIO::SetLoggingLevel(OCIO::LOGGING_LEVEL_NONE);
        return true;
    }();
    (void)quiet;
    std::istringstream in(fuzz::Text(data, size));
    OCIO::ConstConfigRcPtr base;
    try
    {
        base = OCIO::Config::CreateFromStream(in);
    }
    catch (const OCIO::Exception&)
    {
        return 0;
    }
    // What `config --base` and `apply --config` do first: refuse a config
    // that refers to itself (OCIO would recurse until the stack overflows).
    try
    {
        CheckConfigReferences(base, "fuzz.ocio");
    }
    catch (const Exception& e)
    {
        fuzz::CheckMessage(e, "fuzz.ocio");
        return 0;
    }
    ConfigOptions options;
    options.lights = {{"A", BuiltinIlluminant("A")}, {"D65", BuiltinIlluminant("D65")}};
    options.methods = {"bradford", "band3"};
    try
    {
        const ConfigPackage package = ExtendConfig(base, options, true);
        std::ostringstream out;
        package.config->serialize(out);
    }
    catch (const OCIO::Exception&)
    {
    }
    catch (const Exception&)
    {
    }
    return 0;
}
