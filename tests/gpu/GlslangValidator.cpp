// SPDX-License-Identifier: BSD-3-Clause
// GpuRunner's shader validation: Debian's glslangValidator, run on the
// wrapped shaders in a private folder (the EGL side is in GpuRunner.cpp).
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "gpu/GpuRunner.h"

namespace bandlight::test
{

namespace
{

// ---------------------------------------------------------------------------
// glslangValidator.

#ifdef BANDLIGHT_GLSLANG_VALIDATOR
constexpr const char* kValidator = BANDLIGHT_GLSLANG_VALIDATOR;
#else
constexpr const char* kValidator = "";
#endif

std::string Quoted(const std::string& text)
{
    std::string q = "'";
    for (char ch : text)
    {
        q += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
    }
    return q + "'";
}

/// A fresh folder under $TMPDIR, removed with its files when destroyed.
class TempFolder
{
public:
    TempFolder()
    {
        const char* tmp = std::getenv("TMPDIR");
        std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/bandlight_gpu_XXXXXX";
        if (!mkdtemp(pattern.data()))
        {
            throw std::runtime_error("cannot create a folder like " + pattern);
        }
        m_path = pattern;
    }
    ~TempFolder()
    {
        for (const std::string& f : m_files)
        {
            std::remove((m_path + "/" + f).c_str());
        }
        rmdir(m_path.c_str());
    }
    TempFolder(const TempFolder&) = delete;
    TempFolder& operator=(const TempFolder&) = delete;

    const std::string& path() const { return m_path; }
    /// Writes `text` as file `name` in the folder.
    void write(const std::string& name, const std::string& text)
    {
        std::ofstream out(m_path + "/" + name, std::ios::binary);
        out << text;
        if (!out.flush())
        {
            throw std::runtime_error("cannot write " + m_path + "/" + name);
        }
        m_files.push_back(name);
    }
    /// Names a file the validator will write, for clean-up.
    void adopt(const std::string& name) { m_files.push_back(name); }

private:
    std::string m_path;
    std::vector<std::string> m_files;
};

/// Runs a shell command, returning its exit status and, in `output`,
/// stdout and stderr together.
int RunCommand(const std::string& command, std::string& output)
{
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    if (!pipe)
    {
        throw std::runtime_error("cannot run " + command);
    }
    char buf[4096];
    size_t n = 0;
    output.clear();
    while ((n = std::fread(buf, 1, sizeof buf, pipe)) > 0)
    {
        output.append(buf, n);
    }
    const int status = pclose(pipe);
    if (status == -1 || !WIFEXITED(status))
    {
        throw std::runtime_error("the validator did not finish: " + command);
    }
    return WEXITSTATUS(status);
}

/// Splits a multi-file glslangValidator report into one part per file: the
/// validator prints each file's name on a line of its own, then its messages.
std::vector<std::string> SplitReport(const std::string& report,
                                     const std::vector<std::string>& names)
{
    std::map<std::string, size_t> index;
    for (size_t i = 0; i < names.size(); ++i)
    {
        index[names[i]] = i;
    }
    std::vector<std::string> parts(names.size());
    std::istringstream in(report);
    std::string line;
    size_t current = names.size();
    while (std::getline(in, line))
    {
        const auto found = index.find(line);
        if (found != index.end())
        {
            current = found->second;
        }
        else if (current < names.size() && !line.empty())
        {
            parts[current] += line + "\n";
        }
    }
    return parts;
}

bool HasErrors(const std::string& messages)
{
    return messages.find("ERROR") != std::string::npos ||
           messages.find("error") != std::string::npos;
}

}  // namespace

bool GpuRunner::HasValidator()
{
    return *kValidator != '\0';
}

std::string GpuRunner::Compile(const std::string& shaderText, OCIO::GpuLanguage language)
{
    return Compile(std::vector<std::string>{shaderText}, language).front();
}

std::vector<std::string> GpuRunner::Compile(const std::vector<std::string>& shaderTexts,
                                            OCIO::GpuLanguage language)
{
    if (!HasValidator())
    {
        throw std::logic_error("glslangValidator was not found when the tests were configured");
    }
    if (!IsValidated(language))
    {
        throw std::logic_error(std::string("no validator for ") + GpuLanguageName(language));
    }
    std::vector<std::string> results(shaderTexts.size());
    TempFolder folder;
    const std::string cd = "cd " + Quoted(folder.path()) + " && " + Quoted(kValidator);
    if (language == OCIO::GPU_LANGUAGE_HLSL_DX11)
    {
        // HLSL must be translated to SPIR-V (-V), and the validator links
        // every file of a run into one module: one run per shader.
        folder.adopt("s.spv");
        for (size_t i = 0; i < shaderTexts.size(); ++i)
        {
            folder.write("s.hlsl", shaderTexts[i]);
            std::string report;
            const int status = RunCommand(cd + " -D -V -e main -S frag -o s.spv s.hlsl", report);
            results[i] = status == 0 ? std::string() : report;
        }
        return results;
    }
    constexpr size_t kBatch = 64;
    for (size_t first = 0; first < shaderTexts.size(); first += kBatch)
    {
        std::vector<std::string> names;
        std::string command = cd + " -S frag";
        for (size_t i = first; i < std::min(shaderTexts.size(), first + kBatch); ++i)
        {
            names.push_back("s" + std::to_string(i) + ".frag");
            folder.write(names.back(), shaderTexts[i]);
            command += " " + names.back();
        }
        std::string report;
        const int status = RunCommand(command, report);
        const std::vector<std::string> parts = SplitReport(report, names);
        bool attributed = false;
        for (size_t k = 0; k < names.size(); ++k)
        {
            if (HasErrors(parts[k]))
            {
                results[first + k] = parts[k];
                attributed = true;
            }
        }
        if (status != 0 && !attributed)
        {
            // A failure the report does not pin on a file: say so for each.
            for (size_t k = 0; k < names.size(); ++k)
            {
                results[first + k] = "glslangValidator failed: " + report;
            }
        }
    }
    return results;
}

}  // namespace bandlight::test
