#include "db/ensemble_members.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <map>
#include <string>
#include <vector>

#include "db/corrupt_rows.h"
#include "db/read_only_query.h"
#include "db/stored_json.h"

namespace shockmap {

namespace {

void InsertZones(Connection& c, std::int64_t point_id, const std::vector<EnsembleZoneRow>& zones) {
  static const std::string kInsert = "INSERT INTO ensemble_member_zones(point_id, zone, " +
                                     ColumnList(kEnsembleZoneColumns) + ") VALUES (?, ?, " +
                                     Placeholders(std::size(kEnsembleZoneColumns)) + ")";
  Statement& insert = c.Cached(kInsert);
  for (std::size_t i = 0; i < zones.size(); ++i) {
    insert.Reset();
    insert.Bind(1, point_id).Bind(2, static_cast<std::int64_t>(i));
    BindRecord(insert, 3, zones[i], kEnsembleZoneColumns);
    insert.Run();
  }
}

void InsertImpacts(Connection& c, std::int64_t point_id,
                   const std::vector<EnsembleImpactRow>& impacts) {
  static const std::string kInsert = "INSERT INTO ensemble_member_impacts(point_id, " +
                                     ColumnList(kEnsembleImpactColumns) + ") VALUES (?, " +
                                     Placeholders(std::size(kEnsembleImpactColumns)) + ")";
  Statement& insert = c.Cached(kInsert);
  for (const EnsembleImpactRow& impact : impacts) {
    insert.Reset();
    insert.Bind(1, point_id);
    BindRecord(insert, 2, impact, kEnsembleImpactColumns);
    insert.Run();
  }
}

// A nominal run's largest forces, one per zone, are finite (the zones' count is the views'
// to check against zones_json).
void CheckEnsembleReference(const std::string& database_path, const EnsembleReferenceRow& r) {
  CheckFinite(database_path, "ensemble reference " + std::to_string(r.reference_id),
              {"max_force_n", r.max_force_n});
}

std::vector<EnsembleReferenceRow> ReadReferences(Connection& c, std::int64_t study_id) {
  Statement s = c.Prepare("SELECT reference_id, " + ColumnList(kEnsembleReferenceColumns) +
                          " FROM ensemble_references WHERE reference_id IN (SELECT reference_id "
                          "FROM ensemble_members WHERE study_id = ?) ORDER BY reference_id");
  s.Bind(1, study_id);
  std::vector<EnsembleReferenceRow> rows;
  while (s.Step()) {
    EnsembleReferenceRow r;
    s.ReadColumn(0, r.reference_id);
    ReadRecord(s, 1, r, kEnsembleReferenceColumns, c.Path(),
               [&] { return "ensemble reference " + std::to_string(r.reference_id); });
    CheckEnsembleReference(c.Path(), r);
    rows.push_back(std::move(r));
  }
  return rows;
}

std::vector<StoredMember> ReadMembers(Connection& c, std::int64_t study_id) {
  Statement s = c.Prepare(
      "SELECT p.point_id, p.state, p.setting_json, p.member, p.wall_s, p.cpu_s, z.zone, " +
      ColumnList(kEnsembleZoneColumns, "z.") +
      " FROM ensemble_members p LEFT JOIN ensemble_member_zones z ON z.point_id = p.point_id "
      "WHERE p.study_id = ? AND p.status = 'ok' ORDER BY p.point_id, z.zone");
  s.Bind(1, study_id);
  std::vector<StoredMember> members;
  while (s.Step()) {
    const std::int64_t id = s.GetInt(0);
    if (members.empty() || members.back().point_id != id) {
      StoredMember m;
      m.point_id = id;
      s.ReadColumns(m.point_id, m.state, m.setting_json, m.member, m.wall_s, m.cpu_s);
      m.status = "ok";
      members.push_back(std::move(m));
    }
    if (s.IsNull(6)) continue;  // A member without zone rows (CheckEnsemble refuses it).
    members.back().zone_indices.push_back(s.GetInt(6));
    ReadRecord(s, 7, members.back().zones.emplace_back(), kEnsembleZoneColumns, c.Path(), [&] {
      return "member " + std::to_string(id) + ", zone " + std::to_string(s.GetInt(6));
    });
  }
  return members;
}

std::vector<StoredMember> ReadMembersNotOk(Connection& c, std::int64_t study_id) {
  Statement s = c.Prepare(
      "SELECT point_id, state, setting_json, member, status FROM ensemble_members WHERE "
      "study_id = ? AND status != 'ok' ORDER BY point_id");
  s.Bind(1, study_id);
  std::vector<StoredMember> members;
  while (s.Step()) {
    StoredMember m;
    s.ReadColumns(m.point_id, m.state, m.setting_json, m.member, m.status);
    members.push_back(std::move(m));
  }
  return members;
}

}  // namespace

void WriteScore(Connection& c, std::int64_t point_id,
                const std::optional<EnsembleMemberRow>& score) {
  c.Cached("DELETE FROM ensemble_member_zones WHERE point_id = ?").Bind(1, point_id).Run();
  c.Cached("DELETE FROM ensemble_member_impacts WHERE point_id = ?").Bind(1, point_id).Run();
  static const std::string kUpdate =
      "UPDATE ensemble_members SET " + Assignments(kEnsembleMemberColumns) + " WHERE point_id = ?";
  Statement& update = c.Cached(kUpdate);
  const int next = score ? BindRecord(update, 1, *score, kEnsembleMemberColumns)
                         : BindNulls(update, 1, kEnsembleMemberColumns);
  if (score) InsertZones(c, point_id, score->zones);
  if (score) InsertImpacts(c, point_id, score->impacts);
  update.Bind(next, point_id).Run();
}

std::optional<EnsembleReferenceRow> FindEnsembleReference(StudyDatabase& db,
                                                          const std::string& key) {
  auto row = FindReferenceRow<EnsembleReferenceRow>(db, "ensemble_references", "ensemble reference",
                                                    key, kEnsembleReferenceColumns);
  if (row) CheckEnsembleReference(db.Raw().Path(), *row);
  return row;
}

std::int64_t StoreEnsembleReference(StudyDatabase& db, const EnsembleReferenceRow& reference,
                                    std::int64_t run_id) {
  return InsertReference(db, "ensemble_references", reference, kEnsembleReferenceColumns, run_id);
}

namespace {

// The indices of the zones named `name` when more than one zone is, else empty.
std::vector<std::size_t> ZonesNamedTwice(const std::vector<std::string>& names) {
  std::map<std::string, std::vector<std::size_t>> indices;
  for (std::size_t i = 0; i < names.size(); ++i) indices[names[i]].push_back(i);
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (indices[names[i]].size() > 1) return indices[names[i]];
  }
  return {};
}

// The zones of a nominal run, by name, from its zones_json: [{"name": ..., ...}, ...]; every
// name once (the views label rows and columns by them).
std::size_t ZoneCount(const std::string& database_path, const EnsembleReferenceRow& r) {
  const StoredCell cell{database_path, "ensemble reference " + std::to_string(r.reference_id),
                        "zones_json"};
  const auto names = ReadStoredJson(cell, r.zones_json, [](const nlohmann::json& zones) {
    std::vector<std::string> names;
    for (const auto& z : zones.get<std::vector<nlohmann::json>>())
      names.push_back(z.at("name").get<std::string>());
    return names;
  });
  if (const auto twice = ZonesNamedTwice(names); !twice.empty()) {
    ThrowCorruptCell(cell, fmt::format("zones {} are all named \"{}\"; zone names must be unique "
                                       "(run the study again into a new database)",
                                       fmt::join(twice, ", "), names[twice.front()]));
  }
  const std::size_t zones = names.size();
  if (!r.max_force_n.empty() && r.max_force_n.size() != zones) {
    ThrowCorruptCell(cell, fmt::format("{} zones, but max_force_n holds {} forces", zones,
                                       r.max_force_n.size()));
  }
  return zones;
}

// A member's setting_json is a JSON object, {"path": value}.
void CheckSetting(const std::string& database_path, const StoredMember& m) {
  const StoredCell setting{database_path, "ensemble member " + std::to_string(m.point_id),
                           "setting_json"};
  if (!ParseStoredJson(setting, m.setting_json).is_object()) {
    ThrowCorruptCell(setting, "not a JSON object");
  }
}

// Whether `indices` are 0, 1, ..., count - 1.
bool AreZeroTo(const std::vector<std::int64_t>& indices, std::size_t count) {
  if (indices.size() != count) return false;
  for (std::size_t i = 0; i < count; ++i) {
    if (indices[i] != static_cast<std::int64_t>(i)) return false;
  }
  return true;
}

// What the views read of a stored ensemble is whole: its spec and settings are JSON objects,
// every nominal run names the same zones, and every member has one row for each, by its index.
void CheckEnsemble(const std::string& database_path, const std::string& study,
                   const StoredEnsemble& e) {
  const StoredCell spec{database_path, "study " + study, "spec_json"};
  if (!ParseStoredJson(spec, e.spec_json).is_object()) ThrowCorruptCell(spec, "not a JSON object");
  std::optional<std::size_t> zones;
  for (const EnsembleReferenceRow& r : e.references) {
    if (r.zones_json.empty()) continue;
    const std::size_t count = ZoneCount(database_path, r);
    if (zones && count != *zones) {
      ThrowCorrupt(database_path, "ensemble reference " + std::to_string(r.reference_id),
                   fmt::format("{} zones, another nominal run of the study {}", count, *zones));
    }
    zones = count;
  }
  for (const StoredMember& m : e.not_ok) CheckSetting(database_path, m);
  for (const StoredMember& m : e.members) {
    CheckSetting(database_path, m);
    const std::string row = "ensemble member " + std::to_string(m.point_id);
    if (zones && m.zones.size() != *zones) {
      ThrowCorrupt(database_path, row,
                   fmt::format("{} zone rows, its nominal run {} zones", m.zones.size(), *zones));
    }
    if (zones && !AreZeroTo(m.zone_indices, *zones)) {
      ThrowCorrupt(database_path, row,
                   fmt::format("zone rows {}; its nominal run has zones 0 to {}",
                               fmt::join(m.zone_indices, ", "), *zones - 1));
    }
  }
}

}  // namespace

