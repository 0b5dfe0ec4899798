#include "formats/parameter_path.h"

#include <algorithm>

#include "formats/json_reader.h"

namespace shockmap {
namespace {

using Json = nlohmann::json;

[[noreturn]] void FailPath(const std::string& path, const std::string& file,
                           const std::string& where) {
  FailAt(file, where,
         "\"" + path +
             "\" is not a parameter path: use keys joined by dots, with [i] for list "
             "items (at most 9 digits), e.g. \"solver.r_ftrunc\" "
             "or \"zones[0].gap_m\"");
}

// A study sets the scene's end time (its window) and its outputs (what it records) itself, so
// a value of its own there would be overridden and every "different" run would be the same.
void CheckStudyMayVary(const Json::json_pointer& pointer, const std::string& path,
                       const std::string& file, const std::string& where) {
  if (pointer == Json::json_pointer("/solver/end_time_s")) {
    FailAt(file, where,
           "\"" + path +
               "\" cannot be varied: the study runs every point to its window (\"window_s\"), "
               "which would override each value");
  }
  if (!pointer.empty() && pointer.to_string().starts_with("/outputs/")) {
    FailAt(file, where,
           "\"" + path +
               "\" cannot be varied: the study chooses what a run records, which would override "
               "each value");
  }
}

Json::json_pointer PointerOf(const std::string& path, const std::string& file,
                             const std::string& where) {
  const auto pointer = ParameterPointer(path);
  if (!pointer) FailPath(path, file, where);
  return *pointer;
}

void CheckNumberAt(const Json& scene, const Json::json_pointer& pointer, const std::string& path,
                   const std::string& file, const std::string& where) {
  if (!scene.contains(pointer) || !scene.at(pointer).is_number()) {
    FailAt(file, where,
           "the scene has no number at \"" + path +
               "\"; only numbers the scene file sets can be swept (write the default there)");
  }
}

// A list index longer than this could overflow the JSON pointer's index type, which the JSON
// library reports by throwing from contains() instead of answering false. An index is written
// [i] or as a segment of its own ("zones.0.gap_m"), so both are bounded.
constexpr std::size_t kMaxIndexDigits = 9;

bool IsIndex(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), ::isdigit);
}

}  // namespace

std::optional<Json::json_pointer> ParameterPointer(const std::string& path) {
  std::string pointer;
  std::size_t start = 0;
  while (start <= path.size()) {
    const std::size_t dot = std::min(path.find('.', start), path.size());
    std::string segment = path.substr(start, dot - start);
    std::string index;
    if (const auto open = segment.find('['); open != std::string::npos) {
      if (segment.back() != ']' || open == 0) return std::nullopt;
      index = segment.substr(open + 1, segment.size() - open - 2);
      segment.resize(open);
      if (!IsIndex(index) || index.size() > kMaxIndexDigits) return std::nullopt;
    }
    if (segment.empty() || segment.find_first_of("/~]") != std::string::npos ||
        (IsIndex(segment) && segment.size() > kMaxIndexDigits)) {
      return std::nullopt;
    }
    pointer += "/" + segment;
    if (!index.empty()) pointer += "/" + index;
    start = dot + 1;
  }
  return Json::json_pointer(pointer);
}

Json::json_pointer NumericParameter(const Json& scene, const std::string& path,
                                    const std::string& file, const std::string& where) {
  const Json::json_pointer pointer = PointerOf(path, file, where);
  CheckStudyMayVary(pointer, path, file, where);
  CheckNumberAt(scene, pointer, path, file, where);
  return pointer;
}

Json::json_pointer SceneParameter(const Json& scene, const std::string& path, const Json& value,
                                  const std::string& file, const std::string& where) {
  const Json::json_pointer pointer = PointerOf(path, file, where);
  if (value.is_number()) {
    CheckNumberAt(scene, pointer, path, file, where);
    return pointer;
  }
  if (!value.is_boolean()) {
    FailAt(file, where, "expected a number or true/false, got " + Shown(value));
  }
  if (!scene.contains(pointer) || !scene.at(pointer).is_boolean()) {
    FailAt(file, where,
           "the scene has no true/false at \"" + path +
               "\"; only values the scene file sets can be set (write the default there)");
  }
  return pointer;
}

Json::json_pointer SameTypeParameter(const Json& scene, const std::string& path, const Json& value,
                                     const std::string& file, const std::string& where) {
  CheckStudyMayVary(PointerOf(path, file, where), path, file, where);
  return SceneParameter(scene, path, value, file, where);
}

}  // namespace shockmap
