#include "db/canonical_points.h"

#include "db/corrupt_rows.h"

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

// The first shock's columns, all NULL when there was none.
template <typename Member>
std::optional<Member> FirstShock(const std::optional<ShockColumns>& f, Member ShockColumns::*m) {
  return f ? std::optional<Member>((*f).*m) : std::nullopt;
}

}  // namespace

void WriteScore(Connection& db, std::int64_t point_id, const std::optional<ScoreRow>& score) {
  db.Prepare("DELETE FROM scores WHERE point_id = ?").Bind(1, point_id).Run();
  if (!score) return;
  const ScoreRow& c = *score;
  const std::optional<ShockColumns>& f = c.first_shock;
  db.Prepare(
        "INSERT INTO scores(point_id, reference_id, err, srf, n_modes, n_elements, n_dofs, "
        "dt_requested_s, dt_used_s, dt_paper_s, dt_sharp_s, steps, wall_s, cpu_s, "
        "max_energy_ratio, n_shocks, first_shock_start_s, first_shock_impulse_n_s, "
        "first_shock_peak_n, first_shock_duration_s, first_shock_rebounds, shocks_json, "
        "srf_definition) "
        "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)")
      .BindAll(point_id, c.reference_id, c.err, c.srf, c.n_modes, c.n_elements, c.n_dofs,
               c.dt_requested_s, c.dt_used_s, c.dt_paper_s, c.dt_sharp_s, c.steps, c.wall_s,
               c.cpu_s, c.max_energy_ratio, c.n_shocks, FirstShock(f, &ShockColumns::start_s),
               FirstShock(f, &ShockColumns::impulse_n_s), FirstShock(f, &ShockColumns::peak_n),
               FirstShock(f, &ShockColumns::duration_s), FirstShock(f, &ShockColumns::rebounds),
               c.shocks_json, c.srf_definition)
      .Run();
}

std::optional<ReferenceRow> FindReference(StudyDatabase& db, const std::string& reference_key) {
  using R = ReferenceRow;
  auto row = FindRow(db,
                     "SELECT reference_id, r_k, r_fref, r_fref_check, window_s, convergence, "
                     "n_modes_free, n_modes_contact, n_transitions, wall_s, output_dt_s, tip_m, "
                     "force_n, shocks_json FROM reference_runs WHERE reference_key = ?",
                     reference_key, &R::reference_key, &R::reference_id, &R::r_k, &R::r_fref,
                     &R::r_fref_check, &R::window_s, &R::convergence, &R::n_modes_free,
                     &R::n_modes_contact, &R::n_transitions, &R::wall_s, &R::output_dt_s, &R::tip_m,
                     &R::force_n, &R::shocks_json);
  if (row) CheckReference(db.Raw().Path(), *row);
  return row;
}

std::int64_t StoreReference(StudyDatabase& db, const ReferenceRow& r, std::int64_t run_id) {
  return InsertRow(
      db,
      "INSERT INTO reference_runs(reference_key, r_k, r_fref, r_fref_check, window_s, "
      "convergence, n_modes_free, n_modes_contact, n_transitions, wall_s, output_dt_s, tip_m, "
      "force_n, shocks_json, run_id, created_utc) "
      "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
      r.reference_key, r.r_k, r.r_fref, r.r_fref_check, r.window_s, r.convergence, r.n_modes_free,
      r.n_modes_contact, r.n_transitions, r.wall_s, r.output_dt_s, r.tip_m, r.force_n,
      r.shocks_json, run_id, UtcNow());
}

}  // namespace shockmap
