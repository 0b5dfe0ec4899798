#pragma once
// The scene an ensemble study was run on, read back from its stored study file: what `sizing`
// and the report draw its zones on.

#include <string>

#include "core/scene.h"
#include "db/ensemble_members.h"

namespace shockmap {

// The scene of ensemble `study` as stored with it (its zones in the stored order). Throws
// InputError naming the database and the study when it does not parse.
Scene StoredEnsembleScene(const StoredEnsemble& stored, const std::string& database_path,
                          const std::string& study);

}  // namespace shockmap
