#include "db/scene_points.h"

#include "db/corrupt_rows.h"

namespace shockmap {

namespace {

// `text` with every `quote` doubled, between two of them: an SQL literal (') or identifier (").
std::string Quoted(const std::string& text, char quote) {
  std::string s(1, quote);
  for (char c : text) s += c == quote ? std::string(2, c) : std::string(1, c);
  return s + quote;
}

}  // namespace

std::string SceneParamsViewSql(Connection& c) {
  std::string columns;
  Statement paths = c.Prepare(
      "SELECT DISTINCT j.key FROM scene_points p, json_each(p.parameters_json) j ORDER BY j.key");
  while (paths.Step()) {
    const std::string path = paths.GetText(0);
    columns += ", json_extract(r.parameters_json, " + Quoted("$.\"" + path + "\"", '\'') + ") AS " +
               Quoted("params_" + path, '"');
  }
  return "CREATE VIEW scene_params AS SELECT r.*" + columns + " FROM scene_results r";
}

void RefreshSceneParamsView(Connection& c) {
  c.Execute("DROP VIEW IF EXISTS scene_params");
  c.Execute(SceneParamsViewSql(c));
}

const PointTable kScenePoints{"scene_points", {"parameters_json"}, RefreshSceneParamsView};

void WriteScore(Connection& c, std::int64_t point_id, const std::optional<SceneScoreRow>& score) {
  Statement update = c.Prepare(
      "UPDATE scene_points SET reference_id = ?, err = ?, srf = ?, coordinates = ?, zones = ?, "
      "dt_used_s = ?, dt_paper_s = ?, dt_sharp_s = ?, steps = ?, wall_s = ?, cpu_s = ?, "
      "max_energy_ratio = ?, largest_force_n = ?, largest_force_zone = ?, n_shocks = ?, "
      "first_shock_peak_n = ?, first_shock_impulse_n_s = ? WHERE point_id = ?");
  if (score) {
    const SceneScoreRow& r = *score;
    update.BindAll(r.reference_id, r.err, r.srf, r.coordinates, r.zones, r.dt_used_s, r.dt_paper_s,
                   r.dt_sharp_s, r.steps, r.wall_s, r.cpu_s, r.max_energy_ratio, r.largest_force_n,
                   r.largest_force_zone, r.n_shocks, r.first_shock_peak_n,
                   r.first_shock_impulse_n_s);
  } else {
    for (int i = 1; i <= 17; ++i) update.BindNull(i);
  }
  update.Bind(18, point_id).Run();
}

std::optional<SceneReferenceRow> FindSceneReference(StudyDatabase& db, const std::string& key) {
  using R = SceneReferenceRow;
  auto row =
      FindRow(db,
              "SELECT reference_id, parameters_json, status, message, output_dt_s, "
              "displacement_m, force_n, steps, wall_s, max_energy_ratio FROM scene_references "
              "WHERE reference_key = ?",
              key, &R::reference_key, &R::reference_id, &R::parameters_json, &R::status,
              &R::message, &R::output_dt_s, &R::displacement_m, &R::force_n, &R::steps, &R::wall_s,
              &R::max_energy_ratio);
  if (row) CheckSceneReference(db.Raw().Path(), *row);
  return row;
}

std::int64_t StoreSceneReference(StudyDatabase& db, const SceneReferenceRow& r,
                                 std::int64_t run_id) {
  return InsertRow(db,
                   "INSERT INTO scene_references(reference_key, parameters_json, status, message, "
                   "output_dt_s, displacement_m, force_n, steps, wall_s, max_energy_ratio, run_id, "
                   "created_utc) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
                   r.reference_key, r.parameters_json, r.status, r.message, r.output_dt_s,
                   r.displacement_m, r.force_n, r.steps, r.wall_s, r.max_energy_ratio, run_id,
                   UtcNow());
}

}  // namespace shockmap
