#include "db/stored_json.h"

namespace shockmap {

void ThrowCorruptCell(const StoredCell& cell, const std::string& reason) {
  // nlohmann's messages begin with their id: "[json.exception.type_error.302] ...".
  const auto id_end = reason.rfind("] ", reason.find(' '));
  ThrowCorrupt(
      cell.database_path, cell.row,
      cell.column + ": " +
          (reason.starts_with("[json.") && id_end != std::string::npos ? reason.substr(id_end + 2)
                                                                       : reason));
}

nlohmann::json ParseStoredJson(const StoredCell& cell, const std::string& text) {
  const auto limit_depth = [&cell](int depth, nlohmann::json::parse_event_t, nlohmann::json&) {
    if (depth > kMaxStoredJsonDepth) {
      ThrowCorruptCell(cell,
                       "nested deeper than " + std::to_string(kMaxStoredJsonDepth) + " levels");
    }
    return true;
  };
  try {
    return nlohmann::json::parse(text, limit_depth);
  } catch (const nlohmann::json::exception& e) {
    ThrowCorruptCell(cell, e.what());
  }
}

}  // namespace shockmap
