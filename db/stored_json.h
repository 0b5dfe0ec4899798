#pragma once
// JSON stored in a study database, read back. A cell that is not JSON, nests deeper than
// kMaxStoredJsonDepth or has another shape than its reader expects is DbError "<file>: database
// corrupt: <row>: <column>: <reason>", never an exception of the JSON library.

#include <nlohmann/json.hpp>
#include <string>

#include "db/corrupt_rows.h"

namespace shockmap {

// Deeper than any JSON shockmap stores; deeper documents would exhaust the stack of the
// recursive code that copies, prints and destroys them.
inline constexpr int kMaxStoredJsonDepth = 64;

// Where a stored JSON text comes from: "ensemble reference 3", "zones_json".
struct StoredCell {
  std::string database_path, row, column;
};

// Throws DbError "<file>: database corrupt: <row>: <column>: <reason>".
[[noreturn]] void ThrowCorruptCell(const StoredCell& cell, const std::string& reason);

nlohmann::json ParseStoredJson(const StoredCell& cell, const std::string& text);

// What `read` makes of the parsed text; the JSON library's errors while it reads (a missing key,
// a wrong type) are DbError as well.
template <typename Read>
auto ReadStoredJson(const StoredCell& cell, const std::string& text, Read read) {
  const nlohmann::json json = ParseStoredJson(cell, text);
  try {
    return read(json);
  } catch (const nlohmann::json::exception& e) {
    ThrowCorruptCell(cell, e.what());
  }
}

}  // namespace shockmap
