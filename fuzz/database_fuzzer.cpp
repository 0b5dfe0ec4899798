// libFuzzer target: any bytes as a study database, read by what every database reader command
// runs (query, study status, criteria, map, cost, advise, report, sizing, export), in process.
// Each either succeeds or throws DbError or InputError; any other exception, a crash, a
// sanitizer report or a hang is a bug. The corpus (fuzz/corpus/database) holds small real
// databases of each study kind; besides libFuzzer's byte mutations, the custom mutator rewrites
// one stored blob or text cell through SQLite, as SQLite's own dbfuzz does, so that mutations
// reach the checks of stored rows and not only the page parser. The corpus must be at the
// current schema version (readers refuse an older file, so every input would stop at the
// schema check): a new migration is applied to it too, by scripts/migrate-fuzz-corpus.

#include <sqlite3.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "analysis/cost_front.h"
#include "analysis/ensemble_sizing.h"
#include "analysis/scored_points.h"
#include "core/input_error.h"
#include "db/ensemble_members.h"
#include "db/read_only_query.h"
#include "db/report_queries.h"
#include "db/schema.h"
#include "db/stored_signals.h"
#include "db/study_queries.h"
#include "engine/reference_store.h"
#include "formats/json_reader.h"
#include "specs/scene_study_spec.h"
#include "specs/study_file.h"
#include "specs/study_spec.h"
#include "validation/advice.h"
#include "views/cost_front.h"

extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t max_size);