StoredEnsemble ReadEnsemble(Connection& c, const std::string& study) {
  Statement find = c.Prepare(
      "SELECT s.study_id, s.spec_json, (SELECT count(*) FROM ensemble_members p WHERE "
      "p.study_id = s.study_id), (SELECT count(*) FROM ensemble_members p WHERE p.study_id = "
      "s.study_id AND p.status IN ('pending', 'running')), (SELECT count(*) FROM "
      "ensemble_members p WHERE p.study_id = s.study_id AND p.status NOT IN ('pending', "
      "'running', 'ok')) FROM studies s WHERE s.name = ?");
  find.Bind(1, study);
  if (!find.Step()) throw DbError(c.Path() + ": no study named \"" + study + "\"");
  std::int64_t study_id = 0, members = 0;
  StoredEnsemble e;
  e.database_path = c.Path();
  e.study = study;
  find.ReadColumns(study_id, e.spec_json, members, e.pending, e.failed);
  if (members == 0) {
    throw DbError(c.Path() + ": study \"" + study + "\" is not an ensemble study");
  }
  e.references = ReadReferences(c, study_id);
  e.members = ReadMembers(c, study_id);
  e.not_ok = ReadMembersNotOk(c, study_id);
  CheckEnsemble(c.Path(), study, e);
  return e;
}

Table EnsembleImpacts(const std::string& database_path, const std::string& study) {
  return RunReadOnlyQuery(
      database_path,
      "SELECT p.point_id, p.state, p.setting_json, p.member, "
      "json_extract(r.zones_json, '$[' || i.zone || '].name') AS zone_name, " +
          ColumnList(kEnsembleImpactColumns, "i.") +
          " FROM ensemble_member_impacts i JOIN ensemble_members p ON p.point_id = i.point_id "
          "JOIN studies st ON st.study_id = p.study_id LEFT JOIN ensemble_references r ON "
          "r.reference_id = p.reference_id WHERE st.name = ?1 AND p.status = 'ok' "
          "ORDER BY p.point_id, i.zone, i.impact",
      {study});
}

std::vector<std::string> EnsembleStudies(Connection& c) {
  Statement s = c.Prepare(
      "SELECT name FROM studies WHERE study_id IN (SELECT study_id FROM ensemble_members) "
      "ORDER BY study_id");
  std::vector<std::string> names;
  while (s.Step()) names.push_back(s.GetText(0));
  return names;
}

}  // namespace shockmap
