#include "db/sqlite_handle.h"

#include <sys/statvfs.h>
#include <unistd.h>

#include <algorithm>
#include <cassert>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace shockmap {
namespace {

// How long a writer waits for another writer's lock before giving up.
constexpr int kBusyTimeout_ms = 10000;

// SQLite's message, with the system's reason behind a failed read or write of the file ("File
// too large" past the file-size limit, "Read-only file system") and what "busy" and a journal
// left by a killed writer mean for the user.
std::string Describe(sqlite3* db) {
  std::string message = sqlite3_errmsg(db);
  const int primary = sqlite3_extended_errcode(db) & 0xff;
  const int system_error = sqlite3_system_errno(db);
  if (system_error != 0 && (primary == SQLITE_IOERR || primary == SQLITE_FULL ||
                            primary == SQLITE_CANTOPEN || primary == SQLITE_READONLY)) {
    message += " (" + std::string(std::strerror(system_error)) + ")";
  }
  if ((sqlite3_extended_errcode(db) & 0xff) == SQLITE_BUSY) {
    message += " by another writer (waited " + std::to_string(kBusyTimeout_ms / 1000) +
               " s); nothing was written, run again once it is done";
  }
  if (sqlite3_extended_errcode(db) == SQLITE_READONLY_ROLLBACK) {
    message +=
        ": a run was killed while it wrote this file (as when it created the database) and left "
        "its rollback journal, which a reader cannot roll back; a command that writes the "
        "database (`shockmap study run STUDY_FILE --db` this file) rolls it back, losing "
        "nothing committed";
  }
  return message;
}

// `path` as a file: URI (https://sqlite.org/uri.html) for a read-only, maybe immutable, open.
std::string ReadOnlyUri(const std::string& path) {
  std::string uri = path.starts_with('/') ? "file://" : "file:";
  for (unsigned char c : path) {
    if (c == '%' || c == '?' || c == '#' || c < 0x20 || c >= 0x7f) {
      char hex[4];
      std::snprintf(hex, sizeof hex, "%%%02X", c);
      uri += hex;
    } else {
      uri += static_cast<char>(c);
    }
  }
  return uri + (OpensImmutable(path) ? "?mode=ro&immutable=1" : "?mode=ro");
}

// Throws unless `file` (the database at `path`, or a file SQLite keeps beside it) is a regular
// file or, unless `must_exist`, absent.
void CheckRegularOrAbsent(const std::string& path, const std::string& file, bool must_exist) {
  std::error_code ec;
  const auto type = std::filesystem::status(file, ec).type();
  if (type == std::filesystem::file_type::regular) return;
  if (type == std::filesystem::file_type::not_found) {
    if (must_exist) throw DbError("no database at " + path);
    return;
  }
  if (ec) throw DbError("cannot open database " + path + ": " + file + ": " + ec.message());
  throw DbError("cannot open database " + path + ": " +
                (file == path ? "not a regular file (a study database is a regular file)"
                              : file + " is not a regular file (SQLite keeps its journal there)") +
                "; nothing was opened");
}

// Throws unless `path` names a regular file (or nothing yet, when a writer may create it) and
// each file SQLite keeps beside it is a regular file or absent: SQLite would block for ever
// opening a FIFO, and write a -journal beside a device. The database in memory is a file only
// in kInMemory, and only it.
void CheckIsDatabaseFile(const std::string& path, Connection::Mode mode) {
  if (mode == Connection::Mode::kInMemory) {
    assert(path == kInMemoryDatabaseName);
    return;
  }
  if (path == kInMemoryDatabaseName) {
    throw DbError("cannot open database " + path +
                  ": it names SQLite's database in memory, which keeps nothing once closed; a "
                  "study database is a file (./:memory: for a file of that name); nothing was "
                  "opened");
  }
  CheckRegularOrAbsent(path, path, mode == Connection::Mode::kReadOnly);
  for (const char* beside : {"-journal", "-wal", "-shm"}) {
    CheckRegularOrAbsent(path, path + beside, false);
  }
}

// The folder holding `path`, where SQLite also keeps its journal.
std::string FolderOf(const std::string& path) {
  return path.find('/') == std::string::npos
             ? std::string(".")
             : path.substr(0, std::max<std::size_t>(path.rfind('/'), 1));
}

// Throws, naming the place, unless a writer may write `path` (when it exists) and its folder (its
// journal goes there): a read-only file system or a missing permission would otherwise end in
// SQLite's "unable to open database file". A missing folder is left to the open, which names it.
void CheckWritable(const std::string& path) {
  if (path == ":memory:") return;
  const std::string folder = FolderOf(path);
  for (const std::string& place : {path, folder}) {
    if (::access(place.c_str(), W_OK) == 0 || errno == ENOENT) continue;
    const int error = errno;
    throw DbError(
        "cannot write database " + path + ": " +
        (place == path ? "the file" : "its folder " + folder) +
        (error == EROFS ? " is on a read-only file system"
                        : " is not writable (" + std::string(std::strerror(error)) + ")") +
        "; nothing was opened. Running a study writes the database and, beside it, its "
        "journal: run it on a database in a writable folder (commands that only read, such as "
        "query, criteria, map and report, read it where it is)");
  }
}

}  // namespace