namespace shockmap {
namespace {

// A reader's failure the user can act on; anything else propagates and is a finding.
template <typename Read>
void Tolerating(Read read) {
  try {
    read();
  } catch (const DbError&) {
  } catch (const InputError&) {
  }
}

// What `query 'SELECT * FROM <view>'` and `study status` read.
void ReadViews(const std::string& db) {
  for (const char* view : {"results", "scene_results", "scene_params", "ensemble_results"}) {
    Tolerating([&] { RunReadOnlyQuery(db, std::string("SELECT * FROM ") + view + " LIMIT 100"); });
  }
  Tolerating([&] { StudyProgress(db); });
  Tolerating([&] { StudyOrigins(db); });
  Tolerating([&] { StudyProgressBreakdowns(db); });
}

// criteria, map, cost, advise, report and export of a study of the paper's problem.
void ReadCanonical(const std::string& db, const std::string& study, const nlohmann::json& spec) {
  const StudySpec parsed = ParseStudySpec(spec, db);
  const auto points = LoadScoredPoints(db, study, "explicit-modal");
  const auto implicit = LoadScoredPoints(db, study, "implicit-full");
  const ValidityCriteria criteria = DeriveCriteria(points, CriteriaOptions{});
  Tolerating([&] { BuildCostTables(points, implicit, std::nullopt); });
  Tolerating([&] { Advise(parsed.problem, parsed.scoring.window_s, criteria, points, 1000.0); });
  Tolerating([&] { LoadReportTables(db, study); });
  Tolerating([&] { StudyResultRows(db, study, kCanonicalPoints); });
  for (const ScoredPoint& p : points) {
    Tolerating([&] {
      for (const std::int64_t id : ReferenceIdsAt(db, study, p.r_k)) {
        if (const auto row = ReadReference(db, id)) FromReferenceRow(*row, db);
      }
    });
  }
}

// export reference of a scene study's points.
void ReadScene(const std::string& db, const std::string& study, const nlohmann::json& spec) {
  ParseStoredSceneStudySpec(spec, db + ": stored study " + study);
  for (std::int64_t point = 1; point <= 4; ++point) {
    Tolerating([&] {
      if (const auto id = ReferenceOfPoint(db, study, point)) ReadSceneReferenceSignals(db, *id);
    });
  }
}

// sizing (and the tables and pictures of report) of an ensemble study.
void ReadEnsembleStudy(const std::string& db, const std::string& study) {
  Connection c(db, Connection::Mode::kReadOnly);
  CheckSchema(c);
  const StoredEnsemble stored = CurrentMembers(ReadEnsemble(c, study));
  SizingOptions options;
  options.bootstrap_resamples = 100;
  const EnsembleSizing sizing = SizeEnsemble(stored, study, options);
  for (const GroupSizing& g : sizing.groups) {
    for (int zone = 0; zone < static_cast<int>(g.zones.size()); ++zone) {
      SizingConvergence(ZoneForces(stored, g, zone), options);
    }
  }
}

void ReadStudy(const std::string& db, const std::string& study) {
  const auto text = StoredStudySpec(db, study);
  if (!text) return;
  const auto spec = ParseJsonText(*text, db + ": stored study " + study);
  switch (StudyKindOf(spec, db)) {
    case StudyFileKind::kCanonical:
      return ReadCanonical(db, study, spec);
    case StudyFileKind::kSceneSweep:
      return ReadScene(db, study, spec);
    case StudyFileKind::kSceneEnsemble:
      return ReadEnsembleStudy(db, study);
  }
}

// The file the readers open: one per process, in /dev/shm when there is one.
const std::string& DatabasePath() {
  static const std::string path =
      (access("/dev/shm", W_OK) == 0 ? std::string("/dev/shm") : std::string("/tmp")) +
      "/shockmap_database_fuzzer_" + std::to_string(getpid()) + ".db";
  return path;
}

// ---- The custom mutator: one stored cell rewritten through SQLite. ----

// The byte of the database header that says WAL (2) or rollback journal (1): an in-memory
// database cannot be in WAL mode, so the copy is read as a rollback-journal file.
constexpr std::size_t kReadVersionByte = 18;

struct Cell {
  std::string table, column;
  std::int64_t rowid = 0;
};

// A random blob or text cell of a table with a rowid, or nothing.
std::optional<Cell> RandomCell(sqlite3* db, std::mt19937_64& random) {
  std::vector<Cell> columns;
  sqlite3_stmt* s = nullptr;
  if (sqlite3_prepare_v2(db,
                         "SELECT m.name, c.name FROM sqlite_schema m, pragma_table_info(m.name) c "
                         "WHERE m.type = 'table' AND m.sql NOT LIKE '%WITHOUT ROWID%' AND "
                         "(c.type IN ('BLOB', 'TEXT'))",
                         -1, &s, nullptr) != SQLITE_OK) {
    return std::nullopt;
  }
  while (sqlite3_step(s) == SQLITE_ROW) {
    columns.push_back({reinterpret_cast<const char*>(sqlite3_column_text(s, 0)),
                       reinterpret_cast<const char*>(sqlite3_column_text(s, 1))});
  }
  sqlite3_finalize(s);
  if (columns.empty()) return std::nullopt;
  Cell cell = columns[random() % columns.size()];
  const std::string pick = "SELECT rowid FROM \"" + cell.table + "\" ORDER BY random() LIMIT 1";
  if (sqlite3_prepare_v2(db, pick.c_str(), -1, &s, nullptr) != SQLITE_OK) return std::nullopt;
  const bool found = sqlite3_step(s) == SQLITE_ROW;
  if (found) cell.rowid = sqlite3_column_int64(s, 0);
  sqlite3_finalize(s);
  if (!found) return std::nullopt;
  return cell;
}

// The cell's bytes mutated by libFuzzer, or shortened, lengthened or emptied, written back as
// the type it had.
bool RewriteCell(sqlite3* db, const Cell& cell, std::mt19937_64& random) {
  const std::string where = " FROM \"" + cell.table + "\" WHERE rowid = ?";
  sqlite3_stmt* s = nullptr;
  const std::string read =
      "SELECT \"" + cell.column + "\", typeof(\"" + cell.column + "\")" + where;
  if (sqlite3_prepare_v2(db, read.c_str(), -1, &s, nullptr) != SQLITE_OK) return false;
  sqlite3_bind_int64(s, 1, cell.rowid);
  if (sqlite3_step(s) != SQLITE_ROW) {
    sqlite3_finalize(s);
    return false;
  }
  const auto* bytes = static_cast<const std::uint8_t*>(sqlite3_column_blob(s, 0));
  std::vector<std::uint8_t> value(bytes, bytes + sqlite3_column_bytes(s, 0));
  const bool blob =
      std::strcmp(reinterpret_cast<const char*>(sqlite3_column_text(s, 1)), "blob") == 0;
  sqlite3_finalize(s);
  switch (random() % 4) {
    case 0:
      value.resize(random() % (value.size() + 1));
      break;
    case 1:
      value.resize(value.size() + random() % 64, static_cast<std::uint8_t>(random()));
      break;
    default:
      value.resize(value.size() + 64);
      value.resize(LLVMFuzzerMutate(value.data(), value.size() - 64, value.size()));
  }
  const std::string write =
      "UPDATE \"" + cell.table + "\" SET \"" + cell.column + "\" = ?" + " WHERE rowid = ?";
  if (sqlite3_prepare_v2(db, write.c_str(), -1, &s, nullptr) != SQLITE_OK) return false;
  if (blob) {
    sqlite3_bind_blob(s, 1, value.data(), static_cast<int>(value.size()), SQLITE_TRANSIENT);
  } else {
    sqlite3_bind_text(s, 1, reinterpret_cast<const char*>(value.data()),
                      static_cast<int>(value.size()), SQLITE_TRANSIENT);
  }
  sqlite3_bind_int64(s, 2, cell.rowid);
  const bool written = sqlite3_step(s) == SQLITE_DONE;
  sqlite3_finalize(s);
  return written;
}

// Rewrites one cell of the database in `data`; 0 when the bytes are no database SQLite can
// open or the result does not fit in max_size.
std::size_t MutateCell(std::uint8_t* data, std::size_t size, std::size_t max_size, unsigned seed) {
  if (size <= kReadVersionByte + 1) return 0;
  sqlite3* db = nullptr;
  if (sqlite3_open(":memory:", &db) != SQLITE_OK) return 0;
  auto* copy = static_cast<std::uint8_t*>(sqlite3_malloc64(size));
  std::memcpy(copy, data, size);
  copy[kReadVersionByte] = copy[kReadVersionByte + 1] = 1;
  std::size_t out = 0;
  if (sqlite3_deserialize(db, "main", copy, size, size,
                          SQLITE_DESERIALIZE_FREEONCLOSE | SQLITE_DESERIALIZE_RESIZEABLE) ==
      SQLITE_OK) {
    std::mt19937_64 random(seed);
    if (const auto cell = RandomCell(db, random); cell && RewriteCell(db, *cell, random)) {
      sqlite3_int64 bytes = 0;
      if (unsigned char* image = sqlite3_serialize(db, "main", &bytes, 0)) {
        if (static_cast<std::size_t>(bytes) <= max_size) {
          std::memcpy(data, image, static_cast<std::size_t>(bytes));
          out = static_cast<std::size_t>(bytes);
        }
        sqlite3_free(image);
      }
    }
  }
  sqlite3_close(db);
  return out;
}

}  // namespace
}  // namespace shockmap

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace shockmap;
  const std::string& db = DatabasePath();
  std::ofstream(db, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  ReadViews(db);
  Tolerating([&] {
    for (const std::string& study : StudyNames(db)) Tolerating([&] { ReadStudy(db, study); });
  });
  for (const char* file : {"", "-wal", "-shm", "-journal"}) unlink((db + file).c_str());
  return 0;
}

// Half of the mutations rewrite a cell through SQLite, the other half are libFuzzer's own on the
// file's bytes (pages, headers, the schema).
extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size,
                                               std::size_t max_size, unsigned seed) {
  if (seed % 2 == 0) {
    if (const std::size_t mutated = shockmap::MutateCell(data, size, max_size, seed / 2)) {
      return mutated;
    }
  }
  return LLVMFuzzerMutate(data, size, max_size);
}
