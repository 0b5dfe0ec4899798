#include "db/canonical_points.h"

namespace shockmap {

const PointTable kCanonicalPoints{
    "points",
    {"r_k", "r_ftrunc", "scheme", "dt_rule", "dt_factor", "dt_asked_s", "window_s",
     "n_elements_asked", "mass_damping_per_s"}};

namespace {

SqlValue Optional(const std::optional<double>& v) { return v ? SqlValue(*v) : SqlValue(); }

}  // namespace

std::vector<SqlValue> ParameterValues(const PointParameters& p) {
  return {p.r_k,
          p.r_ftrunc,
          p.scheme,
          p.dt_rule ? SqlValue(*p.dt_rule) : SqlValue(),
          Optional(p.dt_factor),
          Optional(p.dt_asked_s),
          p.window_s,
          std::int64_t{p.n_elements_asked},
          p.mass_damping_per_s};
}

namespace {

void WriteScore(Connection& db, std::int64_t point_id, const std::optional<ScoreRow>& score) {
  db.Prepare("DELETE FROM scores WHERE point_id = ?").Bind(1, point_id).Run();
  if (score) {
    const ScoreRow& c = *score;
    Statement insert = db.Prepare(
        "INSERT INTO scores(point_id, reference_id, err, srf, n_modes, n_elements, n_dofs, "
        "dt_requested_s, dt_used_s, dt_paper_s, dt_sharp_s, steps, wall_s, cpu_s, "
        "max_energy_ratio, n_shocks, first_shock_start_s, first_shock_impulse_n_s, "
        "first_shock_peak_n, first_shock_duration_s, first_shock_rebounds, shocks_json) "
        "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
    insert.Bind(1, point_id)
        .Bind(2, c.reference_id)
        .Bind(3, c.err)
        .Bind(4, c.srf)
        .Bind(5, c.n_modes)
        .Bind(6, c.n_elements)
        .Bind(7, c.n_dofs)
        .Bind(8, c.dt_requested_s)
        .Bind(9, c.dt_used_s)
        .Bind(10, c.dt_paper_s)
        .Bind(11, c.dt_sharp_s)
        .Bind(12, c.steps)
        .Bind(13, c.wall_s)
        .Bind(14, c.cpu_s)
        .Bind(15, c.max_energy_ratio)
        .Bind(16, c.n_shocks);
    if (c.first_shock) {
      insert.Bind(17, c.first_shock->start_s)
          .Bind(18, c.first_shock->impulse_n_s)
          .Bind(19, c.first_shock->peak_n)
          .Bind(20, c.first_shock->duration_s)
          .Bind(21, c.first_shock->rebounds);
    } else {
      for (int i = 17; i <= 21; ++i) insert.BindNull(i);
    }
    insert.Bind(22, c.shocks_json).Run();
  }
}

}  // namespace

void StoreCanonicalOutcome(StudyDatabase& db, std::int64_t point_id, std::int64_t run_id,
                           const PointOrigin& origin, const std::string& status,
                           const std::string& message, const std::optional<ScoreRow>& score) {
  StorePointOutcome(db, kCanonicalPoints, point_id, run_id, origin, status, message,
                    [&](Connection& c) { WriteScore(c, point_id, score); });
}

std::optional<ReferenceRow> FindReference(StudyDatabase& db, const std::string& reference_key) {
  Statement s = db.Raw().Prepare(
      "SELECT reference_id, r_k, r_fref, r_fref_check, window_s, convergence, n_modes_free, "
      "n_modes_contact, n_transitions, wall_s, output_dt_s, tip_m, force_n, shocks_json "
      "FROM reference_runs WHERE reference_key = ?");
  s.Bind(1, reference_key);
  if (!s.Step()) return std::nullopt;
  ReferenceRow r;
  r.reference_id = s.GetInt(0);
  r.reference_key = reference_key;
  r.r_k = s.GetDouble(1);
  r.r_fref = s.GetDouble(2);
  r.r_fref_check = s.GetDouble(3);
  r.window_s = s.GetDouble(4);
  r.convergence = s.GetDouble(5);
  r.n_modes_free = static_cast<int>(s.GetInt(6));
  r.n_modes_contact = static_cast<int>(s.GetInt(7));
  r.n_transitions = static_cast<int>(s.GetInt(8));
  r.wall_s = s.GetDouble(9);
  r.output_dt_s = s.GetDouble(10);
  r.tip_m = s.GetBlob(11);
  r.force_n = s.GetBlob(12);
  r.shocks_json = s.GetText(13);
  return r;
}

std::int64_t StoreReference(StudyDatabase& db, const ReferenceRow& r, std::int64_t run_id) {
  Connection& c = db.Raw();
  Transaction t(c);
  c.Prepare(
       "INSERT INTO reference_runs(reference_key, r_k, r_fref, r_fref_check, window_s, "
       "convergence, n_modes_free, n_modes_contact, n_transitions, wall_s, output_dt_s, tip_m, "
       "force_n, shocks_json, run_id, created_utc) "
       "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)")
      .Bind(1, r.reference_key)
      .Bind(2, r.r_k)
      .Bind(3, r.r_fref)
      .Bind(4, r.r_fref_check)
      .Bind(5, r.window_s)
      .Bind(6, r.convergence)
      .Bind(7, r.n_modes_free)
      .Bind(8, r.n_modes_contact)
      .Bind(9, r.n_transitions)
      .Bind(10, r.wall_s)
      .Bind(11, r.output_dt_s)
      .Bind(12, r.tip_m)
      .Bind(13, r.force_n)
      .Bind(14, r.shocks_json)
      .Bind(15, run_id)
      .Bind(16, UtcNow())
      .Run();
  const std::int64_t id = c.LastInsertRowId();
  t.Commit();
  return id;
}

}  // namespace shockmap
