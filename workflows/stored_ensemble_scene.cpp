#include "workflows/stored_ensemble_scene.h"

#include <nlohmann/json.hpp>

#include "db/stored_json.h"
#include "formats/scene_file.h"

namespace shockmap {

Scene StoredEnsembleScene(const StoredEnsemble& stored, const std::string& database_path,
                          const std::string& study) {
  return ReadStoredJson({database_path, "study " + study, "spec_json"}, stored.spec_json,
                        [&](const nlohmann::json& spec) {
                          return ParseScene(spec.at("scene_json"),
                                            database_path + ": scene of study " + study);
                        });
}

}  // namespace shockmap
