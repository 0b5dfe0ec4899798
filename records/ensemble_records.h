#pragma once
// The stored records of ensemble studies (docs/ensembles.md): a member's parameters and cost
// (table ensemble_members, NULL until it is computed), its zones' largest forces and impact
// statistics (table ensemble_member_zones), the impacts of the zones its scene lists (table
// ensemble_member_impacts) and the clearance states' nominal runs (table ensemble_references),
// each with its column table (records/columns.h).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "records/columns.h"

namespace shockmap {

struct EnsembleMemberParameters {
  std::string state;         // The clearance state's name.
  std::string setting_json;  // The numerical setting, {"solver.r_ftrunc": 30, ...}.
  std::int64_t member = 0;   // Its index within the state and setting.
};

inline constexpr Column<EnsembleMemberParameters> kEnsembleMemberParameterColumns[] = {
    {"state", &EnsembleMemberParameters::state, "", "its clearance state's name"},
    {"setting_json", &EnsembleMemberParameters::setting_json, "",
     "its numerical setting as JSON, `{\"solver.r_ftrunc\": 30, ...}`"},
    {"member", &EnsembleMemberParameters::member, "", "its index within the state and setting"},
};

// One zone of one member: the largest normal force and, when the run streamed them, its
// impact statistics (in the vocabulary of code_aster's POST_DYNA_MODA_T; docs/ensembles.md),
// its wear and friction power.
struct EnsembleZoneRow {
  double max_force_n = 0.0;
  std::optional<std::int64_t> impacts;
  std::optional<double> impacts_per_s, rebounds_per_impact, mean_impact_duration_s,
      longest_impact_duration_s, contact_time_fraction, mean_force_n, mean_force_in_contact_n,
      rms_force_n, impulse_n_s, wear_work_rate_w;
  // Archard's volume worn over the scene's wear life (core/wear.h), and the power friction
  // dissipates while the zone slides.
  std::optional<double> wear_volume_m3, friction_power_w;
};

inline constexpr Column<EnsembleZoneRow> kEnsembleZoneColumns[] = {
    {"max_force_n", &EnsembleZoneRow::max_force_n, "N", "the largest normal force",
     ValueRange::kNonNegative},
    {"impacts", &EnsembleZoneRow::impacts, "", "impacts (NULL: statistics not streamed)",
     ValueRange::kNonNegative},
    {"impacts_per_s", &EnsembleZoneRow::impacts_per_s, "1/s", "impacts per second",
     ValueRange::kNonNegative},
    {"rebounds_per_impact", &EnsembleZoneRow::rebounds_per_impact, "", "rebounds per impact",
     ValueRange::kNonNegative},
    {"mean_impact_duration_s", &EnsembleZoneRow::mean_impact_duration_s, "s",
     "mean impact duration", ValueRange::kNonNegative},
    {"longest_impact_duration_s", &EnsembleZoneRow::longest_impact_duration_s, "s",
     "longest impact duration", ValueRange::kNonNegative},
    {"contact_time_fraction", &EnsembleZoneRow::contact_time_fraction, "",
     "fraction of the time in contact", ValueRange::kFraction},
    {"mean_force_n", &EnsembleZoneRow::mean_force_n, "N", "mean force over the whole time",
     ValueRange::kFinite},
    {"mean_force_in_contact_n", &EnsembleZoneRow::mean_force_in_contact_n, "N",
     "mean force in contact", ValueRange::kFinite},
    {"rms_force_n", &EnsembleZoneRow::rms_force_n, "N", "RMS force", ValueRange::kNonNegative},
    {"impulse_n_s", &EnsembleZoneRow::impulse_n_s, "N s", "impulse", ValueRange::kNonNegative},
    {"wear_work_rate_w", &EnsembleZoneRow::wear_work_rate_w, "W",
     "wear work rate (NULL unless the scene bends in both planes)", ValueRange::kFinite},
    {"wear_volume_m3", &EnsembleZoneRow::wear_volume_m3, "m^3",
     "Archard's wear volume K P T over the scene's wear life (NULL without a wear law or a wear "
     "work rate)",
     ValueRange::kFinite},
    {"friction_power_w", &EnsembleZoneRow::friction_power_w, "W",
     "power dissipated by friction while sliding (NULL unless the zone has friction)",
     ValueRange::kFinite},
};

// One impact of a zone whose impacts a member lists (the scene's
// outputs.impact_statistics.impact_table; core/impact_statistics.h's ImpactRecord).
struct EnsembleImpactRow {
  std::int64_t zone = 0;    // The zone's index in the scene's order.
  std::int64_t impact = 0;  // Its number within the zone's, from 1 in time order.
  double start_s = 0.0, duration_s = 0.0, peak_force_n = 0.0, peak_time_s = 0.0, impulse_n_s = 0.0;
  std::optional<double> impact_speed_m_s;
  std::int64_t rebounds = 0, truncated = 0;
};

inline constexpr Column<EnsembleImpactRow> kEnsembleImpactColumns[] = {
    {"zone", &EnsembleImpactRow::zone, "",
     "the zone's index in the scene's order (its name in the nominal run's `zones_json`)"},
    {"impact", &EnsembleImpactRow::impact, "",
     "its number within the zone's, from 1 in time order"},
    {"start_s", &EnsembleImpactRow::start_s, "s", "its first contact's start"},
    {"duration_s", &EnsembleImpactRow::duration_s, "s", "to its last contact's end"},
    {"peak_force_n", &EnsembleImpactRow::peak_force_n, "N", "the largest force at a step"},
    {"peak_time_s", &EnsembleImpactRow::peak_time_s, "s", "when"},
    {"impulse_n_s", &EnsembleImpactRow::impulse_n_s, "N s", "the integral of the force over it"},
    {"impact_speed_m_s", &EnsembleImpactRow::impact_speed_m_s, "m/s",
     "the penetration rate as the zone closed (NULL: not known)"},
    {"rebounds", &EnsembleImpactRow::rebounds, "", "its contacts after the first"},
    {"truncated", &EnsembleImpactRow::truncated, "",
     "1 when the statistics window's start or end cuts it, else 0"},
};

// A member's run: its seed and cost, and one zone row per zone of the scene.
struct EnsembleMemberRow {
  std::int64_t reference_id = 0;
  std::string member_seed;  // 0x and 16 hexadecimal digits.
  int coordinates = 0;
  double dt_used_s = 0.0;
  std::int64_t steps = 0;
  double wall_s = 0.0, cpu_s = 0.0, max_energy_ratio = 0.0;
  std::vector<EnsembleZoneRow> zones;      // In the scene's zone order; in their own table.
  std::vector<EnsembleImpactRow> impacts;  // Of the listed zones, in zone then time order.
};

inline constexpr Column<EnsembleMemberRow> kEnsembleMemberColumns[] = {
    {"reference_id", &EnsembleMemberRow::reference_id, "",
     "the row of `ensemble_references` of its state's nominal run"},
    {"member_seed", &EnsembleMemberRow::member_seed, "",
     "the seed of its draws, 0x and 16 hexadecimal digits"},
    {"coordinates", &EnsembleMemberRow::coordinates, "", "modal coordinates of the model",
     ValueRange::kNonNegative},
    {"dt_used_s", &EnsembleMemberRow::dt_used_s, "s", "time step used", ValueRange::kNonNegative},
    {"steps", &EnsembleMemberRow::steps, "", "time steps taken", ValueRange::kNonNegative},
    {"wall_s", &EnsembleMemberRow::wall_s, "s", "wall time of the run", ValueRange::kNonNegative},
    {"cpu_s", &EnsembleMemberRow::cpu_s, "s", "CPU time of the run", ValueRange::kNonNegative},
    {"max_energy_ratio", &EnsembleMemberRow::max_energy_ratio, "",
     "largest total energy over the initial energy"},
};

// A clearance state's nominal run: every draw at its centre, at the refined setting.
struct EnsembleReferenceRow {
  std::int64_t reference_id = 0;  // Its key in the database, given when it is stored.
  std::string reference_key, state, status, message;
  // [{"name", "beam_a", "beam_b", "height_m", "y_m", "z_m"}, ...] in the scene's zone order.
  std::string zones_json;
  std::vector<double> max_force_n;
  std::int64_t steps = 0;
  double wall_s = 0.0;
};

inline constexpr Column<EnsembleReferenceRow> kEnsembleReferenceColumns[] = {
    {"reference_key", &EnsembleReferenceRow::reference_key, "",
     "the scene, draws, state, refined setting and window as JSON, unique"},
    {"state", &EnsembleReferenceRow::state, "", "the clearance state's name"},
    {"status", &EnsembleReferenceRow::status, "", "its run status"},
    {"message", &EnsembleReferenceRow::message, "", "why it failed or diverged"},
    {"zones_json", &EnsembleReferenceRow::zones_json, "",
     "the zones in the scene's order: `name`, `beam_a`, `beam_b`, `height_m`, `y_m`, `z_m`"},
    {"max_force_n", &EnsembleReferenceRow::max_force_n, "N",
     "**blob**: the largest force of each zone (empty unless it ended `ok`)"},
    {"steps", &EnsembleReferenceRow::steps, "", "time steps taken", ValueRange::kNonNegative},
    {"wall_s", &EnsembleReferenceRow::wall_s, "s", "wall time of the run",
     ValueRange::kNonNegative},
};

}  // namespace shockmap
