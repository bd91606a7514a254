// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

namespace bandlight::cli
{

/// Runs a gnuplot script that draws into `output` (.png or .svg, chosen by
/// extension): the script is given the terminal and the output file (a
/// temporary name in the destination folder, renamed when gnuplot has
/// succeeded, so a failed plot leaves the previous one intact). Data the
/// script needs go in `data`, written to a temporary file whose path
/// replaces every "$DATA" in the script. Throws Exception with gnuplot's
/// message on failure, or when gnuplot is not installed.
void RunGnuplot(const std::string& script, const std::string& data, const std::string& output);

}  // namespace bandlight::cli
