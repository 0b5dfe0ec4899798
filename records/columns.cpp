#include "records/columns.h"

namespace shockmap {

std::string_view ToString(SqlType type) {
  switch (type) {
    case SqlType::kInteger:
      return "INTEGER";
    case SqlType::kReal:
      return "REAL";
    case SqlType::kText:
      return "TEXT";
    case SqlType::kBlob:
      return "BLOB";
  }
  return "BLOB";
}

}  // namespace shockmap
