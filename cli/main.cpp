// SPDX-License-Identifier: BSD-3-Clause
// bandlight: the command, one face of the jobs library (jobs/): each
// subcommand maps its flags to a request and prints the result. Exit codes: 0 success, 2 bad input
// (one line on stderr), 1 anything unexpected.
#include <cstdlib>
#include <iostream>
#include <new>

#include <OpenColorIO/OpenColorIO.h>

#include "cli/Commands.h"
#include "cli/Common.h"
#include "cli/Diagnostics.h"
#include "spectral/AtomicFile.h"
#include "spectral/Exception.h"
#include "transforms/Defaults.h"

namespace
{

/// OpenColorIO as the command runs it: no cache fallback, and its messages
/// held with the run's other notes.
void ConfigureOcio()
{
    // On a cache miss OpenColorIO 2.1 compares the new processor with every
    // processor it has cached (the "cache fallback"), so a command that builds
    // one processor per colour space (config --base, which checks each of the
    // base's transforms) takes time quadratic in the config: 86 of 120 s for
    // 10,000 colour spaces. The fallback only ever finds an identical
    // processor, so turning it off changes no result. A user's own setting wins.
    ::setenv(OCIO_NAMESPACE::OCIO_DISABLE_CACHE_FALLBACK, "1", 0);
    OCIO_NAMESPACE::SetLoggingFunction([](const char* message) { bandlight::cli::Note(message); });
}

void AddCommands(CLI::App& app)
{
    bandlight::cli::AddTablesCommand(app);
    bandlight::cli::AddXyzCommand(app);
    bandlight::cli::AddCriCommand(app);
    bandlight::cli::AddQualityCommand(app);
    bandlight::cli::AddIdtCommand(app);
    bandlight::cli::AddWallCommand(app);
    bandlight::cli::AddConfigCommand(app);
    bandlight::cli::AddLutCommand(app);
    bandlight::cli::AddApplyCommand(app);
    bandlight::cli::AddPackageCommand(app);
    bandlight::cli::AddAccuracyCommand(app);
    bandlight::cli::AddPlotCommand(app);
    bandlight::cli::AddRenderCommand(app);
    bandlight::cli::AddSpectralCommand(app);
    bandlight::cli::AddMethodsCommand(app);
}

/// CLI11 says only "A subcommand is required" for a mistyped command: name
/// it, and the command it was likely meant to be. A command that was found
/// and lacks a required option keeps CLI11's message ("--illuminant is
/// required").
std::string MissingCommand(const CLI::App& app, int argc, char** argv, const CLI::RequiredError& e)
{
    if (!app.get_subcommands().empty())
    {
        return e.what();
    }
    std::string commands, nearest;
    size_t best = std::string::npos;
    for (const CLI::App* sub : app.get_subcommands({}))
    {
        const std::string& name = sub->get_name();
        commands += (commands.empty() ? "" : ", ") + name;
        const size_t d = argc > 1 ? bandlight::cli::EditDistance(argv[1], name) : best;
        if (d < best)
        {
            best = d;
            nearest = name;
        }
    }
    if (argc <= 1)
    {
        return "give a command: " + commands + " (bandlight --help)";
    }
    if (argv[1][0] != '-')
    {
        return "unknown command '" + bandlight::OneLine(argv[1], 40) + "'" +
               (best <= 2 ? " (did you mean " + nearest + "?)" : std::string()) +
               "; the commands are " + commands;
    }
    return e.what();
}

/// The one place that maps the exception being handled to an exit code and
/// one line on stderr: 2 for bad input, 1 for anything unexpected; help and
/// version exit as CLI11 says.
int ExitFor(const CLI::App& app, int argc, char** argv, bandlight::cli::StderrCapture& capture)
{
    // Messages may quote file names and values of any length and content:
    // one line, bounded.
    const auto fail = [&capture](int code, const std::string& prefix, const std::string& what)
    {
        std::cout.flush();
        capture.finish(false, "bandlight: " + prefix + bandlight::OneLine(what, 4000));
        return code;
    };
    try
    {
        throw;
    }
    catch (const CLI::Success& e)
    {
        // --help, --help-all, --version.
        capture.finish(true, "");
        return app.exit(e);
    }
    catch (const CLI::RequiredError& e)
    {
        return fail(2, "", MissingCommand(app, argc, argv, e));
    }
    catch (const CLI::ParseError& e)
    {
        return fail(2, "", e.what());
    }
    catch (const bandlight::ParameterError& e)
    {
        // The library names its parameters; the command spells them as flags.
        return fail(2, "", e.spelled(bandlight::Face::COMMAND));
    }
    catch (const bandlight::FileError& e)
    {
        // A file that cannot be used; its message may name a parameter too.
        return fail(2, "", e.spelled(bandlight::Face::COMMAND));
    }
    catch (const bandlight::Exception& e)
    {
        return fail(2, "", e.what());
    }
    catch (const OCIO_NAMESPACE::Exception& e)
    {
        // OpenColorIO's own messages name the file and what is wrong with it.
        return fail(2, "", e.what());
    }
    catch (const std::bad_alloc&)
    {
        // Inputs are checked against stated limits before anything large is
        // allocated; this is the last resort when memory runs out anyway.
        return fail(2, "", "out of memory (the input asks for more than this machine has)");
    }
    catch (const std::exception& e)
    {
        return fail(1, "internal error: ", e.what());
    }
}

}  // namespace

int main(int argc, char** argv)
{
    // An interrupted run leaves every previous output as it was, and no
    // temporary files behind.
    bandlight::RemoveTemporaryFilesOnInterrupt();
    // A failed run prints one line: notes, progress and libraries' own
    // messages are held back until the run has succeeded.
    bandlight::cli::StderrCapture capture;
    ConfigureOcio();
    CLI::App app{
        "bandlight: the 3-band model of coloured light and surfaces, measured against an exact "
        "spectral core"};
    app.require_subcommand(1);
    app.set_version_flag("--version", std::string("bandlight ") + bandlight::defaults::VERSION);
    AddCommands(app);
    try
    {
        app.parse(argc, argv);
    }
    catch (...)
    {
        return ExitFor(app, argc, argv, capture);
    }
    std::cout.flush();
    capture.finish(true, "");
    return 0;
}
