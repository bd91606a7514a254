// SPDX-License-Identifier: BSD-3-Clause
#include "cli/Gnuplot.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "spectral/AtomicFile.h"
#include "spectral/Exception.h"

namespace bandlight::cli
{

namespace
{
std::string ReplaceAll(std::string s, const std::string& from, const std::string& to)
{
    for (size_t i = 0; (i = s.find(from, i)) != std::string::npos; i += to.size())
    {
        s.replace(i, from.size(), to);
    }
    return s;
}

/// A path as a gnuplot string literal.
std::string Quote(const std::string& path)
{
    return "'" + ReplaceAll(path, "'", "''") + "'";
}
/// A path as a shell word.
std::string ShellQuote(const std::string& path)
{
    return "'" + ReplaceAll(path, "'", "'\\''") + "'";
}
}  // namespace

void RunGnuplot(const std::string& script, const std::string& data, const std::string& output)
{
    const bool svg = output.size() > 4 && output.substr(output.size() - 4) == ".svg";
    const bool png = output.size() > 4 && output.substr(output.size() - 4) == ".png";
    if (!svg && !png)
    {
        throw Exception(output + ": plots are written as .png or .svg");
    }
    AtomicFile image(output);
    image.stream().close();
    const std::string base = image.tempPath();
    const std::string dataPath = base + ".dat";
    const std::string scriptPath = base + ".gp";
    const std::string errPath = base + ".err";
    struct Cleanup
    {
        std::string a, b, c;
        ~Cleanup()
        {
            std::remove(a.c_str());
            std::remove(b.c_str());
            std::remove(c.c_str());
        }
    } cleanup{dataPath, scriptPath, errPath};
    std::ofstream(dataPath) << data;
    {
        std::ofstream gp(scriptPath);
        gp << (svg ? "set terminal svg size 1000,650 dynamic font 'Sans,12'\n"
                   : "set terminal pngcairo size 1000,650 font 'Sans,11'\n")
           << "set output " << Quote(base) << "\n"
           << ReplaceAll(script, "$DATA", Quote(dataPath)) << "\n";
    }
    const std::string cmd = "gnuplot " + ShellQuote(scriptPath) + " 2>" + ShellQuote(errPath);
    const int status = std::system(cmd.c_str());
    if (status != 0)
    {
        std::ifstream err(errPath);
        std::stringstream msg;
        msg << err.rdbuf();
        std::string text = msg.str();
        if (WIFEXITED(status) && WEXITSTATUS(status) == 127)
        {
            text = "gnuplot is not installed (Debian: gnuplot-nox)";
        }
        while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
        {
            text.pop_back();
        }
        const size_t nl = text.rfind('\n');
        throw Exception(output + ": plotting failed: " +
                        (nl == std::string::npos ? text : text.substr(nl + 1)));
    }
    image.commit();
}

}  // namespace bandlight::cli