bool OpensImmutable(const std::string& path) {
  struct statvfs fs {};
  if (::statvfs(path.c_str(), &fs) == 0 && (fs.f_flag & ST_RDONLY) != 0) return true;
  const std::string folder = FolderOf(path);
  const bool writable = ::access(path.c_str(), W_OK) == 0 && ::access(folder.c_str(), W_OK) == 0;
  return !writable && ::access((path + "-wal").c_str(), F_OK) != 0;
}

Connection::Connection(const std::string& path, Mode mode) : path_(path) {
  CheckIsDatabaseFile(path, mode);
  const bool read_only = mode == Mode::kReadOnly;
  if (!read_only) CheckWritable(path);
  const std::string name = read_only ? ReadOnlyUri(path) : path;
  const int flags = read_only ? SQLITE_OPEN_READONLY | SQLITE_OPEN_URI
                              : SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE;
  const int rc = sqlite3_open_v2(name.c_str(), &db_, flags | SQLITE_OPEN_NOMUTEX, nullptr);
  if (rc != SQLITE_OK) {
    const std::string msg = db_ != nullptr ? Describe(db_) : sqlite3_errstr(rc);
    sqlite3_close(db_);
    db_ = nullptr;
    throw DbError("cannot open database " + path + ": " + msg);
  }
  sqlite3_extended_result_codes(db_, 1);
  sqlite3_busy_timeout(db_, kBusyTimeout_ms);
  if (mode == Mode::kReadOnly) Execute("PRAGMA query_only = 1");
}

Connection::~Connection() {
  cached_.clear();  // Finalized before the connection closes.
  sqlite3_close_v2(db_);
}

void Connection::Execute(std::string_view sql) {
  char* err = nullptr;
  const std::string text(sql);
  if (sqlite3_exec(db_, text.c_str(), nullptr, nullptr, &err) != SQLITE_OK) {
    const std::string msg = err != nullptr && (sqlite3_extended_errcode(db_) & 0xff) != SQLITE_BUSY
                                ? std::string(err)
                                : Describe(db_);
    sqlite3_free(err);
    throw DbError(path_ + ": " + msg + " (in: " + text.substr(0, 200) + ")");
  }
}

Statement Connection::Prepare(std::string_view sql) {
  sqlite3_stmt* stmt = nullptr;
  const char* tail = nullptr;
  const int rc = sqlite3_prepare_v2(db_, sql.data(), static_cast<int>(sql.size()), &stmt, &tail);
  if (rc != SQLITE_OK) {
    throw DbError(path_ + ": " + Describe(db_) + " (in: " + std::string(sql.substr(0, 200)) + ")");
  }
  if (stmt == nullptr) throw DbError("empty SQL statement");
  return Statement(db_, stmt, std::string(sql));
}

Statement& Connection::Cached(std::string_view sql) {
  auto it = cached_.find(sql);
  if (it == cached_.end()) {
    it = cached_.emplace(std::string(sql), std::make_unique<Statement>(Prepare(sql))).first;
  }
  it->second->Reset();
  return *it->second;
}

std::int64_t Connection::LastInsertRowId() const { return sqlite3_last_insert_rowid(db_); }

Statement::Statement(sqlite3* db, sqlite3_stmt* stmt, std::string sql)
    : db_(db), stmt_(stmt), sql_(std::move(sql)) {}

Statement::~Statement() { sqlite3_finalize(stmt_); }

