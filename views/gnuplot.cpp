#include "views/gnuplot.h"

#include <fmt/format.h>

#include <cstdlib>
#include <fstream>
#include <stdexcept>

#include "core/input_error.h"

namespace shockmap {

std::string TerminalFor(const std::filesystem::path& file, int width, int height) {
  if (file.extension() == ".svg") {
    return fmt::format("svg size {},{} dynamic font 'DejaVu Sans,12' background '#ffffff'", width,
                       height);
  }
  if (file.extension() == ".png") {
    return fmt::format("pngcairo size {},{} font 'DejaVu Sans,11'", width, height);
  }
  throw InputError(file.string() + ": the plot file must end in .png or .svg");
}

void RunGnuplot(const std::string& script, const std::filesystem::path& script_file) {
  {
    std::ofstream out(script_file);
    out << script;
    if (!out) throw std::runtime_error("cannot write " + script_file.string());
  }
  const std::string command = "gnuplot '" + script_file.string() + "' 2>&1";
  const int status = std::system(command.c_str());
  if (status != 0) {
    throw std::runtime_error("gnuplot failed on " + script_file.string() + " (status " +
                             std::to_string(status) + "); is gnuplot installed?");
  }
}

}  // namespace shockmap
