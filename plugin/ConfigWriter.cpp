// SPDX-License-Identifier: BSD-3-Clause
// A config package as text (SerializeConfig) and as files on disk
// (WriteConfigPackage: config.ocio and its LUTs, written as one set).
#include "plugin/ConfigBuilder.h"

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>

#include "plugin/detail/ConfigParts.h"
#include "spectral/AtomicFile.h"
#include "spectral/Exception.h"

namespace bandlight
{

namespace
{

/// `text` as a YAML double-quoted scalar.
std::string YamlQuoted(const std::string& text)
{
    std::string out = "\"";
    for (const char c : text)
    {
        if (c == '"' || c == '\\')
        {
            out += '\\';
            out += c;
        }
        else if (static_cast<unsigned char>(c) < 0x20)
        {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\x%02X", unsigned(static_cast<unsigned char>(c)));
            out += buf;
        }
        else
        {
            out += c;
        }
    }
    return out + "\"";
}

}  // namespace

std::string SerializeConfig(const OCIO::ConstConfigRcPtr& config)
{
    std::ostringstream out;
    config->serialize(out);
    std::string text = out.str();
    // OCIO 2.1 writes no `environment:` section for a v1 config, though v1
    // has one and its context variables (a show's $SEQ/$SHOT defaults) are
    // what its search paths and looks resolve: put it back after the
    // version line, where OCIO writes it for v2.
    if (config->getMajorVersion() < 2 && config->getNumEnvironmentVars() > 0 &&
        text.find("\nenvironment:") == std::string::npos)
    {
        std::string env = "\nenvironment:\n";
        for (int i = 0; i < config->getNumEnvironmentVars(); ++i)
        {
            const char* name = config->getEnvironmentVarNameByIndex(i);
            env += "  " + YamlQuoted(name) + ": " +
                   YamlQuoted(config->getEnvironmentVarDefault(name)) + "\n";
        }
        const size_t eol = text.find('\n');
        text.insert(eol == std::string::npos ? text.size() : eol + 1, env);
    }
    return text;
}

void WriteConfigPackage(const ConfigPackage& package, const std::string& dir, OutputSet* outputs)
{
    auto makeDir = [](const std::string& d)
    {
        std::error_code ec;
        std::filesystem::create_directories(d, ec);
        if (ec || !std::filesystem::is_directory(d))
        {
            // A file where the folder belongs is ENOTDIR, as for a file on its path.
            throw FileError(d, ec ? ec.value() : ENOTDIR,
                            "cannot create the directory (" +
                                (ec ? ec.message() : std::string("a file is in the way")) + ")");
        }
    };
    makeDir(dir);
    // Every folder a LUT file goes into (luts/, and below it a wall's
    // luts/wall/<white balance>/).
    std::set<std::string> folders;
    for (const auto& lut : package.lutFiles)
    {
        const std::string folder =
            std::filesystem::path(dir + "/" + lut.first).parent_path().string();
        if (folders.insert(folder).second)
        {
            makeDir(folder);
        }
    }
    // The config and its LUTs are one set: a config is never left pointing
    // at LUTs of another run, nor LUTs replaced under an old config.
    OutputSet own;
    OutputSet& set = outputs ? *outputs : own;
    OCIO::ConstConfigRcPtr raw = OCIO::Config::CreateRaw();
    for (const auto& lut : package.lutFiles)
    {
        const auto& transform = lut.second;
        // CLF, or OCIO's CTF for what CLF cannot hold (a matrix with alpha).
        const bool ctf = std::filesystem::path(lut.first).extension() == ".ctf";
        const char* format = ctf ? "Color Transform Format" : "Academy/ASC Common LUT Format";
        set.write(dir + "/" + lut.first,
                  [&](std::ostream& os) { transform->write(raw, format, os); });
    }
    // OCIO 2.1 serialises in time quadratic in the colour spaces: the text
    // ExtendConfig checked is the one written.
    const std::string text = package.text.empty() ? SerializeConfig(package.config) : package.text;
    set.write(dir + "/config.ocio", [&](std::ostream& os) { os << text; });
    own.commit();
}

}  // namespace bandlight
