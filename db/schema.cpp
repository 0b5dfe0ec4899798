#include "db/schema.h"

#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "db/migrations.h"
#include "db/point_tables.h"
#include "db/result_views.h"

namespace shockmap {
namespace {

int PragmaInt(Connection& db, const char* pragma) {
  Statement s = db.Prepare(std::string("PRAGMA ") + pragma);
  return s.Step() ? static_cast<int>(s.GetInt(0)) : 0;
}

// What a schema version is made of, one entry per table, view and table column: "table points",
// "column points.host", "view results" (a view's columns vary: scene_params).
using SchemaObjects = std::set<std::string>;

SchemaObjects ObjectsOf(Connection& db) {
  SchemaObjects objects;
  std::vector<std::string> tables;
  Statement s = db.Prepare(
      "SELECT type, name FROM sqlite_schema WHERE type IN ('table', 'view') AND name NOT LIKE "
      "'sqlite\\_%' ESCAPE '\\'");
  while (s.Step()) {
    objects.insert(s.GetText(0) + " " + s.GetText(1));
    if (s.GetText(0) == "table") tables.push_back(s.GetText(1));
  }
  for (const std::string& table : tables) {
    Statement columns = db.Prepare("SELECT name FROM pragma_table_info(?)");
    columns.Bind(1, table);
    while (columns.Step()) objects.insert("column " + table + "." + columns.GetText(0));
  }
  return objects;
}

// The names of the declared views (db/result_views.h, db/point_tables.h) a database of schema
// `version` holds.
std::vector<std::string> DeclaredViewsOf(int version) {
  std::vector<std::string> names;
  for (const ResultView& view : ResultViews()) {
    if (view.since <= version) names.emplace_back(view.name);
  }
  for (const PointTable* table : PointTables()) {
    if (table->parameter_view && table->parameter_view->since <= version) {
      names.emplace_back(table->parameter_view->name);
    }
  }
  return names;
}

// What a new database is made of: the migrations applied in turn to an empty database in
// memory, once per process, and the declared views.
struct FreshSchema {
  std::vector<SchemaObjects> objects;  // Of each version, index = version.
  // The definition of every results view without its layout (WithoutLayout), by name.
  std::map<std::string, std::string> results_views;
};

const FreshSchema& Fresh() {
  static const FreshSchema fresh = [] {
    Connection scratch(std::string(kInMemoryDatabaseName), Connection::Mode::kInMemory);
    FreshSchema f{{ObjectsOf(scratch)}, {}};
    for (int version = 1; version <= kSchemaVersion; ++version) {
      scratch.Execute(kMigrations[version - 1]);
      SchemaObjects objects = ObjectsOf(scratch);
      for (const std::string& view : DeclaredViewsOf(version)) objects.insert("view " + view);
      f.objects.push_back(std::move(objects));
    }
    for (const ResultView& view : ResultViews()) {
      f.results_views[std::string(view.name)] = WithoutLayout(CreateViewSql(view));
    }
    return f;
  }();
  return fresh;
}

// The first of `objects` not in `in`, tables and views before columns (a table that is missing
// is named, not its first column), or "" when `objects` lies within `in`.
std::string FirstMissing(const SchemaObjects& objects, const SchemaObjects& in) {
  for (const bool columns : {false, true}) {
    for (const std::string& o : objects) {
      if (o.starts_with("column ") == columns && !in.contains(o)) return o;
    }
  }
  return "";
}

// Throws unless the file's tables agree with its version: it holds every table, view and column
// of that version, and none that the next migration adds (it would fail on them half-way).
void CheckTablesMatch(Connection& db, int version) {
  const std::vector<SchemaObjects>& versions = Fresh().objects;
  const SchemaObjects present = ObjectsOf(db);
  const std::string corrupt = db.Path() + ": database corrupt: schema version " +
                              std::to_string(version) + " disagrees with its tables: ";
  if (const std::string missing = FirstMissing(versions[version], present); !missing.empty()) {
    throw DbError(corrupt + missing + " of version " + std::to_string(version) + " is missing");
  }
  if (version == kSchemaVersion) return;
  SchemaObjects added;
  for (const std::string& o : versions[version + 1]) {
    if (!versions[version].contains(o) && present.contains(o)) added.insert(o);
  }
  if (const std::string first = FirstMissing(added, {}); !first.empty()) {
    throw DbError(corrupt + first + ", added by version " + std::to_string(version + 1) +
                  ", is already there");
  }
}

// True when `sql` is how this build defines the view `name` in `file`: a results view as its
// declaration writes it, whatever the layout of its text (earlier versions wrote it by hand), or
// a kind's parameter view (scene_params) with the columns of the parameter paths stored in the
// file, or with none as earlier versions wrote it until they stored a point
// (`SELECT * FROM scene_results`).
bool IsOurs(Connection& file, const std::string& name, const std::string& sql) {
  const auto& fresh = Fresh().results_views;
  const auto our = fresh.find(name);
  if (our != fresh.end()) return our->second == WithoutLayout(sql);
  for (const PointTable* table : PointTables()) {
    if (table->parameter_view && table->parameter_view->name == name) {
      return sql == ParameterViewSql(file, *table) ||
             WithoutLayout(sql) ==
                 "CREATE VIEW " + name + " AS SELECT * FROM " + std::string(table->results_view);
    }
  }
  return false;
}

// Throws unless every entry of the file's schema of type `type` ("view" or "trigger") is one this
// build writes, as it writes it: the commands read the views, so a view another program
// redefined (an endless recursive query, say) would hang them or feed them other rows, and a
// trigger (shockmap writes none) would run inside a write, a migration's included.
void CheckEntriesAreOurs(Connection& db, std::string_view type) {
  Statement s = db.Prepare("SELECT name, sql FROM sqlite_schema WHERE type = ?");
  s.Bind(1, type);
  while (s.Step()) {
    if (!IsOurs(db, s.GetText(0), s.GetText(1))) {
      throw DbError(db.Path() + ": " + std::string(type) + " " + s.GetText(0) +
                    " is not the one shockmap writes (another program defined or changed "
                    "it); refusing to read the file");
    }
  }
}

// Throws unless the file is empty, or ours at a version this build can read with the tables of
// that version and no view or trigger of another program.
int CheckedVersion(Connection& db) {
  {
    Statement check = db.Prepare("PRAGMA quick_check");
    const std::string verdict = check.Step() ? check.GetText(0) : "no answer";
    if (verdict != "ok") {
      throw DbError(db.Path() + ": not a sound SQLite database (quick_check: " + verdict + ")");
    }
  }
  const int version = PragmaInt(db, "user_version");
  const int app_id = PragmaInt(db, "application_id");
  Statement tables = db.Prepare("SELECT count(*) FROM sqlite_schema");
  tables.Step();
  const bool empty = tables.GetInt(0) == 0;
  if (empty && version == 0 && app_id == 0) return 0;
  if (app_id != kApplicationId) {
    throw DbError(db.Path() + ": not a shockmap database (application_id " +
                  std::to_string(app_id) + "); refusing to touch it");
  }
  if (version > kSchemaVersion) {
    throw DbError(db.Path() + ": written by a newer shockmap (schema version " +
                  std::to_string(version) + ", this build reads up to " +
                  std::to_string(kSchemaVersion) + ")");
  }
  if (version < 0) {
    throw DbError(db.Path() + ": database corrupt: schema version " + std::to_string(version) +
                  " (PRAGMA user_version) is none shockmap writes (0 to " +
                  std::to_string(kSchemaVersion) + ")");
  }
  CheckTablesMatch(db, version);
  CheckEntriesAreOurs(db, "trigger");
  if (version == kSchemaVersion) CheckEntriesAreOurs(db, "view");  // Older ones are rewritten.
  return version;
}

// The checks' several reads in one read transaction, so that they see one state of the file
// even while another process migrates it.
int CheckedVersionAtOnce(Connection& db) {
  db.Execute("BEGIN");
  try {
    const int version = CheckedVersion(db);
    db.Execute("COMMIT");
    return version;
  } catch (...) {
    db.Execute("ROLLBACK");
    throw;
  }
}

}  // namespace

void CheckSchema(Connection& db) {
  if (CheckedVersionAtOnce(db) != kSchemaVersion) {
    throw DbError(db.Path() +
                  ": schema is older than this build's; `shockmap study run STUDY_FILE --db " +
                  db.Path() + "` migrates it (it opens the database for writing)");
  }
}

void MigrateToCurrent(Connection& db) {
  if (CheckedVersionAtOnce(db) == kSchemaVersion) return;
  // All pending migrations in one IMMEDIATE transaction: a process killed midway leaves the
  // file as it was, never at an intermediate version; two processes migrating at once are
  // serialized, and the second reads the version again under the lock and finds nothing to do.
  Transaction t(db);
  const int from = CheckedVersion(db);
  DropDeclaredViews(db);
  for (int version = from; version < kSchemaVersion; ++version) db.Execute(kMigrations[version]);
  CreateDeclaredViews(db);
  CheckEntriesAreOurs(db, "view");
  db.Execute("PRAGMA application_id = " + std::to_string(kApplicationId));
  db.Execute("PRAGMA user_version = " + std::to_string(kSchemaVersion));
  t.Commit();
}

}  // namespace shockmap
