#pragma once
// Runs gnuplot on a script; every plot of the project goes through here, and every piece of text
// that enters a script (titles, labels, file names) goes through GnuplotQuoted.

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace shockmap {

// gnuplot is missing, failed or was killed: not the user's input, exit code 1.
class PlotError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "pngcairo size W,H ..." or "svg size W,H ...": the gnuplot terminal for a file's extension.
// Throws InputError for any other extension, and for a name GnuplotFileName refuses: called
// first, it refuses an image before any of its files or folders is made.
std::string TerminalFor(const std::filesystem::path& file, int width, int height);

// `text` as a gnuplot string literal that stays data: single-quoted (where gnuplot expands
// nothing), each ' doubled, and line breaks and other control characters, which such a string
// cannot hold, replaced by spaces.
std::string GnuplotQuoted(std::string_view text);

// The literal naming `file` in a script run from file's own folder (see RunGnuplot): "./" and
// its name, quoted, so that no name reads as a command ('|cmd', '<cmd'). Throws InputError when the
// name holds a control character, which no gnuplot string can carry.
std::string GnuplotFileName(const std::filesystem::path& file);

// The file name for the `set output` of a script that draws `image`: a temporary file of
// RunGnuplot's choosing when RunGnuplot runs the script, `image` (as GnuplotFileName) when
// someone runs it by hand.
std::string GnuplotOutputName(const std::filesystem::path& image);

// "set xtics (...)" (axis "x") or "set ytics (...)": one tick per value, in ascending order,
// labelled with 4 significant digits; x labels are turned so that close values stay legible.
std::string GnuplotTics(const char* axis, std::vector<double> values);

// Writes `script` to script_file (in full or not at all) and runs gnuplot on it from the
// script's folder, without a shell: its file names are relative to that folder. `image` is the
// file the script draws, naming it by GnuplotOutputName: gnuplot draws a temporary file that is
// renamed over `image` once complete, so that an image already there is replaced only by a
// whole one, and a signal ending the process leaves neither (formats/signal_cleanup.h).
// Throws PlotError when gnuplot is not found, ends with a non-zero status or a signal (quoting
// what it printed), or ends without writing `image`; InputError when it wrote only part of the
// image (gnuplot exits 0 on a full disk), as for any output file that could not be written.
void RunGnuplot(const std::string& script, const std::filesystem::path& script_file,
                const std::filesystem::path& image);

}  // namespace shockmap
