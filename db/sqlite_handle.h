#pragma once
// Thin RAII over the SQLite C API: a connection and prepared statements that throw DbError with
// SQLite's message and the SQL involved.

#include <sqlite3.h>

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "records/table.h"

namespace shockmap {

class DbError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Statement;

// One SQL value: NULL, integer, real or text.
using SqlValue = TableCell;

// True when a read-only connection to `path` may treat the file as immutable: its file system
// is mounted read-only, or this process may not write the file or its folder and no -wal file
// (the mark of a writer in WAL mode) lies beside it.
bool OpensImmutable(const std::string& path);

// The name SQLite gives a database in memory, which no file holds and closing loses.
inline constexpr std::string_view kInMemoryDatabaseName = ":memory:";

class Connection {
 public:
  // kInMemory: a scratch database of this process (path kInMemoryDatabaseName), never a
  // study's.
  enum class Mode { kReadWriteCreate, kReadOnly, kInMemory };
  // Opens `path`. Throws DbError naming the path when it cannot be opened: before SQLite
  // touches anything when the path is not a regular file (a FIFO, a device, a folder), names
  // the database in memory outside kInMemory (a study stored there would be lost) or, for a
  // read-only connection, names nothing; for a writer, when the file or its folder is on a
  // read-only file system or not writable, naming which. A read-only connection never creates
  // the file and sets PRAGMA query_only; where nothing can write the file (see OpensImmutable)
  // it opens it immutable, so that SQLite neither locks it nor creates -wal or -shm files
  // beside it.
  Connection(const std::string& path, Mode mode);
  ~Connection();
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;

  // Runs one or more statements without results.
  void Execute(std::string_view sql);
  Statement Prepare(std::string_view sql);
  // The statement of `sql` prepared once for the connection's life and reset (bindings
  // cleared) on every call: for the writer's statements run once per stored point. The
  // reference is valid until the connection closes; one use at a time.
  Statement& Cached(std::string_view sql);
  std::int64_t LastInsertRowId() const;
  const std::string& Path() const { return path_; }
  sqlite3* Raw() const { return db_; }

 private:
  std::string path_;
  sqlite3* db_ = nullptr;
  std::map<std::string, std::unique_ptr<Statement>, std::less<>> cached_;
};

// A prepared statement. Bind parameters are 1-based as in SQLite.
class Statement {
 public:
  Statement(sqlite3* db, sqlite3_stmt* stmt, std::string sql);
  ~Statement();
  Statement(Statement&& other) noexcept;
  Statement& operator=(Statement&&) = delete;
  Statement(const Statement&) = delete;

  Statement& Bind(int i, double v);
  Statement& Bind(int i, std::int64_t v);
  Statement& Bind(int i, int v) { return Bind(i, static_cast<std::int64_t>(v)); }
  Statement& Bind(int i, std::string_view v);
  Statement& Bind(int i, const char* v) { return Bind(i, std::string_view(v)); }
  // The doubles as a blob (an empty vector: an empty blob, not NULL).
  Statement& Bind(int i, const std::vector<double>& blob);
  Statement& BindNull(int i);
  Statement& BindValue(int i, const SqlValue& v);
  // Binds `values` to ?1, ?2, ... in order.
  template <typename... T>
  Statement& BindAll(const T&... values) {
    int i = 0;
    (Bind(++i, values), ...);
    return *this;
  }
  template <typename T>
  Statement& Bind(int i, const std::optional<T>& v) {
    return v ? Bind(i, *v) : BindNull(i);
  }

  // Advances; true while a row is available.
  bool Step();
  // Runs a statement without results to completion.
  void Run();
  void Reset();

  int ColumnCount() const;
  std::string ColumnName(int i) const;
  bool IsNull(int i) const;
  int ColumnType(int i) const;
  double GetDouble(int i) const;
  std::int64_t GetInt(int i) const;
  std::string GetText(int i) const;
  std::optional<double> GetOptionalDouble(int i) const;
  // A blob of little-endian float64 values; DbError when its size is not a multiple of 8.
  std::vector<double> GetBlob(int i) const;
  // Reads the current row's columns 0, 1, ... into `out` in order, each by its type (double,
  // std::int64_t, int, std::string, std::optional<double> or a blob of doubles).
  template <typename... T>
  void ReadColumns(T&... out) const {
    int i = 0;
    (ReadColumn(i++, out), ...);
  }
  // Reads column i of the current row into `v` by its type; an optional is empty for NULL.
  void ReadColumn(int i, double& v) const { v = GetDouble(i); }
  void ReadColumn(int i, std::int64_t& v) const { v = GetInt(i); }
  void ReadColumn(int i, int& v) const { v = static_cast<int>(GetInt(i)); }
  void ReadColumn(int i, std::string& v) const { v = GetText(i); }
  void ReadColumn(int i, std::vector<double>& v) const { v = GetBlob(i); }
  template <typename T>
  void ReadColumn(int i, std::optional<T>& v) const {
    if (IsNull(i)) {
      v.reset();
    } else {
      ReadColumn(i, v.emplace());
    }
  }
  // True when the statement cannot modify the database (sqlite3_stmt_readonly).
  bool IsReadOnly() const;

 private:
  void Check(int rc) const;
  sqlite3* db_;
  sqlite3_stmt* stmt_;
  std::string sql_;
};

// BEGIN IMMEDIATE ... COMMIT, rolled back if destroyed before Commit().
class Transaction {
 public:
  explicit Transaction(Connection& c);
  ~Transaction();
  void Commit();

 private:
  Connection& c_;
  bool done_ = false;
};

}  // namespace shockmap
