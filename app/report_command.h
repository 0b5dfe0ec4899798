#pragma once
// `shockmap report`: the HTML report of a stored study (workflows/study_report.h).

#include <CLI/CLI.hpp>

namespace shockmap {

void AddReportCommand(CLI::App& app);

}  // namespace shockmap
