#pragma once
// The migrations of the study database, in order: migration i brings PRAGMA user_version from i
// to i + 1, and the schema's version is their count. Append-only: a migration once released is
// never edited (a file migrated by it exists somewhere); a change of the schema is a new one at
// the end, and docs/database.md follows (tests/records_test.cpp checks the tables against the
// records' column tables, docs/architecture.md "Add a field"). The migrations change tables
// only: the views hold no data and are declared once (db/result_views.h), dropped before
// migrating and written again after (db/schema.cpp); their statements, which earlier versions
// wrote here, were taken out of the migrations that held them.

#include <iterator>

namespace shockmap {

inline constexpr const char* kMigrations[] = {
    R"sql(
CREATE TABLE studies (
  study_id    INTEGER PRIMARY KEY,
  name        TEXT NOT NULL UNIQUE,
  spec_json   TEXT NOT NULL,
  created_utc TEXT NOT NULL,
  updated_utc TEXT NOT NULL
);
CREATE TABLE runs (
  run_id       INTEGER PRIMARY KEY,
  study_id     INTEGER NOT NULL REFERENCES studies(study_id),
  code_version TEXT NOT NULL,
  compiler     TEXT NOT NULL,
  build_type   TEXT NOT NULL,
  host         TEXT NOT NULL,
  pid          INTEGER NOT NULL,
  jobs         INTEGER NOT NULL,
  started_utc  TEXT NOT NULL,
  ended_utc    TEXT,
  points_done  INTEGER NOT NULL DEFAULT 0
);
CREATE TABLE reference_runs (
  reference_id    INTEGER PRIMARY KEY,
  reference_key   TEXT NOT NULL UNIQUE,
  r_k             REAL NOT NULL,
  r_fref          REAL NOT NULL,
  r_fref_check    REAL NOT NULL,
  window_s        REAL NOT NULL,
  convergence     REAL NOT NULL,
  n_modes_free    INTEGER NOT NULL,
  n_modes_contact INTEGER NOT NULL,
  n_transitions   INTEGER NOT NULL,
  wall_s          REAL NOT NULL,
  output_dt_s     REAL NOT NULL,
  tip_m           BLOB NOT NULL,
  force_n         BLOB NOT NULL,
  shocks_json     TEXT NOT NULL,
  run_id          INTEGER REFERENCES runs(run_id),
  created_utc     TEXT NOT NULL
);
CREATE TABLE points (
  point_id           INTEGER PRIMARY KEY,
  study_id           INTEGER NOT NULL REFERENCES studies(study_id),
  point_key          TEXT NOT NULL,
  reference_key      TEXT NOT NULL,
  r_k                REAL NOT NULL,
  r_ftrunc           REAL NOT NULL,
  scheme             TEXT NOT NULL,
  dt_rule            TEXT,
  dt_factor          REAL,
  dt_asked_s         REAL,
  window_s           REAL NOT NULL,
  n_elements_asked   INTEGER NOT NULL,
  mass_damping_per_s REAL NOT NULL,
  status             TEXT NOT NULL DEFAULT 'pending'
    CHECK (status IN ('pending', 'running', 'ok', 'diverged', 'failed', 'reference_unconverged')),
  message            TEXT NOT NULL DEFAULT '',
  run_id             INTEGER REFERENCES runs(run_id),
  updated_utc        TEXT NOT NULL,
  UNIQUE (study_id, point_key)
);
CREATE INDEX points_by_status ON points(study_id, status);
CREATE TABLE scores (
  point_id                 INTEGER PRIMARY KEY REFERENCES points(point_id),
  reference_id             INTEGER NOT NULL REFERENCES reference_runs(reference_id),
  err                      REAL,
  srf                      REAL,
  n_modes                  INTEGER NOT NULL,
  n_elements               INTEGER NOT NULL,
  n_dofs                   INTEGER NOT NULL,
  dt_requested_s           REAL NOT NULL,
  dt_used_s                REAL NOT NULL,
  dt_paper_s               REAL NOT NULL,
  dt_sharp_s               REAL NOT NULL,
  steps                    INTEGER NOT NULL,
  wall_s                   REAL NOT NULL,
  cpu_s                    REAL NOT NULL,
  max_energy_ratio         REAL NOT NULL,
  n_shocks                 INTEGER NOT NULL,
  first_shock_start_s      REAL,
  first_shock_impulse_n_s  REAL,
  first_shock_peak_n       REAL,
  first_shock_duration_s   REAL,
  first_shock_rebounds     INTEGER,
  shocks_json              TEXT NOT NULL
);
)sql",
    // 1 -> 2: studies of scene files. A point is the scene with some numeric parameters set
    // (parameters_json: {"solver.r_ftrunc": 30, ...}); it is scored against the same scene run
    // with the study's reference settings.
    R"sql(
CREATE TABLE scene_references (
  reference_id     INTEGER PRIMARY KEY,
  reference_key    TEXT NOT NULL UNIQUE,
  parameters_json  TEXT NOT NULL,
  status           TEXT NOT NULL,
  message          TEXT NOT NULL,
  output_dt_s      REAL NOT NULL,
  displacement_m   BLOB NOT NULL,
  force_n          BLOB NOT NULL,
  steps            INTEGER NOT NULL,
  wall_s           REAL NOT NULL,
  max_energy_ratio REAL NOT NULL,
  run_id           INTEGER REFERENCES runs(run_id),
  created_utc      TEXT NOT NULL
);
CREATE TABLE scene_points (
  point_id                INTEGER PRIMARY KEY,
  study_id                INTEGER NOT NULL REFERENCES studies(study_id),
  point_key               TEXT NOT NULL,
  reference_key           TEXT NOT NULL,
  parameters_json         TEXT NOT NULL,
  status                  TEXT NOT NULL DEFAULT 'pending'
    CHECK (status IN ('pending', 'running', 'ok', 'diverged', 'failed', 'reference_unconverged')),
  message                 TEXT NOT NULL DEFAULT '',
  run_id                  INTEGER REFERENCES runs(run_id),
  updated_utc             TEXT NOT NULL,
  reference_id            INTEGER REFERENCES scene_references(reference_id),
  err                     REAL,
  srf                     REAL,
  coordinates             INTEGER,
  zones                   INTEGER,
  dt_used_s               REAL,
  dt_paper_s              REAL,
  dt_sharp_s              REAL,
  steps                   INTEGER,
  wall_s                  REAL,
  cpu_s                   REAL,
  max_energy_ratio        REAL,
  largest_force_n         REAL,
  largest_force_zone      TEXT,
  n_shocks                INTEGER,
  first_shock_peak_n      REAL,
  first_shock_impulse_n_s REAL,
  UNIQUE (study_id, point_key)
);
CREATE INDEX scene_points_by_status ON scene_points(study_id, status);
)sql",
    // 2 -> 3: the writer's lease. A run holds the database while its heartbeat is recent
    // (db/study_database.h); how each run ended.
    R"sql(
