// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <CLI/CLI.hpp>

namespace bandlight::cli
{

/// Each command registers its subcommand and the callback that runs it.
void AddTablesCommand(CLI::App& app);
void AddXyzCommand(CLI::App& app);
void AddCriCommand(CLI::App& app);
void AddQualityCommand(CLI::App& app);
void AddIdtCommand(CLI::App& app);
void AddConfigCommand(CLI::App& app);
void AddLutCommand(CLI::App& app);
void AddApplyCommand(CLI::App& app);
void AddPackageCommand(CLI::App& app);
void AddAccuracyCommand(CLI::App& app);
void AddPlotCommand(CLI::App& app);
void AddRenderCommand(CLI::App& app);
void AddSpectralCommand(CLI::App& app);
void AddMethodsCommand(CLI::App& app);
void AddWallCommand(CLI::App& app);

}  // namespace bandlight::cli
