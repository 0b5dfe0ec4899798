#include "specs/study_file.h"

#include "core/input_error.h"
#include "formats/json_reader.h"

namespace shockmap {

std::string ToString(StudyFileKind kind) {
  switch (kind) {
    case StudyFileKind::kSceneSweep:
      return "scene_sweep";
    case StudyFileKind::kSceneEnsemble:
      return "scene_ensemble";
    case StudyFileKind::kCanonical:
      break;
  }
  return "canonical";
}

StudyFileKind StudyFileKindFromString(std::string_view text, const std::string& file) {
  for (StudyFileKind k :
       {StudyFileKind::kCanonical, StudyFileKind::kSceneSweep, StudyFileKind::kSceneEnsemble}) {
    if (text == ToString(k)) return k;
  }
  FailAt(file, "kind",
         "unknown study kind \"" + std::string(text) +
             "\"; allowed: canonical, scene_sweep, scene_ensemble");
}

StudyFileKind StudyKindOf(const nlohmann::json& study, const std::string& file) {
  if (!study.is_object()) FailAt(file, "", "expected a JSON object, got " + Shown(study));
  const auto kind = study.find("kind");
  if (kind == study.end()) {
    return study.contains("scene") ? StudyFileKind::kSceneSweep : StudyFileKind::kCanonical;
  }
  if (!kind->is_string()) FailAt(file, "kind", "expected a string, got " + Shown(*kind));
  return StudyFileKindFromString(kind->get<std::string>(), file);
}

std::map<std::string, double, std::less<>> StudyThresholds(const nlohmann::json& study,
                                                           const std::string& file) {
  std::map<std::string, double, std::less<>> thresholds = DefaultThresholds();
  const StudyFileKind kind = StudyKindOf(study, file);
  const auto scoring = study.find("scoring");
  if (kind == StudyFileKind::kSceneEnsemble || scoring == study.end()) return thresholds;
  JsonObjectReader s(*scoring, file, "scoring");
  if (kind == StudyFileKind::kSceneSweep) {
    ReadThresholds(s, thresholds);
  } else if (const nlohmann::json* given = s.Get("thresholds")) {
    JsonObjectReader t(*given, file, s.PathOf("thresholds"));
    ReadThresholds(t, thresholds);
  }
  return thresholds;
}

StudyFile ParseStudyFile(const nlohmann::json& json, const std::string& file,
                         const SceneFileAccess& access) {
  switch (StudyKindOf(json, file)) {
    case StudyFileKind::kSceneSweep:
      return ParseSceneStudySpec(json, file, access);
    case StudyFileKind::kSceneEnsemble:
      return ParseEnsembleStudySpec(json, file, access);
    case StudyFileKind::kCanonical:
      break;
  }
  return ParseStudySpec(json, file);
}

StudyFile ReadStudyFile(const std::string& path, const SceneFileAccess& access) {
  return ParseStudyFile(ReadJsonFile(path), path, access);
}

}  // namespace shockmap