ALTER TABLE runs ADD COLUMN heartbeat_unix_s REAL;
ALTER TABLE runs ADD COLUMN end_reason TEXT;
UPDATE runs SET end_reason = 'completed' WHERE ended_utc IS NOT NULL;
)sql",
    // 3 -> 4: where each point was computed: host and MPI rank (0 in a local run). Points
    // stored before take their run's host and rank 0; the views show the point's own. How a
    // stopped run ended, in words (the tasks an MPI job got no answer for).
    R"sql(
ALTER TABLE runs ADD COLUMN end_message TEXT;
ALTER TABLE points ADD COLUMN host TEXT;
ALTER TABLE points ADD COLUMN rank INTEGER;
ALTER TABLE scene_points ADD COLUMN host TEXT;
ALTER TABLE scene_points ADD COLUMN rank INTEGER;
UPDATE points SET host = (SELECT host FROM runs WHERE runs.run_id = points.run_id), rank = 0
WHERE run_id IS NOT NULL AND status NOT IN ('pending', 'running');
UPDATE scene_points SET host = (SELECT host FROM runs WHERE runs.run_id = scene_points.run_id),
  rank = 0
WHERE run_id IS NOT NULL AND status NOT IN ('pending', 'running');
)sql",
    // 4 -> 5: the SRf definition each score was computed with (paper eq. 9 admits several
    // readings); scores stored before used the first shock.
    R"sql(
