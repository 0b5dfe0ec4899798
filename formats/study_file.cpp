#include "formats/study_file.h"

#include "core/input_error.h"
#include "formats/json_reader.h"

namespace shockmap {

std::string ToString(StudyFileKind kind) {
  return kind == StudyFileKind::kSceneSweep ? "scene_sweep" : "canonical";
}

StudyFileKind StudyFileKindFromString(std::string_view text, const std::string& file) {
  for (StudyFileKind k : {StudyFileKind::kCanonical, StudyFileKind::kSceneSweep}) {
    if (text == ToString(k)) return k;
  }
  FailAt(file, "kind",
         "unknown study kind \"" + std::string(text) + "\"; allowed: canonical, scene_sweep");
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

StudyFile ParseStudyFile(const nlohmann::json& json, const std::string& file,
                         const SceneFileAccess& access) {
  if (StudyKindOf(json, file) == StudyFileKind::kSceneSweep) {
    return ParseSceneStudySpec(json, file, access);
  }
  return ParseStudySpec(json, file);
}

StudyFile ReadStudyFile(const std::string& path, const SceneFileAccess& access) {
  return ParseStudyFile(ReadJsonFile(path), path, access);
}

}  // namespace shockmap
