#include "db/read_only_query.h"

#include <cctype>
#include <chrono>
#include <cstdio>

#include "db/schema.h"

namespace shockmap {
namespace {

using Clock = std::chrono::steady_clock;

// Virtual machine instructions between two looks at the clock.
constexpr int kProgressPeriod = 10000;

struct Deadline {
  Clock::time_point end;
  bool reached = false;
};

int StopAtDeadline(void* context) {
  auto* deadline = static_cast<Deadline*>(context);
  deadline->reached = deadline->reached || Clock::now() >= deadline->end;
  return deadline->reached ? 1 : 0;
}

// The one statement of `sql`, checked to be alone and read-only.
Statement PrepareOne(Connection& db, const std::string& sql) {
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
  return statement;
}

TableCell Cell(const Statement& statement, int i) {
  switch (statement.ColumnType(i)) {
    case SQLITE_NULL:
      return std::monostate{};
    case SQLITE_INTEGER:
      return statement.GetInt(i);
    case SQLITE_FLOAT:
      return statement.GetDouble(i);
    case SQLITE_BLOB:
      return "<blob " + std::to_string(statement.GetBlob(i).size()) + " doubles>";
    default:
      return statement.GetText(i);
  }
}

// Steps once; throws QueryLimitReached when the deadline interrupted the step.
bool Step(Statement& statement, const Deadline& deadline, double timeout_s) {
  try {
    return statement.Step();
  } catch (const DbError&) {
    if (!deadline.reached) throw;
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%g", timeout_s);
    throw QueryLimitReached(std::string("the statement ran longer than the time limit of ") +
                            seconds + " s and was stopped");
  }
}

class Collector : public TableSink {
 public:
  explicit Collector(Table& result) : result_(result) {}
  void Columns(const std::vector<std::string>& names) override { result_.columns = names; }
  void Row(const std::vector<TableCell>& row) override { result_.rows.push_back(row); }

 private:
  Table& result_;
};

}  // namespace

void StreamReadOnlyQuery(const std::string& database_path, const std::string& sql,
                         const std::vector<TableCell>& parameters, const QueryLimits& limits,
                         TableSink& sink) {
  Connection db(database_path, Connection::Mode::kReadOnly);
  CheckSchema(db);
  Statement statement = PrepareOne(db, sql);
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    statement.BindValue(static_cast<int>(i + 1), parameters[i]);
  }
  Deadline deadline{Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                       std::chrono::duration<double>(limits.timeout_s))};
  if (limits.timeout_s > 0) {
    sqlite3_progress_handler(db.Raw(), kProgressPeriod, StopAtDeadline, &deadline);
  }
  std::vector<std::string> columns;
  for (int i = 0; i < statement.ColumnCount(); ++i) columns.push_back(statement.ColumnName(i));
  sink.Columns(columns);
  std::vector<TableCell> row(columns.size());
  for (std::int64_t n = 0; Step(statement, deadline, limits.timeout_s); ++n) {
    if (limits.max_rows > 0 && n == limits.max_rows) {
      throw QueryLimitReached("the result has more than the row limit of " +
                              std::to_string(limits.max_rows) + " rows; stopped there");
    }
    for (int i = 0; i < statement.ColumnCount(); ++i) row[i] = Cell(statement, i);
    sink.Row(row);
  }
}

Table RunReadOnlyQuery(const std::string& database_path, const std::string& sql,
                       const std::vector<TableCell>& parameters) {
  Table result;
  Collector collector(result);
  StreamReadOnlyQuery(database_path, sql, parameters, {}, collector);
  return result;
}

}  // namespace shockmap