ALTER TABLE scores ADD COLUMN srf_definition TEXT NOT NULL DEFAULT 'first_shock';
)sql",
    // 5 -> 6: scene study parameters as columns, params_<path> beside scene_results (as
    // Optuna's params_*): the view scene_params (db/point_tables.h), written again whenever scene
    // points are added, with one column per parameter path of any scene study. No table changes.
    R"sql()sql",
    // 6 -> 7: the status 'unstable' (core/run_status.h, docs/physics.md §3.1). SQLite cannot
    // change a CHECK constraint in place: both point tables are rebuilt with the same columns in
    // the same order (foreign keys are off while migrating, so the scores keep their rows; the
    // views that read them are dropped before migrating). Stored canonical points that ended 'ok'
    // undamped with an energy ratio above the limit become 'unstable', as a new run classifies
    // them; scene points keep their status until recomputed (their damping is in their scene, not
    // in a column).
    R"sql(
CREATE TABLE points_v7 (
  point_id           INTEGER PRIMARY KEY,
  study_id           INTEGER NOT NULL REFERENCES studies(study_id),
  point_key          TEXT NOT NULL,
  reference_key      TEXT NOT NULL,
  r_k                REAL NOT NULL,
  r_ftrunc           REAL NOT NULL,
  scheme             TEXT NOT NULL,
  dt_rule            TEXT,
  dt_factor          REAL,
  dt_asked_s         REAL,
  window_s           REAL NOT NULL,
  n_elements_asked   INTEGER NOT NULL,
  mass_damping_per_s REAL NOT NULL,
  status             TEXT NOT NULL DEFAULT 'pending'
    CHECK (status IN ('pending', 'running', 'ok', 'diverged', 'unstable', 'failed',
                      'reference_unconverged')),
  message            TEXT NOT NULL DEFAULT '',
  run_id             INTEGER REFERENCES runs(run_id),
  updated_utc        TEXT NOT NULL,
  host               TEXT,
  rank               INTEGER,
  UNIQUE (study_id, point_key)
);
INSERT INTO points_v7 SELECT point_id, study_id, point_key, reference_key, r_k, r_ftrunc, scheme,
  dt_rule, dt_factor, dt_asked_s, window_s, n_elements_asked, mass_damping_per_s, status,
  message, run_id, updated_utc, host, rank FROM points;
DROP TABLE points;
ALTER TABLE points_v7 RENAME TO points;
CREATE INDEX points_by_status ON points(study_id, status);
UPDATE points SET status = 'unstable',
  message = 'undamped, energy grew to ' ||
    (SELECT printf('%.6g', max_energy_ratio) FROM scores WHERE scores.point_id = points.point_id) ||
    ' times its initial value (unstable above 5)'
WHERE status = 'ok' AND mass_damping_per_s = 0
  AND point_id IN (SELECT point_id FROM scores WHERE max_energy_ratio > 5);
CREATE TABLE scene_points_v7 (
  point_id                INTEGER PRIMARY KEY,
  study_id                INTEGER NOT NULL REFERENCES studies(study_id),
  point_key               TEXT NOT NULL,
  reference_key           TEXT NOT NULL,
  parameters_json         TEXT NOT NULL,
  status                  TEXT NOT NULL DEFAULT 'pending'
    CHECK (status IN ('pending', 'running', 'ok', 'diverged', 'unstable', 'failed',
                      'reference_unconverged')),
  message                 TEXT NOT NULL DEFAULT '',
  run_id                  INTEGER REFERENCES runs(run_id),
  updated_utc             TEXT NOT NULL,
  reference_id            INTEGER REFERENCES scene_references(reference_id),
  err                     REAL,
  srf                     REAL,
  coordinates             INTEGER,
  zones                   INTEGER,
  dt_used_s               REAL,
  dt_paper_s              REAL,
  dt_sharp_s              REAL,
  steps                   INTEGER,
  wall_s                  REAL,
  cpu_s                   REAL,
  max_energy_ratio        REAL,
  largest_force_n         REAL,
  largest_force_zone      TEXT,
  n_shocks                INTEGER,
  first_shock_peak_n      REAL,
  first_shock_impulse_n_s REAL,
  host                    TEXT,
  rank                    INTEGER,
  UNIQUE (study_id, point_key)
);
INSERT INTO scene_points_v7 SELECT point_id, study_id, point_key, reference_key, parameters_json,
  status, message, run_id, updated_utc, reference_id, err, srf, coordinates, zones, dt_used_s,
  dt_paper_s, dt_sharp_s, steps, wall_s, cpu_s, max_energy_ratio, largest_force_n,
  largest_force_zone, n_shocks, first_shock_peak_n, first_shock_impulse_n_s, host, rank
