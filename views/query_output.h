#pragma once
// Query results as an aligned table, CSV (RFC 4180) or a JSON array of objects.

#include <optional>
#include <ostream>
#include <string>
#include <string_view>

#include "db/read_only_query.h"

namespace shockmap {

enum class QueryFormat { kTable, kCsv, kJson };
std::string ToString(QueryFormat f);
std::optional<QueryFormat> QueryFormatFromString(std::string_view s);

void WriteQueryResult(const QueryResult& result, QueryFormat format, std::ostream& out);

}  // namespace shockmap
