// SPDX-License-Identifier: BSD-3-Clause
// bandlight: spectral data → band-model tables, colorimetry and (later) OCIO
// transforms. Exit codes: 0 success, 2 bad input (one line on stderr), 1
// anything unexpected.
#include <iostream>

#include <OpenColorIO/OpenColorIO.h>

#include "cli/Commands.h"
#include "spectral/AtomicFile.h"
#include "spectral/Exception.h"

int main(int argc, char** argv)
{
    // An interrupted run leaves every previous output as it was, and no
    // temporary files behind.
    bandlight::RemoveTemporaryFilesOnInterrupt();
    CLI::App app{
        "bandlight: the 3-band model of coloured light and surfaces, measured against an exact "
        "spectral core"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "bandlight 0.1.0");
    bandlight::cli::AddTablesCommand(app);
    bandlight::cli::AddXyzCommand(app);
    bandlight::cli::AddCriCommand(app);
    bandlight::cli::AddConfigCommand(app);
    bandlight::cli::AddLutCommand(app);
    bandlight::cli::AddApplyCommand(app);
    bandlight::cli::AddPackageCommand(app);
    bandlight::cli::AddAccuracyCommand(app);
    bandlight::cli::AddPlotCommand(app);
    bandlight::cli::AddRenderCommand(app);
    try
    {
        app.parse(argc, argv);
    }
    catch (const CLI::CallForHelp& e)
    {
        return app.exit(e);
    }
    catch (const CLI::CallForAllHelp& e)
    {
        return app.exit(e);
    }
    catch (const CLI::CallForVersion& e)
    {
        return app.exit(e);
    }
    catch (const CLI::ParseError& e)
    {
        std::cerr << "bandlight: " << e.what() << "\n";
        return 2;
    }
    catch (const bandlight::Exception& e)
    {
        std::cerr << "bandlight: " << e.what() << "\n";
        return 2;
    }
    catch (const OCIO_NAMESPACE::Exception& e)
    {
        // OpenColorIO's own messages name the file and what is wrong with it.
        std::cerr << "bandlight: " << e.what() << "\n";
        return 2;
    }
    catch (const std::exception& e)
    {
        std::cerr << "bandlight: internal error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