FROM scene_points;
DROP TABLE scene_points;
ALTER TABLE scene_points_v7 RENAME TO scene_points;
CREATE INDEX scene_points_by_status ON scene_points(study_id, status);
)sql",
    // 7 -> 8: ensemble studies of a scene (specs/ensemble_study_spec.h). A point is one
    // member: a clearance state, a numerical setting and the member's index; its zones' rows
    // hold the largest force and the impact statistics of the member's run. A reference is a
    // state's nominal run (every draw at its centre) at the refined setting.
    R"sql(
CREATE TABLE ensemble_references (
  reference_id     INTEGER PRIMARY KEY,
  reference_key    TEXT NOT NULL UNIQUE,
  state            TEXT NOT NULL,
  status           TEXT NOT NULL,
  message          TEXT NOT NULL,
  zones_json       TEXT NOT NULL,
  max_force_n      BLOB NOT NULL,
  steps            INTEGER NOT NULL,
  wall_s           REAL NOT NULL,
  run_id           INTEGER REFERENCES runs(run_id),
  created_utc      TEXT NOT NULL
);
CREATE TABLE ensemble_members (
  point_id         INTEGER PRIMARY KEY,
  study_id         INTEGER NOT NULL REFERENCES studies(study_id),
  point_key        TEXT NOT NULL,
  reference_key    TEXT NOT NULL,
  state            TEXT NOT NULL,
  setting_json     TEXT NOT NULL,
  member           INTEGER NOT NULL,
  status           TEXT NOT NULL DEFAULT 'pending'
    CHECK (status IN ('pending', 'running', 'ok', 'diverged', 'unstable', 'failed',
                      'reference_unconverged')),
  message          TEXT NOT NULL DEFAULT '',
  run_id           INTEGER REFERENCES runs(run_id),
  updated_utc      TEXT NOT NULL,
  host             TEXT,
  rank             INTEGER,
  reference_id     INTEGER REFERENCES ensemble_references(reference_id),
  member_seed      TEXT,
  coordinates      INTEGER,
  dt_used_s        REAL,
  steps            INTEGER,
  wall_s           REAL,
  cpu_s            REAL,
  max_energy_ratio REAL,
  UNIQUE (study_id, point_key)
);
CREATE INDEX ensemble_members_by_status ON ensemble_members(study_id, status);
CREATE TABLE ensemble_member_zones (
  point_id                  INTEGER NOT NULL REFERENCES ensemble_members(point_id),
  zone                      INTEGER NOT NULL,
  max_force_n               REAL NOT NULL,
  impacts                   INTEGER,
  impacts_per_s             REAL,
  rebounds_per_impact       REAL,
  mean_impact_duration_s    REAL,
  longest_impact_duration_s REAL,
  contact_time_fraction     REAL,
  mean_force_n              REAL,
  mean_force_in_contact_n   REAL,
  rms_force_n               REAL,
  impulse_n_s               REAL,
  wear_work_rate_w          REAL,
  PRIMARY KEY (point_id, zone)
) WITHOUT ROWID;
)sql",
    // 8 -> 9: a member refers to its nominal run by its state's name, not by the nominal run's
    // key, which holds the whole scene: a million members repeated it into gigabytes. The key
    // stays, once, in ensemble_references.
    R"sql(
UPDATE ensemble_members SET reference_key = state;
)sql",
    // 9 -> 10: the peak-force ratio of the first shock (validation/scores.h, "pfr"), a score of
    // both kinds scored against a reference, at the end of their results views. Points stored
    // before have none until computed again.
    R"sql(
ALTER TABLE scores ADD COLUMN pfr REAL;
ALTER TABLE scene_points ADD COLUMN pfr REAL;
)sql",
    // 10 -> 11: a member zone's Archard wear volume over the scene's wear life and its friction
    // power, and one row per impact of the zones a member's scene lists
    // (outputs.impact_statistics.impact_table); records/ensemble_records.h. Members stored before
    // have none until computed again.
    R"sql(
