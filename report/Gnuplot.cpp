// SPDX-License-Identifier: BSD-3-Clause
#include "report/Gnuplot.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include "spectral/AtomicFile.h"
#include "spectral/Exception.h"

namespace bandlight
{

namespace
{
std::string Hex(unsigned char c)
{
    char buf[8];
    std::snprintf(buf, sizeof buf, "\\x%02X", unsigned(c));
    return buf;
}

/// The gnuplot child of a run in flight, for the interrupt handler.
std::atomic<pid_t> g_child{0};

void KillChild() noexcept
{
    if (const pid_t pid = g_child.load(); pid > 0)
    {
        ::kill(pid, SIGKILL);
    }
}

/// Runs gnuplot on the script file `script` as its standard input (so no
/// path, not even one starting with '-', is ever an argument), stdout into
/// `outPath` (the image) and stderr into `errPath`; no shell. Returns the
/// wait status; 127 << 8 when gnuplot cannot be run.
int Spawn(const std::string& script, const std::string& outPath, const std::string& errPath)
{
    // Prepare everything the child needs before fork: after fork in a
    // possibly threaded process only async-signal-safe calls are allowed.
    const int out = ::open(outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    const int err = ::open(errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
    const int input = ::open(script.c_str(), O_RDONLY | O_CLOEXEC);
    if (out < 0 || err < 0 || input < 0)
    {
        const std::string reason = std::strerror(errno);
        for (int fd : {out, err, input})
        {
            if (fd >= 0)
            {
                ::close(fd);
            }
        }
        throw Exception(outPath + ": cannot create (" + reason + ")");
    }
    AlsoOnInterrupt(&KillChild);
    const char* argv[] = {"gnuplot", nullptr};
    const pid_t pid = ::fork();
    if (pid == 0)
    {
        ::dup2(input, 0);
        ::dup2(out, 1);
        ::dup2(err, 2);
        ::execvp("gnuplot", const_cast<char* const*>(argv));
        ::_exit(127);
    }
    for (int fd : {out, err, input})
    {
        ::close(fd);
    }
    if (pid < 0)
    {
        throw Exception(std::string("cannot start gnuplot (") + std::strerror(errno) + ")");
    }
    g_child.store(pid);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR)
    {
    }
    g_child.store(0);
    return status;
}
}  // namespace

std::string GnuplotQuote(const std::string& text)
{
    std::string out = "'";
    for (const char ch : text)
    {
        const auto c = static_cast<unsigned char>(ch);
        if (c == '\'')
        {
            out += "''";
        }
        else if (c < 0x20 || c == 0x7F)
        {
            out += Hex(c);
        }
        else
        {
            out += ch;  // bytes of UTF-8 sequences pass as they are
        }
    }
    return out + "'";
}

std::string GnuplotDataLabel(const std::string& text)
{
    std::string out = "\"";
    for (const char ch : text)
    {
        const auto c = static_cast<unsigned char>(ch);
        out += (c < 0x20 || c == 0x7F || c == '"' || c == '\\') ? Hex(c) : std::string(1, ch);
    }
    return out + "\"";
}

namespace
{
std::string PlotExtension(const std::string& output)
{
    std::string ext = output.size() > 4 ? output.substr(output.size() - 4) : "";
    for (char& c : ext)
    {
        c = char(std::tolower(static_cast<unsigned char>(c)));
    }
    return ext;
}
}  // namespace

void CheckPlotPath(const std::string& output)
{
    const std::string ext = PlotExtension(output);
    if (ext != ".svg" && ext != ".png")
    {
        throw ParameterError("{plot} '" + OneLine(output, 200) +
                             "': plots are written as .png or .svg (the format follows the "
                             "extension)");
    }
}

void RunGnuplot(const std::string& script, const std::string& data, const std::string& output,
                OutputSet* outputs, PlotSize size)
{
    CheckPlotPath(output);
    const bool svg = PlotExtension(output) == ".svg";
    OutputSet own;
    AtomicFile& image = (outputs ? *outputs : own).add(output);
    image.stream().close();
    // gnuplot never sees a path it did not make: the image goes to its
    // standard output (redirected into the temporary file), the data are a
    // datablock inside the script, and the script and gnuplot's messages
    // live beside the image under AtomicFile's registered temporary names.
    AtomicFile scriptFile(image.tempPath() + ".gp", AtomicFile::Scratch{});
    AtomicFile errFile(image.tempPath() + ".err", AtomicFile::Scratch{});
    const std::string wh = std::to_string(size.width) + "," + std::to_string(size.height);
    scriptFile.stream() << (svg ? "set terminal svg size " + wh + " dynamic font 'Sans,12'\n"
                                : "set terminal pngcairo size " + wh + " font 'Sans,11'\n")
                        << "set termoption noenhanced\n"
                        << "$bandlight_data << EOD\n"
                        << data << (data.empty() || data.back() == '\n' ? "" : "\n") << "EOD\n"
                        << script << "\n";
    scriptFile.stream().close();
    if (!scriptFile.stream())
    {
        throw Exception(output + ": cannot write gnuplot's script beside it (disk full?)");
    }
    const int status = Spawn(scriptFile.tempPath(), image.tempPath(), errFile.tempPath());
    if (status != 0)
    {
        std::ifstream err(errFile.tempPath());
        std::stringstream msg;
        msg << err.rdbuf();
        std::string text = msg.str();
        if (WIFEXITED(status) && WEXITSTATUS(status) == 127)
        {
            text = "gnuplot is not installed (Debian: gnuplot-nox)";
        }
        else if (WIFSIGNALED(status))
        {
            text = "gnuplot was stopped by signal " + std::to_string(WTERMSIG(status));
        }
        while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
        {
            text.pop_back();
        }
        const size_t nl = text.rfind('\n');
        text = nl == std::string::npos ? text : text.substr(nl + 1);
        for (char& c : text)
        {
            c = (static_cast<unsigned char>(c) < 0x20) ? ' ' : c;
        }
        throw Exception(output + ": plotting failed: " + text);
    }
    own.commit();
}

}  // namespace bandlight
