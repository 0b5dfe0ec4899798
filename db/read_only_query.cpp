#include "db/read_only_query.h"

#include <cctype>
#include <filesystem>

#include "db/schema.h"
#include "db/sqlite_handle.h"

namespace shockmap {

QueryResult RunReadOnlyQuery(const std::string& database_path, const std::string& sql,
                             const std::vector<std::string>& text_parameters) {
  if (!std::filesystem::is_regular_file(database_path)) {
    throw DbError("no database at " + database_path);
  }
  Connection db(database_path, Connection::Mode::kReadOnly);
  CheckSchema(db);
  sqlite3_stmt* raw = nullptr;
  const char* tail = nullptr;
  if (sqlite3_prepare_v2(db.Raw(), sql.c_str(), static_cast<int>(sql.size()), &raw, &tail) !=
      SQLITE_OK) {
    throw DbError(std::string("SQL error: ") + sqlite3_errmsg(db.Raw()));
  }
  Statement statement(db.Raw(), raw, sql);
  if (raw == nullptr) throw DbError("empty SQL");
  for (const char* c = tail; c != nullptr && *c != '\0'; ++c) {
    if (!std::isspace(static_cast<unsigned char>(*c)) && *c != ';') {
      throw DbError("one statement at a time: found more after the first");
    }
  }
  if (!statement.IsReadOnly()) {
    throw DbError("refused: the statement would modify the database; shockmap query is read-only");
  }
  for (std::size_t i = 0; i < text_parameters.size(); ++i) {
    statement.Bind(static_cast<int>(i + 1), text_parameters[i]);
  }
  QueryResult result;
  for (int i = 0; i < statement.ColumnCount(); ++i)
    result.columns.push_back(statement.ColumnName(i));
  while (statement.Step()) {
    std::vector<QueryCell> row;
    for (int i = 0; i < statement.ColumnCount(); ++i) {
      switch (statement.ColumnType(i)) {
        case SQLITE_NULL:
          row.emplace_back(std::monostate{});
          break;
        case SQLITE_INTEGER:
          row.emplace_back(statement.GetInt(i));
          break;
        case SQLITE_FLOAT:
          row.emplace_back(statement.GetDouble(i));
          break;
        case SQLITE_BLOB:
          row.emplace_back("<blob " + std::to_string(statement.GetBlob(i).size()) + " doubles>");
          break;
        default:
          row.emplace_back(statement.GetText(i));
      }
    }
    result.rows.push_back(std::move(row));
  }
  return result;
}

}  // namespace shockmap