ALTER TABLE ensemble_member_zones ADD COLUMN wear_volume_m3 REAL;
ALTER TABLE ensemble_member_zones ADD COLUMN friction_power_w REAL;
CREATE TABLE ensemble_member_impacts (
  point_id         INTEGER NOT NULL REFERENCES ensemble_members(point_id),
  zone             INTEGER NOT NULL,
  impact           INTEGER NOT NULL,
  start_s          REAL NOT NULL,
  duration_s       REAL NOT NULL,
  peak_force_n     REAL NOT NULL,
  peak_time_s      REAL NOT NULL,
  impulse_n_s      REAL NOT NULL,
  impact_speed_m_s REAL,
  rebounds         INTEGER NOT NULL,
  truncated        INTEGER NOT NULL,
  PRIMARY KEY (point_id, zone, impact)
) WITHOUT ROWID;
)sql",
    // 11 -> 12: a point's scores under rounding-level perturbations (compare/score_spread.h:
    // their smallest and largest value over the runs, where the study takes them) and the parts
    // of a reference's estimated error (tip, first-shock impulse, induced Err), both at the end
    // of the results view. Rows stored before have none.
    R"sql(
ALTER TABLE scores ADD COLUMN spread_runs INTEGER;
ALTER TABLE scores ADD COLUMN err_spread_low REAL;
ALTER TABLE scores ADD COLUMN err_spread_high REAL;
ALTER TABLE scores ADD COLUMN srf_spread_low REAL;
ALTER TABLE scores ADD COLUMN srf_spread_high REAL;
ALTER TABLE scores ADD COLUMN pfr_spread_low REAL;
ALTER TABLE scores ADD COLUMN pfr_spread_high REAL;
ALTER TABLE reference_runs ADD COLUMN estimate_tip REAL;
ALTER TABLE reference_runs ADD COLUMN estimate_impulse REAL;
ALTER TABLE reference_runs ADD COLUMN estimate_err REAL;
)sql",
    // 12 -> 13: a scene point refers to its reference by the reference's parameters as JSON
    // (the "parameters" member of the reference's key, as ParametersJson wrote it there), not by
    // the key, which holds the whole scene: each point's row filled a page of its own, written
    // twice (log, then file) at every store. The key stays, once, in scene_references. A key
    // without such a member (a file edited by hand) is left as it was: a run finds no reference
    // by it, or refuses it as a corrupt cell when it is not a JSON object
    // (SceneStudy::FindReference).
    R"sql(
UPDATE scene_points SET reference_key = json_extract(reference_key, '$.parameters')
WHERE CASE WHEN json_valid(reference_key)
           THEN json_type(reference_key, '$.parameters') = 'object' ELSE 0 END;
)sql",
    // 13 -> 14: a pin that meets the wrapper on several faces (every outer pin of a hexagonal
    // bundle, the single pin of a row) names each face by the direction of its normal
    // (formats/scene_file.cpp, BundleZoneName): "pin_0-wrapper@0.9144", which earlier versions
    // gave to every face, becomes "pin_0-wrapper_60deg@0.9144". A nominal run's zones_json is
    // renamed where the face is derivable: the pin's centre is the mean of the positions of the
    // generated zones it takes part in at that height (6 on a hexagonal lattice, 2 for a row's
    // single pin), and the face is the direction from it to the zone, one of 0, 60, ..., 300
    // degrees (180 or 0 in a row). Other names are left as they were (the readers refuse names
    // given twice). Zone rows are stored by index and are untouched.
    R"sql(
CREATE TEMP TABLE migrating_zones AS
SELECT r.reference_id, CAST(j.key AS INTEGER) AS i, json_extract(j.value, '$.name') AS name,
       json_extract(j.value, '$.beam_a') AS beam_a, json_extract(j.value, '$.beam_b') AS beam_b,
       json_extract(j.value, '$.height_m') AS height_m, json_extract(j.value, '$.y_m') AS y_m,
       json_extract(j.value, '$.z_m') AS z_m
FROM ensemble_references r,
     json_each(CASE WHEN json_valid(r.zones_json) AND json_type(r.zones_json) = 'array'
                    THEN r.zones_json ELSE '[]' END) j
