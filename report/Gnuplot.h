// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "spectral/AtomicFile.h"

namespace bandlight
{

/// `text` as a gnuplot string literal that gnuplot prints but never
/// evaluates, whatever the text holds. gnuplot evaluates backquotes (`cmd`)
/// and escapes inside double quotes, and a newline ends its command in the
/// middle of any string; inside single quotes only `'` is special (written
/// `''`) and neither `@` macros nor backquotes are expanded. So the literal
/// is single-quoted, `'` is doubled, and every control character (newline,
/// CR, tab, DEL, ...) is shown as a visible `\xNN` — text taken from files
/// and file names never reaches gnuplot's command parser as code.
std::string GnuplotQuote(const std::string& text);

/// A label for a gnuplot data file (read with `with labels` or
/// `columnheader`): double-quoted for the data reader, which evaluates
/// nothing; `"`, `\` and control characters are shown as `\xNN`.
std::string GnuplotDataLabel(const std::string& text);

/// Refuses (ParameterError) a plot path that is not a .png or .svg file:
/// the format follows the extension (case-insensitive).
void CheckPlotPath(const std::string& output);

/// Runs a gnuplot script that draws into `output` (.png or .svg, chosen by
/// extension): the script is given the terminal and the output file (a
/// temporary name in the destination folder, renamed when gnuplot has
/// succeeded, so a failed plot leaves the previous one intact). Data the
/// script needs go in `data`, which the script sees as the datablock
/// `$bandlight_data` (`plot $bandlight_data index 0 ...`); data lines hold
/// numbers and GnuplotDataLabel() strings only, so no line of them can end
/// the block. Every string in `script` that comes
/// from outside the program must have gone through GnuplotQuote().
///
/// gnuplot is started directly (fork and exec, no shell), writes the image
/// to its standard output (so no path is ever written into a script), its text
/// rendering is not "enhanced" (so `^`, `_`, `@`, `{}` in names print as
/// they are), and an interrupt (SIGINT, SIGTERM, SIGHUP) stops it and
/// removes every temporary file. Throws Exception with gnuplot's last
/// message on failure, or when gnuplot is not installed.
/// With `outputs`, the image joins that set of outputs (the caller commits).
/// The image is `width` × `height` pixels (an SVG's size in points).
struct PlotSize
{
    int width = 1000;
    int height = 650;
};
void RunGnuplot(const std::string& script, const std::string& data, const std::string& output,
                OutputSet* outputs = nullptr, PlotSize size = {});

}  // namespace bandlight
