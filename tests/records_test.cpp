// Every stored record is declared once (records/): its columns are the columns of its table in a
// database migrated to the current schema, name, type and nullability; docs/database.md lists
// them as declared; every registered score is a column of the score rows that carry scores; and
// a record comes back from its SQL and its bytes column for column.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "db/migrations.h"
#include "db/point_tables.h"
#include "db/result_views.h"
#include "db/schema.h"
#include "db/stored_record.h"
#include "engine/record_codec.h"
#include "records/canonical_records.h"
#include "records/ensemble_records.h"
#include "records/output_columns.h"
#include "records/scene_records.h"
#include "tests/temp_dir.h"
#include "validation/scores.h"

namespace shockmap {
namespace {

// "name TYPE" or "name TYPE NOT NULL", as a table's column is compared.
using ColumnFacts = std::set<std::string>;

std::string Fact(std::string_view name, std::string_view type, bool nullable) {
  return std::string(name) + " " + std::string(type) + (nullable ? "" : " NOT NULL");
}

// The facts of a record's declared columns; every one nullable when the record's columns sit in
// a points table (NULL until the point is computed).
ColumnFacts Declared(const auto& columns, bool all_nullable = false) {
  ColumnFacts facts;
  for (const auto& c : columns) {
    facts.insert(Fact(c.name, ToString(c.Type()), all_nullable || c.Nullable()));
  }
  return facts;
}

ColumnFacts Union(std::initializer_list<ColumnFacts> parts) {
  ColumnFacts all;
  for (const ColumnFacts& part : parts) all.insert(part.begin(), part.end());
  return all;
}

// The columns every points table has besides its parameters and scores.
const ColumnFacts kLifecycle = {"point_id INTEGER",
                                "study_id INTEGER NOT NULL",
                                "point_key TEXT NOT NULL",
                                "reference_key TEXT NOT NULL",
                                "status TEXT NOT NULL",
                                "message TEXT NOT NULL",
                                "run_id INTEGER",
                                "updated_utc TEXT NOT NULL",
                                "host TEXT",
                                "rank INTEGER"};
// The columns every reference table has besides its record.
const ColumnFacts kReferenceBookkeeping = {"reference_id INTEGER", "run_id INTEGER",
                                           "created_utc TEXT NOT NULL"};

// Every table a study kind stores its records in, with the columns declared for it.
std::map<std::string, ColumnFacts> DeclaredTables() {
  return {
      {"points", Union({kLifecycle, Declared(kPointParameterColumns)})},
      {"scores", Union({{"point_id INTEGER"}, Declared(kScoreColumns)})},
      {"reference_runs", Union({kReferenceBookkeeping, Declared(kReferenceColumns)})},
      {"scene_points", Union({kLifecycle, Declared(kScenePointParameterColumns),
                              Declared(kSceneScoreColumns, true)})},
      {"scene_references", Union({kReferenceBookkeeping, Declared(kSceneReferenceColumns)})},
      {"ensemble_members", Union({kLifecycle, Declared(kEnsembleMemberParameterColumns),
                                  Declared(kEnsembleMemberColumns, true)})},
      {"ensemble_member_zones", Union({{"point_id INTEGER NOT NULL", "zone INTEGER NOT NULL"},
                                       Declared(kEnsembleZoneColumns)})},
      {"ensemble_member_impacts",
       Union({{"point_id INTEGER NOT NULL"}, Declared(kEnsembleImpactColumns)})},
      {"ensemble_references", Union({kReferenceBookkeeping, Declared(kEnsembleReferenceColumns)})},
  };
}

ColumnFacts MigratedColumns(Connection& db, const std::string& table) {
  ColumnFacts facts;
  Statement s = db.Prepare("SELECT name, type, \"notnull\" FROM pragma_table_info(?)");
  s.Bind(1, table);
  while (s.Step()) facts.insert(Fact(s.GetText(0), s.GetText(1), s.GetInt(2) == 0));
  return facts;
}

std::string Listed(const ColumnFacts& facts) {
  std::string text;
  for (const std::string& f : facts) text += "\n  " + f;
  return text;
}

class RecordsTest : public testing::TempDirTest {};

TEST_F(RecordsTest, MigratedTablesHaveExactlyTheDeclaredColumns) {
  Connection db(Path("migrated.db"), Connection::Mode::kReadWriteCreate);
  MigrateToCurrent(db);
  for (const auto& [table, declared] : DeclaredTables()) {
    const ColumnFacts migrated = MigratedColumns(db, table);
    ColumnFacts missing, undeclared;
    std::ranges::set_difference(declared, migrated, std::inserter(missing, missing.end()));
    std::ranges::set_difference(migrated, declared, std::inserter(undeclared, undeclared.end()));
    EXPECT_TRUE(missing.empty() && undeclared.empty())
        << table << ": declared but not migrated:" << Listed(missing)
        << "\nmigrated but not declared:" << Listed(undeclared)
        << "\n(a new column is a member and a line of its record's column table in records/ "
           "and a new migration in db/migrations.h: docs/architecture.md, \"Add a field\")";
  }
}

TEST_F(RecordsTest, EveryKindsPointTableIsMigratedWithItsParameterColumnsAndView) {
  Connection db(Path("migrated.db"), Connection::Mode::kReadWriteCreate);
  MigrateToCurrent(db);
  const auto declared = DeclaredTables();
  for (const PointTable* table : PointTables()) {
    SCOPED_TRACE(table->name);
    ASSERT_TRUE(declared.contains(std::string(table->name)));
    const ColumnFacts migrated = MigratedColumns(db, std::string(table->name));
    for (const std::string& column : table->parameter_columns) {
      EXPECT_TRUE(std::ranges::any_of(migrated, [&](const std::string& f) {
        return f.starts_with(column + " ");
      })) << column;
    }
    for (std::string_view column : table->progress_by) {
      EXPECT_TRUE(std::ranges::count(table->parameter_columns, column) == 1) << column;
    }
    Statement view =
        db.Prepare("SELECT count(*) FROM sqlite_schema WHERE type = 'view' AND name = ?");
    view.Bind(1, table->results_view);
    ASSERT_TRUE(view.Step());
    EXPECT_EQ(view.GetInt(0), 1) << table->results_view;
  }
}

// A record's rows as docs/database.md shows them: | `name` | unit | meaning |.
std::string DocumentedRows(const auto& columns) {
  std::string rows;
  for (const auto& c : columns) {
    rows += "| `" + std::string(c.name) + "` | " + std::string(c.unit) +
            (c.unit.empty() ? "" : " ") + "| " + std::string(c.meaning) + " |\n";
  }
  return rows;
}

std::string DatabaseDoc() {
  std::ifstream in(std::string(SHOCKMAP_SOURCE_DIR) + "/docs/database.md");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(RecordsDoc, DatabaseDocListsEveryDeclaredColumnAsDeclared) {
  const std::string doc = DatabaseDoc();
  ASSERT_FALSE(doc.empty());
  const std::vector<std::pair<std::string, std::string>> records = {
      {"points: the parameters (kPointParameterColumns)", DocumentedRows(kPointParameterColumns)},
      {"scores (kScoreColumns)", DocumentedRows(kScoreColumns)},
      {"reference_runs (kReferenceColumns)", DocumentedRows(kReferenceColumns)},
      {"scene_points: the parameters (kScenePointParameterColumns)",
       DocumentedRows(kScenePointParameterColumns)},
      {"scene_points: the scores (kSceneScoreColumns)", DocumentedRows(kSceneScoreColumns)},
      {"scene_references (kSceneReferenceColumns)", DocumentedRows(kSceneReferenceColumns)},
      {"ensemble_members: the parameters (kEnsembleMemberParameterColumns)",
       DocumentedRows(kEnsembleMemberParameterColumns)},
      {"ensemble_members: the run (kEnsembleMemberColumns)",
       DocumentedRows(kEnsembleMemberColumns)},
      {"ensemble_member_zones (kEnsembleZoneColumns)", DocumentedRows(kEnsembleZoneColumns)},
      {"ensemble_member_impacts (kEnsembleImpactColumns)", DocumentedRows(kEnsembleImpactColumns)},
      {"ensemble_references (kEnsembleReferenceColumns)",
       DocumentedRows(kEnsembleReferenceColumns)},
  };
  for (const auto& [record, rows] : records) {
    EXPECT_NE(doc.find(rows), std::string::npos)
        << "docs/database.md does not list the columns of " << record
        << " as declared in records/; its table must hold these rows, in this order:\n"
        << rows;
  }
  EXPECT_NE(doc.find("(" + std::to_string(kSchemaVersion) + " at present)"), std::string::npos)
      << "docs/database.md must give the schema version, " << kSchemaVersion;
}

TEST(ScoreRegistry, EveryScoreIsAColumnOfTheScoreRowsThatCarryScores) {
  for (const ScoreDefinition& score : Scores()) {
    SCOPED_TRACE(score.name);
    EXPECT_NE(OptionalRealMember(kScoreColumns, score.name), nullptr);
    EXPECT_NE(OptionalRealMember(kSceneScoreColumns, score.name), nullptr);
    EXPECT_EQ(FindScore(score.name), &score);
    EXPECT_LT(score.threshold_low, score.threshold_high);
    EXPECT_LT(score.map_low, score.map_high);
    EXPECT_NE(score.compute, nullptr);
  }
}

// A record with a value in every column, NULL where a column may be NULL.
ScoreRow SampleScore() {
  ScoreRow s;
  s.reference_id = 7;
  s.err = 0.1234567890123;
  s.n_modes = 12;
  s.steps = 123456789012;
  s.wall_s = 1e-300;
  s.first_shock_peak_n = 150.0;
  s.first_shock_rebounds = 3;
  s.shocks_json = R"([{"rebounds":3}])";
  s.srf_definition = "reference_window";
  return s;
}

void ExpectSameCells(const ScoreRow& a, const ScoreRow& b) {
  EXPECT_EQ(CellsOf(a, kScoreColumns), CellsOf(b, kScoreColumns));
}

TEST_F(RecordsTest, ARecordComesBackFromItsSqlColumnForColumn) {
  Connection db(Path("records.db"), Connection::Mode::kReadWriteCreate);
  MigrateToCurrent(db);
  const ScoreRow sent = SampleScore();
  Statement insert = db.Prepare("INSERT INTO scores(point_id, " + ColumnList(kScoreColumns) +
                                ") VALUES (1, " + Placeholders(std::size(kScoreColumns)) + ")");
  BindRecord(insert, 1, sent, kScoreColumns);
  db.Execute("PRAGMA foreign_keys = OFF");
  insert.Run();
  Statement select = db.Prepare("SELECT " + ColumnList(kScoreColumns) + " FROM scores");
  ASSERT_TRUE(select.Step());
  ScoreRow got;
  ReadRecord(select, 0, got, kScoreColumns, db.Path(), [] { return std::string("score 1"); });
  ExpectSameCells(got, sent);
  EXPECT_FALSE(got.srf.has_value());
  EXPECT_EQ(got.first_shock_rebounds, 3);
}

TEST(RecordCodec, ARecordComesBackFromItsBytesColumnForColumn) {
  const ScoreRow sent = SampleScore();
  ByteWriter out;
  PutRecord(sent, kScoreColumns, out);
  ByteReader in(out.Bytes());
  ExpectSameCells(GetRecord<ScoreRow>(in, kScoreColumns), sent);
  EXPECT_TRUE(in.AtEnd());
  const std::string truncated = out.Bytes().substr(0, out.Bytes().size() - 1);
  ByteReader short_in(truncated);
  EXPECT_THROW(GetRecord<ScoreRow>(short_in, kScoreColumns), std::runtime_error);
}

TEST(RecordTable, ARecordsCellsAreItsColumnsInOrderWithNullForAnEmptyOptional) {
  const Table t = TableOf(std::vector<ScoreRow>{SampleScore()}, kScoreColumns);
  ASSERT_EQ(t.columns.size(), std::size(kScoreColumns));
  ASSERT_EQ(t.rows.size(), 1u);
  const NamedRow row(t, 0);
  EXPECT_EQ(row["err"], TableCell(0.1234567890123));
  EXPECT_EQ(row["srf"], TableCell());
  EXPECT_EQ(row["steps"], TableCell(std::int64_t{123456789012}));
  EXPECT_EQ(row["srf_definition"], TableCell(std::string("reference_window")));
  EXPECT_THROW(row["no_such_column"], std::out_of_range);
}

// The names of a table's or view's columns, in order.
std::vector<std::string> ColumnsOf(Connection& db, std::string_view table) {
  std::vector<std::string> names;
  Statement s = db.Prepare("SELECT name FROM pragma_table_info(?)");
  s.Bind(1, table);
  while (s.Step()) names.push_back(s.GetText(0));
  return names;
}

// The statement that defines `view`, as SQLite stores it.
std::string ViewSqlOf(Connection& db, std::string_view view) {
  Statement s = db.Prepare("SELECT sql FROM sqlite_schema WHERE type = 'view' AND name = ?");
  s.Bind(1, view);
  return s.Step() ? s.GetText(0) : "";
}

std::string Source(const std::string& path) {
  return std::string(SHOCKMAP_SOURCE_DIR) + "/" + path;
}

TEST(ResultViews, NoMigrationWritesAView) {
  for (const char* migration : kMigrations) {
    EXPECT_EQ(std::string(migration).find("VIEW"), std::string::npos) << migration;
  }
}

// Each view shows every column of the records it reads but those it leaves out, and what it
// leaves out are columns of those records (a name mistyped would show the column).
TEST(ResultViews, EachViewShowsEveryColumnOfItsRecordsButThoseItLeavesOut) {
  for (const ResultView& view : ResultViews()) {
    SCOPED_TRACE(view.name);
    const std::vector<std::string> columns = ViewColumns(view);
    for (const ViewSource& source : view.sources) {
      for (std::string_view left_out : source.left_out) {
        EXPECT_EQ(std::ranges::count(source.columns, left_out), 1) << left_out;
      }
      for (const std::string& column : source.columns) {
        const std::string expression = std::string(source.alias) + "." + column;
        const bool shown = std::ranges::any_of(columns, [&](const std::string& c) {
          return c == expression || c.starts_with(expression + " AS ");
        });
        EXPECT_EQ(shown, std::ranges::count(source.left_out, column) == 0) << expression;
      }
    }
  }
}

// A database of schema 2 (tests/data/schema_v2.db, written by that version) is migrated with
// the views of a new database: the same definitions and columns, and scene_params with the
// stored parameter paths after the columns of scene_results.
TEST_F(RecordsTest, AnOldSchemaDatabaseOpensWithTheViewsOfANewOne) {
  std::filesystem::copy_file(Source("tests/data/schema_v2.db"), Path("v2.db"));
  Connection old(Path("v2.db"), Connection::Mode::kReadWriteCreate);
  Connection fresh(Path("fresh.db"), Connection::Mode::kReadWriteCreate);
  const std::vector<std::string> v2_results = ColumnsOf(old, "results");
  ASSERT_EQ(std::ranges::count(v2_results, "pfr"), 0);  // Added to the view by schema 10.
  MigrateToCurrent(old);
  MigrateToCurrent(fresh);
  for (const ResultView& view : ResultViews()) {
    SCOPED_TRACE(view.name);
    EXPECT_EQ(ViewSqlOf(old, view.name), ViewSqlOf(fresh, view.name));
    EXPECT_EQ(ColumnsOf(old, view.name), ColumnsOf(fresh, view.name));
    EXPECT_EQ(ColumnsOf(fresh, view.name).size(), ViewColumns(view).size());
  }
  EXPECT_EQ(ColumnsOf(fresh, "scene_params"), ColumnsOf(fresh, "scene_results"));
  const std::vector<std::string> params = ColumnsOf(old, "scene_params");
  const std::vector<std::string> results = ColumnsOf(old, "scene_results");
  ASSERT_GT(params.size(), results.size());
  EXPECT_TRUE(std::equal(results.begin(), results.end(), params.begin()));
  for (auto p = params.begin() + static_cast<std::ptrdiff_t>(results.size()); p != params.end();
       ++p) {
    EXPECT_TRUE(p->starts_with("params_")) << *p;
  }
}

// A database of the current schema whose views earlier versions wrote by hand (the fuzzer's
// seeds, written before the views were declared) reads as it did: its views differ from the
// declared ones in layout only, and show the same columns.
TEST_F(RecordsTest, ViewsWrittenByHandByEarlierVersionsAreAcceptedWithTheirLayout) {
  std::filesystem::copy_file(Source("fuzz/corpus/database/canonical.db"), Path("seed.db"));
  Connection fresh(Path("fresh.db"), Connection::Mode::kReadWriteCreate);
  MigrateToCurrent(fresh);
  Connection seed(Path("seed.db"), Connection::Mode::kReadOnly);
  EXPECT_NO_THROW(CheckSchema(seed));
  for (const ResultView& view : ResultViews()) {
    SCOPED_TRACE(view.name);
    EXPECT_EQ(WithoutLayout(ViewSqlOf(seed, view.name)), WithoutLayout(CreateViewSql(view)));
    EXPECT_EQ(ColumnsOf(seed, view.name), ColumnsOf(fresh, view.name));
  }
}

// A record and an output of the same value, declared apart (records/output_columns.h).
struct SampleRecord {
  std::int64_t count = 0, flag = 0;
  double kept = -1.0;
  std::optional<double> rate = 7.0;
  std::string label;
};
inline constexpr Column<SampleRecord> kSampleColumns[] = {
    {"count", &SampleRecord::count, "", "a count"},
    {"flag", &SampleRecord::flag, "", "a flag"},
    {"kept", &SampleRecord::kept, "", "not taken from the outputs"},
    {"rate", &SampleRecord::rate, "1/s", "a rate, none when unknown"},
    {"label", &SampleRecord::label, "", "a text"},
};
struct SampleValue {
  int count;
  bool flag;
  double kept;
  double rate;
};
inline constexpr OutputColumn<SampleValue> kSampleOutputs[] = {
    {"count", [](const SampleValue& v) -> OutputValue { return std::int64_t{v.count}; }, "", ""},
    {"flag", [](const SampleValue& v) -> OutputValue { return v.flag; }, "", ""},
    {"kept", [](const SampleValue& v) -> OutputValue { return v.kept; }, "", ""},
    {"rate",
     [](const SampleValue& v) -> OutputValue {
       if (v.rate < 0.0) return {};
       return v.rate;
     },
     "1/s", ""},
    {"only_in_outputs", [](const SampleValue&) -> OutputValue { return 1.0; }, "", ""},
};
inline constexpr OutputColumn<SampleValue> kMismatchedOutputs[] = {
    {"label", [](const SampleValue& v) -> OutputValue { return v.kept; }, "", ""},
};

TEST(SetColumnsFromOutputs, SetsTheRecordsColumnsTheOutputsName) {
  SampleRecord r;
  SetColumnsFromOutputs(r, kSampleColumns, SampleValue{3, true, 2.5, -1.0}, kSampleOutputs,
                        {"kept"});
  EXPECT_EQ(r.count, 3);
  EXPECT_EQ(r.flag, 1);
  EXPECT_EQ(r.kept, -1.0);           // Left out by `except`.
  EXPECT_FALSE(r.rate.has_value());  // None empties it.
  EXPECT_EQ(r.label, "");            // No output of that name.
  SetColumnsFromOutputs(r, kSampleColumns, SampleValue{4, false, 2.5, 0.25}, kSampleOutputs);
  EXPECT_EQ(r.flag, 0);
  EXPECT_EQ(r.kept, 2.5);
  EXPECT_EQ(r.rate, 0.25);
  EXPECT_THROW(SetColumnsFromOutputs(r, kSampleColumns, SampleValue{}, kMismatchedOutputs),
               std::logic_error);
}

}  // namespace
}  // namespace shockmap