WHERE j.type = 'object';
DELETE FROM migrating_zones
WHERE typeof(name) != 'text' OR typeof(beam_a) != 'text' OR typeof(beam_b) != 'text'
   OR typeof(height_m) NOT IN ('real', 'integer') OR typeof(y_m) NOT IN ('real', 'integer')
   OR typeof(z_m) NOT IN ('real', 'integer')
   OR substr(name, 1, length(beam_a) + length(beam_b) + 2) != beam_a || '-' || beam_b || '@';
CREATE INDEX temp.migrating_zones_by_name ON migrating_zones(reference_id, name);
CREATE INDEX temp.migrating_zones_by_height ON migrating_zones(reference_id, height_m);
CREATE TEMP TABLE zone_faces AS
WITH pins AS (
  SELECT w.reference_id, w.beam_a AS pin, w.height_m, avg(o.y_m) AS y_m, avg(o.z_m) AS z_m,
         count(*) AS zones
  FROM (SELECT DISTINCT reference_id, beam_a, height_m FROM migrating_zones
        WHERE beam_b = 'wrapper') w
  JOIN migrating_zones o ON o.reference_id = w.reference_id AND o.height_m = w.height_m
                        AND w.beam_a IN (o.beam_a, o.beam_b)
  GROUP BY w.reference_id, w.beam_a, w.height_m
), faces AS (
  SELECT f.reference_id, f.i, f.name, f.beam_a, f.y_m - p.y_m AS dy, f.z_m - p.z_m AS dz
  FROM migrating_zones f
  JOIN pins p ON p.reference_id = f.reference_id AND p.pin = f.beam_a AND p.height_m = f.height_m
  WHERE f.beam_b = 'wrapper' AND f.beam_a LIKE 'pin\_%' ESCAPE '\' AND p.zones IN (2, 6)
    AND EXISTS (SELECT 1 FROM migrating_zones d
                WHERE d.reference_id = f.reference_id AND d.name = f.name AND d.i != f.i)
)
SELECT reference_id, i,
       beam_a || '-wrapper_' ||
         CASE WHEN abs(dz) < 0.5 * abs(dy) THEN CASE WHEN dy > 0 THEN 0 ELSE 180 END
              WHEN dz > 0 THEN CASE WHEN dy > 0 THEN 60 ELSE 120 END
              ELSE CASE WHEN dy > 0 THEN 300 ELSE 240 END END ||
         'deg' || substr(name, length(beam_a) + length('-wrapper') + 1) AS name
FROM faces;
CREATE INDEX temp.zone_faces_by_zone ON zone_faces(reference_id, i);
CREATE TEMP TABLE renamed_zones AS
SELECT reference_id, zones_json FROM (
  SELECT r.reference_id, CAST(j.key AS INTEGER) AS i,
         json_group_array(CASE WHEN f.name IS NULL THEN json(j.value)
                               ELSE json_set(j.value, '$.name', f.name) END)
           OVER (PARTITION BY r.reference_id ORDER BY CAST(j.key AS INTEGER)
                 ROWS BETWEEN UNBOUNDED PRECEDING AND UNBOUNDED FOLLOWING) AS zones_json
  FROM ensemble_references r, json_each(r.zones_json) j
  LEFT JOIN zone_faces f ON f.reference_id = r.reference_id AND f.i = CAST(j.key AS INTEGER)
  WHERE r.reference_id IN (SELECT reference_id FROM zone_faces)
    AND NOT EXISTS (SELECT 1 FROM json_each(r.zones_json) x WHERE x.type != 'object'))
WHERE i = 0;
UPDATE ensemble_references
SET zones_json = (SELECT n.zones_json FROM renamed_zones n
                  WHERE n.reference_id = ensemble_references.reference_id)
WHERE reference_id IN (SELECT reference_id FROM renamed_zones);
DROP TABLE migrating_zones;
DROP TABLE zone_faces;
DROP TABLE renamed_zones;
)sql",
    // 14 -> 15: the scores a point's reference does not decide (compare/reference_decision.h:
    // each score is judged by the part of the reference's estimate it reads, the window's tip or
    // the first shock), at the end of the results view. Rows stored before have none: their
    // reference decided every score it scored.
    R"sql(
ALTER TABLE scores ADD COLUMN reference_undecided TEXT;
)sql",
};

inline constexpr int kSchemaVersion = static_cast<int>(std::size(kMigrations));

}  // namespace shockmap
