#include "studies/gnuplot.h"

#include <cstdlib>
#include <fstream>
#include <stdexcept>

namespace shockmap {

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
