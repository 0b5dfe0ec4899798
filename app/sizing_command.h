#pragma once
// `shockmap sizing`: the sizing statistics of an ensemble study (docs/ensembles.md).

#include <CLI/CLI.hpp>
#include <string>

#include "core/scene.h"
#include "db/ensemble_members.h"

namespace shockmap {

void AddSizingCommand(CLI::App& app);

// The scene of ensemble `study` as stored with it (its zones in the stored order). Throws
// InputError naming the database and the study when it does not parse.
Scene StoredEnsembleScene(const StoredEnsemble& stored, const std::string& database_path,
                          const std::string& study);

}  // namespace shockmap
