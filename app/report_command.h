#pragma once
// `shockmap report`: the HTML report of a stored study (views/html_report.h), with the runs it
// shows beside the stored results (the Fig. 3 of chosen points, a scene study's contact-force
// maps) computed here.

#include <CLI/CLI.hpp>

namespace shockmap {

void AddReportCommand(CLI::App& app);

}  // namespace shockmap