Statement::Statement(Statement&& other) noexcept
    : db_(other.db_), stmt_(other.stmt_), sql_(std::move(other.sql_)) {
  other.stmt_ = nullptr;
}

void Statement::Check(int rc) const {
  if (rc != SQLITE_OK) throw DbError(std::string(sqlite3_errmsg(db_)) + " (in: " + sql_ + ")");
}

Statement& Statement::Bind(int i, double v) {
  Check(sqlite3_bind_double(stmt_, i, v));
  return *this;
}

Statement& Statement::Bind(int i, std::int64_t v) {
  Check(sqlite3_bind_int64(stmt_, i, v));
  return *this;
}

Statement& Statement::Bind(int i, std::string_view v) {
  Check(sqlite3_bind_text(stmt_, i, v.data(), static_cast<int>(v.size()), SQLITE_TRANSIENT));
  return *this;
}

Statement& Statement::Bind(int i, const std::vector<double>& blob) {
  // An empty vector is an empty blob: a null data() would bind NULL.
  Check(blob.empty() ? sqlite3_bind_zeroblob(stmt_, i, 0)
                     : sqlite3_bind_blob64(stmt_, i, blob.data(), blob.size() * sizeof(double),
                                           SQLITE_TRANSIENT));
  return *this;
}

Statement& Statement::BindNull(int i) {
  Check(sqlite3_bind_null(stmt_, i));
  return *this;
}

Statement& Statement::BindValue(int i, const SqlValue& v) {
  return std::visit(
      [&](const auto& x) -> Statement& {
        if constexpr (std::is_same_v<std::decay_t<decltype(x)>, std::monostate>) {
          return BindNull(i);
        } else {
          return Bind(i, x);
        }
      },
      v);
}

bool Statement::Step() {
  const int rc = sqlite3_step(stmt_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  throw DbError(std::string(sqlite3_db_filename(db_, "main")) + ": " + Describe(db_) +
                " (in: " + sql_.substr(0, 200) + ")");
}

void Statement::Run() {
  while (Step()) {
  }
  Reset();
}

void Statement::Reset() {
  sqlite3_reset(stmt_);
  sqlite3_clear_bindings(stmt_);
}

int Statement::ColumnCount() const { return sqlite3_column_count(stmt_); }
std::string Statement::ColumnName(int i) const { return sqlite3_column_name(stmt_, i); }
bool Statement::IsNull(int i) const { return sqlite3_column_type(stmt_, i) == SQLITE_NULL; }
int Statement::ColumnType(int i) const { return sqlite3_column_type(stmt_, i); }
double Statement::GetDouble(int i) const { return sqlite3_column_double(stmt_, i); }
std::int64_t Statement::GetInt(int i) const { return sqlite3_column_int64(stmt_, i); }

std::string Statement::GetText(int i) const {
  const auto* p = sqlite3_column_text(stmt_, i);
  return p != nullptr ? std::string(reinterpret_cast<const char*>(p)) : std::string();
}

std::optional<double> Statement::GetOptionalDouble(int i) const {
  if (IsNull(i)) return std::nullopt;
  return GetDouble(i);
}

std::vector<double> Statement::GetBlob(int i) const {
  const void* p = sqlite3_column_blob(stmt_, i);
  const auto bytes = static_cast<std::size_t>(sqlite3_column_bytes(stmt_, i));
  if (bytes % sizeof(double) != 0) {
    const char* file = sqlite3_db_filename(sqlite3_db_handle(stmt_), "main");
    throw DbError(std::string(file != nullptr ? file : "") + ": database corrupt: column " +
                  ColumnName(i) + " holds " + std::to_string(bytes) +
                  " bytes, not a whole number of 8-byte float64 values");
  }
  std::vector<double> v(bytes / sizeof(double));
  if (p != nullptr && !v.empty()) std::memcpy(v.data(), p, v.size() * sizeof(double));
  return v;
}

bool Statement::IsReadOnly() const { return sqlite3_stmt_readonly(stmt_) != 0; }

Transaction::Transaction(Connection& c) : c_(c) { c_.Execute("BEGIN IMMEDIATE"); }

Transaction::~Transaction() {
  if (!done_) {
    try {
      c_.Execute("ROLLBACK");
    } catch (const DbError&) {
      // Nothing more can be done from a destructor; the transaction is abandoned.
    }
  }
}

void Transaction::Commit() {
  c_.Execute("COMMIT");
  done_ = true;
}

}  // namespace shockmap
