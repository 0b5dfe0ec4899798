#pragma once
// The stored records of studies of the paper's problem: a point's parameters (table points),
// its scores (table scores) and the semi-analytical references (table reference_runs), each
// with its column table (records/columns.h).

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "records/columns.h"

namespace shockmap {

// The parameters of one grid point as stored.
struct PointParameters {
  double r_k = 0.0;
  double r_ftrunc = 0.0;
  std::string scheme;
  std::optional<std::string> dt_rule;
  std::optional<double> dt_factor;
  std::optional<double> dt_asked_s;
  double window_s = 0.0;
  int n_elements_asked = 0;
  double mass_damping_per_s = 0.0;
};

inline constexpr Column<PointParameters> kPointParameterColumns[] = {
    {"r_k", &PointParameters::r_k, "", "k_s / K_bend", ValueRange::kPositive},
    {"r_ftrunc", &PointParameters::r_ftrunc, "", "f_trunc / f1", ValueRange::kPositive},
    {"scheme", &PointParameters::scheme, "", "`explicit-modal` or `implicit-full`"},
    {"dt_rule", &PointParameters::dt_rule, "",
     "the bound the time step is a factor of (`paper` or `sharp`), or NULL"},
    {"dt_factor", &PointParameters::dt_factor, "", "that factor, or NULL", ValueRange::kPositive},
    {"dt_asked_s", &PointParameters::dt_asked_s, "s", "the time step given in seconds, or NULL",
     ValueRange::kPositive},
    {"window_s", &PointParameters::window_s, "s", "observation window", ValueRange::kPositive},
    {"n_elements_asked", &PointParameters::n_elements_asked, "",
     "FE elements asked (0: the default for the truncation)", ValueRange::kNonNegative},
    {"mass_damping_per_s", &PointParameters::mass_damping_per_s, "1/s",
     "mass-proportional damping α", ValueRange::kNonNegative},
};

// A score's spread columns are its name with these suffixes (err_spread_low, ...).
inline constexpr std::string_view kSpreadLowSuffix = "_spread_low";
inline constexpr std::string_view kSpreadHighSuffix = "_spread_high";

// The measurements of a computed point. Each score of the registry (validation/scores.h) that
// the paper's problem carries is an optional real column named after it.
struct ScoreRow {
  std::int64_t reference_id = 0;
  std::optional<double> err, srf, pfr;
  int n_modes = 0, n_elements = 0, n_dofs = 0;
  double dt_requested_s = 0.0, dt_used_s = 0.0, dt_paper_s = 0.0, dt_sharp_s = 0.0;
  std::int64_t steps = 0;
  double wall_s = 0.0, cpu_s = 0.0, max_energy_ratio = 0.0;
  int n_shocks = 0;
  // The first shock's; all NULL when there was none.
  std::optional<double> first_shock_start_s, first_shock_impulse_n_s, first_shock_peak_n,
      first_shock_duration_s;
  std::optional<int> first_shock_rebounds;
  std::string shocks_json = "[]";
  std::string srf_definition = "first_shock";  // What srf compares (paper eq. 9's readings).
  // Each score's smallest and largest value over the point's perturbed runs
  // (compare/score_spread.h), where the study takes them; NULL elsewhere.
  std::optional<int> spread_runs;
  std::optional<double> err_spread_low, err_spread_high, srf_spread_low, srf_spread_high,
      pfr_spread_low, pfr_spread_high;
  // The scores the reference does not decide (compare/reference_decision.h), by name, comma
  // separated ("err"); NULL when it decides every one.
  std::optional<std::string> reference_undecided;
};

inline constexpr Column<ScoreRow> kScoreColumns[] = {
    {"reference_id", &ScoreRow::reference_id, "",
     "the row of `reference_runs` it was scored against"},
    {"err", &ScoreRow::err, "", "Err, paper eq. 8 (NULL when not scored)", ValueRange::kFraction},
    {"srf", &ScoreRow::srf, "", "SRf, paper eq. 9 (NULL when not scored)", ValueRange::kFraction},
    {"pfr", &ScoreRow::pfr, "",
     "peak-force ratio of the first shock, min/max as SRf (NULL when not scored; schema 10)",
     ValueRange::kFraction},
    {"n_modes", &ScoreRow::n_modes, "", "modes kept", ValueRange::kNonNegative},
    {"n_elements", &ScoreRow::n_elements, "", "FE elements", ValueRange::kNonNegative},
    {"n_dofs", &ScoreRow::n_dofs, "", "unknowns", ValueRange::kNonNegative},
    {"dt_requested_s", &ScoreRow::dt_requested_s, "s", "time step asked", ValueRange::kNonNegative},
    {"dt_used_s", &ScoreRow::dt_used_s, "s", "time step used (shortened to end on the window)",
     ValueRange::kNonNegative},
    {"dt_paper_s", &ScoreRow::dt_paper_s, "s", "the bound 1/(4 f_trunc)", ValueRange::kNonNegative},
    {"dt_sharp_s", &ScoreRow::dt_sharp_s, "s", "the bound 2/ω_max", ValueRange::kNonNegative},
    {"steps", &ScoreRow::steps, "", "time steps taken", ValueRange::kNonNegative},
    {"wall_s", &ScoreRow::wall_s, "s",
     "wall time of the numerical run alone; of a run under `scoring.timing.repeat_until_s` "
     "(0.5 ms by default), the lower median of its repeats (docs/physics.md §4.4)",
     ValueRange::kNonNegative},
    {"cpu_s", &ScoreRow::cpu_s, "s", "CPU time of the numerical run alone, as wall_s",
     ValueRange::kNonNegative},
    {"max_energy_ratio", &ScoreRow::max_energy_ratio, "",
     "largest total energy over the initial energy"},
    {"n_shocks", &ScoreRow::n_shocks, "", "shocks in the window", ValueRange::kNonNegative},
    {"first_shock_start_s", &ScoreRow::first_shock_start_s, "s", "start of the first shock",
     ValueRange::kNonNegative},
    {"first_shock_impulse_n_s", &ScoreRow::first_shock_impulse_n_s, "N s", "its impulse",
     ValueRange::kNonNegative},
    {"first_shock_peak_n", &ScoreRow::first_shock_peak_n, "N", "its peak force",
     ValueRange::kNonNegative},
    {"first_shock_duration_s", &ScoreRow::first_shock_duration_s, "s", "its duration",
     ValueRange::kNonNegative},
    {"first_shock_rebounds", &ScoreRow::first_shock_rebounds, "", "contacts in it after the first",
     ValueRange::kNonNegative},
    {"shocks_json", &ScoreRow::shocks_json, "",
     "every shock: `start_s`, `end_s`, `duration_s`, `peak_force_n`, `peak_time_s`, "
     "`impulse_n_s`, `rebounds`, `truncated`"},
    {"srf_definition", &ScoreRow::srf_definition, "",
     "which reading of eq. 9 (`first_shock`, `first_contact`, `reference_window`; "
     "docs/fidelity.md)"},
    {"spread_runs", &ScoreRow::spread_runs, "",
     "runs scored under perturbations that leave the setting as it is (the release amplitude "
     "at rounding level, two finer meshes), the nominal one included (docs/physics.md §4.5; "
     "NULL where the study took none: `scoring.spread.from_rk`; schema 12)",
     ValueRange::kNonNegative},
    {"err_spread_low", &ScoreRow::err_spread_low, "", "the smallest Err over those runs",
     ValueRange::kFraction},
    {"err_spread_high", &ScoreRow::err_spread_high, "", "the largest Err over those runs",
     ValueRange::kFraction},
    {"srf_spread_low", &ScoreRow::srf_spread_low, "", "the smallest SRf over those runs",
     ValueRange::kFraction},
    {"srf_spread_high", &ScoreRow::srf_spread_high, "", "the largest SRf over those runs",
     ValueRange::kFraction},
    {"pfr_spread_low", &ScoreRow::pfr_spread_low, "", "the smallest PFr over those runs",
     ValueRange::kFraction},
    {"pfr_spread_high", &ScoreRow::pfr_spread_high, "", "the largest PFr over those runs",
     ValueRange::kFraction},
    {"reference_undecided", &ScoreRow::reference_undecided, "",
     "the scores the reference's estimate does not decide, by name, comma separated (`err`): "
     "their values are NULL and the point's message gives the estimate that leaves each "
     "undecided (docs/fidelity.md; NULL when it decides every score, and before schema 15)"},
};

// A semi-analytical reference: one per problem, window and reference settings.
struct ReferenceRow {
  std::int64_t reference_id = 0;  // Its key in the database, given when it is stored.
  std::string reference_key;
  double r_k = 0.0, r_fref = 0.0, r_fref_check = 0.0, window_s = 0.0, convergence = 0.0;
  // The parts of `convergence`; NULL in references stored before schema 12.
  std::optional<double> estimate_tip, estimate_impulse, estimate_err;
  int n_modes_free = 0, n_modes_contact = 0, n_transitions = 0;
  double wall_s = 0.0, output_dt_s = 0.0;
  std::vector<double> tip_m, force_n;
  std::string shocks_json = "[]";
};

inline constexpr Column<ReferenceRow> kReferenceColumns[] = {
    {"reference_key", &ReferenceRow::reference_key, "",
     "problem, R_k, window and reference settings as JSON, unique"},
    {"r_k", &ReferenceRow::r_k, "", "k_s / K_bend", ValueRange::kPositive},
    {"r_fref", &ReferenceRow::r_fref, "", "its truncation (docs/physics.md §2)",
     ValueRange::kPositive},
    {"r_fref_check", &ReferenceRow::r_fref_check, "",
     "the finer truncation it is checked against, 3 r_fref (in references stored by earlier "
     "versions: the coarser r_fref / 3)",
     ValueRange::kPositive},
    {"window_s", &ReferenceRow::window_s, "s", "the window it covers", ValueRange::kPositive},
    {"convergence", &ReferenceRow::convergence, "",
     "its estimated error: the largest grid convergence index of the tip (a fraction of the "
     "amplitude), the first-shock impulse (relative) and the Err it induces, from r_fref / 9 to "
     "r_fref_check (docs/physics.md §2); in earlier versions' references: the tip difference "
     "from the coarser truncation"},
    {"estimate_tip", &ReferenceRow::estimate_tip, "",
     "the tip's part of that estimate, a fraction of the amplitude (NULL before schema 12)"},
    {"estimate_impulse", &ReferenceRow::estimate_impulse, "",
     "the first-shock impulse's part, relative (NULL before schema 12)"},
    {"estimate_err", &ReferenceRow::estimate_err, "",
     "the part of the Err the reference's own error induces (NULL before schema 12)"},
    {"n_modes_free", &ReferenceRow::n_modes_free, "", "modes of the free phase",
     ValueRange::kNonNegative},
    {"n_modes_contact", &ReferenceRow::n_modes_contact, "", "modes of the contact phase",
     ValueRange::kNonNegative},
    {"n_transitions", &ReferenceRow::n_transitions, "", "phase changes", ValueRange::kNonNegative},
    {"wall_s", &ReferenceRow::wall_s, "s", "its computation, the check included",
     ValueRange::kNonNegative},
    {"output_dt_s", &ReferenceRow::output_dt_s, "s", "the sampling step of the two signals below",
     ValueRange::kPositive},
    {"tip_m", &ReferenceRow::tip_m, "m", "**blob**: the tip displacement"},
    {"force_n", &ReferenceRow::force_n, "N", "**blob**: the contact force"},
    {"shocks_json", &ReferenceRow::shocks_json, "", "its shocks, as in `scores.shocks_json`"},
};

}  // namespace shockmap
