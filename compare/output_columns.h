#pragma once
// The columns of the values a run gives out (records/output_columns.h), each declared once: a
// scene run's summary (`simulate --json`, summary.json, Python's SceneRun.summary), a
// comparison of the paper's problem (`compare --json`, Python's Comparison.summary), a shock
// (shocks.csv, the comparison's first shocks, Python's shock dicts), a zone's impact statistics
// (impact_statistics.csv, summary.json's zone results), one impact of a zone (impacts.csv), a
// run's energies at one instant (energies.csv) and a zone's largest force
// (max_contact_force.csv).
// docs/scenes.md describes the files.

#include <cmath>
#include <optional>

#include "compare/comparison.h"
#include "compare/scene_run.h"
#include "core/impact_statistics.h"
#include "core/wear.h"
#include "records/output_columns.h"
#include "validation/shock_segmentation.h"

namespace shockmap {

inline constexpr OutputColumn<Shock> kShockColumns[] = {
    {"start_s", [](const Shock& s) -> OutputValue { return s.start_s; }, "s",
     "its first contact's start"},
    {"end_s", [](const Shock& s) -> OutputValue { return s.end_s; }, "s", "its last contact's end"},
    {"duration_s", [](const Shock& s) -> OutputValue { return s.Duration(); }, "s",
     "from its start to its end"},
    {"peak_force_n", [](const Shock& s) -> OutputValue { return s.peak_force_n; }, "N",
     "its largest force sample"},
    {"peak_time_s", [](const Shock& s) -> OutputValue { return s.peak_time_s; }, "s",
     "the time of that sample"},
    {"impulse_n_s", [](const Shock& s) -> OutputValue { return s.impulse_n_s; }, "N s",
     "the integral of the force over it"},
    {"rebounds", [](const Shock& s) -> OutputValue { return std::int64_t{s.Rebounds()}; }, "",
     "its contacts after the first"},
    {"truncated", [](const Shock& s) -> OutputValue { return s.truncated; }, "",
     "cut by the record's start or end (its figures are bounds)"},
};

// A zone's impact statistics with the scene's wear law, which its wear volume needs.
struct ZoneImpactStatistics {
  const ImpactStatistics& statistics;
  const std::optional<WearLaw>& wear;
};

// How a zone's wear work rate was measured: at every step from its two sides' tangential speed
// (no friction), or only while it slides (friction).
inline const char* WearBasis(const ImpactStatistics& s) {
  return s.sliding_only ? "sliding_only" : "tangential_speed";
}

// In the order of impact_statistics.csv: those of the first version, then those added with the
// conventions, friction and wear. An unavailable wear work rate, friction power or wear volume
// is none.
inline constexpr OutputColumn<ZoneImpactStatistics> kImpactStatisticsColumns[] = {
    {"impacts",
     [](const ZoneImpactStatistics& z) -> OutputValue {
       return std::int64_t{z.statistics.impacts};
     },
     "", "impacts started in the window"},
    {"impacts_per_s",
     [](const ZoneImpactStatistics& z) -> OutputValue { return z.statistics.impacts_per_s; }, "1/s",
     "impacts per second"},
    {"rebounds_per_impact",
     [](const ZoneImpactStatistics& z) -> OutputValue { return z.statistics.rebounds_per_impact; },
     "", "rebounds per impact"},
    {"mean_impact_duration_s",
     [](const ZoneImpactStatistics& z) -> OutputValue {
       return z.statistics.mean_impact_duration_s;
     },
     "s", "mean impact duration"},
    {"longest_impact_duration_s",
     [](const ZoneImpactStatistics& z) -> OutputValue {
       return z.statistics.longest_impact_duration_s;
     },
     "s", "longest impact duration"},
    {"contact_time_fraction",
     [](const ZoneImpactStatistics& z) -> OutputValue {
       return z.statistics.contact_time_fraction;
     },
     "", "fraction of the window in contact"},
    {"mean_force_n",
     [](const ZoneImpactStatistics& z) -> OutputValue { return z.statistics.mean_force_n; }, "N",
     "mean force over the whole window"},
    {"mean_force_in_contact_n",
     [](const ZoneImpactStatistics& z) -> OutputValue {
       return z.statistics.mean_force_in_contact_n;
     },
     "N", "mean force in contact"},
    {"rms_force_n",
     [](const ZoneImpactStatistics& z) -> OutputValue { return z.statistics.rms_force_n; }, "N",
     "RMS force over the whole window"},
    {"max_force_n",
     [](const ZoneImpactStatistics& z) -> OutputValue { return z.statistics.max_force_n; }, "N",
     "largest force at a step"},
    {"impulse_n_s",
     [](const ZoneImpactStatistics& z) -> OutputValue { return z.statistics.impulse_n_s; }, "N s",
     "impulse over the window"},
    {"wear_work_rate_w",
     [](const ZoneImpactStatistics& z) -> OutputValue {
       if (!z.statistics.wear_available) return {};
       return z.statistics.wear_work_rate_w;
     },
     "W", "wear work rate (none unless the scene bends in both planes)"},
    {"contacts",
     [](const ZoneImpactStatistics& z) -> OutputValue {
       return std::int64_t{z.statistics.contacts};
     },
     "", "contacts, rebounds included"},
    {"truncated",
     [](const ZoneImpactStatistics& z) -> OutputValue { return z.statistics.truncated; }, "",
     "an impact is cut by the window's start or end"},
    {"convention",
     [](const ZoneImpactStatistics& z) -> OutputValue {
       return std::string(ToString(z.statistics.convention));
     },
     "", "the statistics' convention (docs/scenes.md)"},
    {"window_start_s",
     [](const ZoneImpactStatistics& z) -> OutputValue { return z.statistics.window_start_s; }, "s",
     "the window's start, snapped to a step"},
    {"window_end_s",
     [](const ZoneImpactStatistics& z) -> OutputValue { return z.statistics.window_end_s; }, "s",
     "the window's end, snapped to a step"},
    {"mean_contact_duration_s",
     [](const ZoneImpactStatistics& z) -> OutputValue {
       return z.statistics.mean_contact_duration_s;
     },
     "s", "time in contact per contact"},
    {"rms_force_in_contact_n",
     [](const ZoneImpactStatistics& z) -> OutputValue {
       return z.statistics.rms_force_in_contact_n;
     },
     "N", "RMS force in contact"},
    {"wear_basis",
     [](const ZoneImpactStatistics& z) -> OutputValue {
       return std::string(WearBasis(z.statistics));
     },
     "", "`tangential_speed` at every step, or `sliding_only` (friction)"},
    {"friction_power_w",
     [](const ZoneImpactStatistics& z) -> OutputValue {
       if (!z.statistics.wear_available || !z.statistics.sliding_only) return {};
       return z.statistics.friction_power_w;
     },
     "W", "power dissipated by friction while sliding (none without friction)"},
    {"wear_volume_m3",
     [](const ZoneImpactStatistics& z) -> OutputValue {
       if (!z.statistics.wear_available || !z.wear) return {};
       return ArchardWearVolume(*z.wear, z.statistics.wear_work_rate_w);
     },
     "m^3", "Archard's wear volume over the wear life (none without a wear law or work rate)"},
};

// In the order of impacts.csv, after the zone's name and the impact's number.
inline constexpr OutputColumn<ImpactRecord> kImpactRecordColumns[] = {
    {"start_s", [](const ImpactRecord& r) -> OutputValue { return r.start_s; }, "s",
     "its first contact's start"},
    {"duration_s", [](const ImpactRecord& r) -> OutputValue { return r.duration_s; }, "s",
     "to its last contact's end"},
    {"peak_force_n", [](const ImpactRecord& r) -> OutputValue { return r.peak_force_n; }, "N",
     "the largest force at a step"},
    {"peak_time_s", [](const ImpactRecord& r) -> OutputValue { return r.peak_time_s; }, "s",
     "when"},
    {"impulse_n_s", [](const ImpactRecord& r) -> OutputValue { return r.impulse_n_s; }, "N s",
     "the integral of the force over its contacts"},
    {"impact_speed_m_s",
     [](const ImpactRecord& r) -> OutputValue {
       if (!std::isfinite(r.impact_speed_m_s)) return {};
       return r.impact_speed_m_s;
     },
     "m/s", "the penetration rate as the zone closed (none: not known)"},
    {"contacts", [](const ImpactRecord& r) -> OutputValue { return std::int64_t{r.contacts}; }, "",
     "its contacts: 1 + its rebounds"},
    {"rebounds", [](const ImpactRecord& r) -> OutputValue { return std::int64_t{r.contacts - 1}; },
     "", "its contacts after the first"},
    {"truncated", [](const ImpactRecord& r) -> OutputValue { return r.truncated; }, "",
     "cut by the window's start or end"},
};

// One recorded instant of a run's energies, in the order of energies.csv: their balance is the
// run's energy check.
struct EnergySample {
  const EnergyHistory& energy;
  std::size_t index;
};

inline constexpr OutputColumn<EnergySample> kEnergyColumns[] = {
    {"t_s", [](const EnergySample& e) -> OutputValue { return e.energy.kinetic_j.TimeAt(e.index); },
     "s", "the simulated time"},
    {"kinetic_j",
     [](const EnergySample& e) -> OutputValue { return e.energy.kinetic_j.values[e.index]; }, "J",
     "kinetic energy"},
    {"strain_j",
     [](const EnergySample& e) -> OutputValue { return e.energy.strain_j.values[e.index]; }, "J",
     "strain energy"},
    {"contact_j",
     [](const EnergySample& e) -> OutputValue { return e.energy.contact_j.values[e.index]; }, "J",
     "energy stored in the closed contacts"},
    {"dissipated_j",
     [](const EnergySample& e) -> OutputValue { return e.energy.dissipated_j.values[e.index]; },
     "J", "energy dissipated since the start"},
    {"external_work_j",
     [](const EnergySample& e) -> OutputValue { return e.energy.external_work_j.values[e.index]; },
     "J", "work of the external loads since the start"},
};

// A zone's largest contact force over a run with where the zone is, in the order of
// max_contact_force.csv.
struct ZoneLargestForce {
  const Scene& scene;
  const SceneZone& zone;
  double force_n;
};

inline constexpr OutputColumn<ZoneLargestForce> kLargestForceColumns[] = {
    {"zone", [](const ZoneLargestForce& z) -> OutputValue { return z.zone.name; }, "",
     "the zone's name"},
    {"beam",
     [](const ZoneLargestForce& z) -> OutputValue { return z.scene.SideName(z.zone, false); }, "",
     "its first side"},
    {"against",
     [](const ZoneLargestForce& z) -> OutputValue { return z.scene.SideName(z.zone, true); }, "",
     "its other side: a beam, a structure's node or a stop"},
    {"height_m", [](const ZoneLargestForce& z) -> OutputValue { return z.zone.height_m; }, "m",
     "its height"},
    {"y_m", [](const ZoneLargestForce& z) -> OutputValue { return z.zone.y_m; }, "m",
     "its position in the cross-section, y"},
    {"z_m", [](const ZoneLargestForce& z) -> OutputValue { return z.zone.z_m; }, "m",
     "its position in the cross-section, z"},
    {"max_force_n", [](const ZoneLargestForce& z) -> OutputValue { return z.force_n; }, "N",
     "the largest contact force of the run"},
};

// A scene run with its scene.
struct SceneRunOutput {
  const Scene& scene;
  const SceneRun& run;
};

// The scalar members of a scene run's summary; beside them, where the scene has them, its
// structures, wear law, power laws' bound, largest contact force and zone results
// (formats/scene_outputs.h).
inline constexpr OutputColumn<SceneRunOutput> kSceneRunColumns[] = {
    {"scene", [](const SceneRunOutput& o) -> OutputValue { return o.scene.name; }, "",
     "the scene's name"},
    {"status",
     [](const SceneRunOutput& o) -> OutputValue { return ToString(o.run.result.summary.status); },
     "", "the run's status"},
    {"message", [](const SceneRunOutput& o) -> OutputValue { return o.run.result.summary.message; },
     "", "why it failed or diverged"},
    {"end_time_s", [](const SceneRunOutput& o) -> OutputValue { return o.scene.solver.end_time_s; },
     "s", "the time simulated"},
    {"dt_s", [](const SceneRunOutput& o) -> OutputValue { return o.run.result.summary.dt_used_s; },
     "s", "time step used"},
    {"dt_requested_s",
     [](const SceneRunOutput& o) -> OutputValue { return o.run.result.summary.dt_requested_s; },
     "s", "time step asked"},
    {"dt_paper_s", [](const SceneRunOutput& o) -> OutputValue { return o.run.bounds.dt_paper_s; },
     "s", "the bound 1/(4 f_trunc)"},
    {"dt_sharp_s", [](const SceneRunOutput& o) -> OutputValue { return o.run.bounds.dt_sharp_s; },
     "s", "the bound 2/ω_max"},
    {"steps",
     [](const SceneRunOutput& o) -> OutputValue { return o.run.result.summary.steps_taken; }, "",
     "time steps taken"},
    {"beams",
     [](const SceneRunOutput& o) -> OutputValue {
       return static_cast<std::int64_t>(o.scene.beams.size());
     },
     "", "beams of the scene"},
    {"zones",
     [](const SceneRunOutput& o) -> OutputValue {
       return static_cast<std::int64_t>(o.scene.zones.size());
     },
     "", "contact zones of the scene"},
    {"coordinates",
     [](const SceneRunOutput& o) -> OutputValue { return std::int64_t{o.run.coordinates}; }, "",
     "modal coordinates integrated"},
    {"distinct_bases",
     [](const SceneRunOutput& o) -> OutputValue { return std::int64_t{o.run.distinct_bases}; }, "",
     "modal bases computed"},
    {"max_energy_ratio",
     [](const SceneRunOutput& o) -> OutputValue { return o.run.result.summary.max_energy_ratio; },
     "", "largest total energy over the initial energy"},
    {"build_wall_s", [](const SceneRunOutput& o) -> OutputValue { return o.run.build_wall_s; }, "s",
     "wall time of the model's assembly"},
    {"wall_s", [](const SceneRunOutput& o) -> OutputValue { return o.run.result.summary.wall_s; },
     "s", "wall time of the run"},
    {"cpu_s", [](const SceneRunOutput& o) -> OutputValue { return o.run.result.summary.cpu_s; },
     "s", "CPU time of the run"},
};

// One run of the paper's problem scored against its reference, with what it was asked.
struct ComparisonOutput {
  const CantileverImpact& problem;
  const ComparisonOptions& options;
  const ComparisonResult& result;
};

// The scalar members of `compare --json`; beside them, each registered score by its name, the
// scores the reference leaves undecided and the first shock of each run
// (formats/comparison_json.h).
inline constexpr OutputColumn<ComparisonOutput> kComparisonColumns[] = {
    {"rk", [](const ComparisonOutput& c) -> OutputValue { return c.problem.r_k; }, "",
     "k_s / K_bend"},
    {"rftrunc", [](const ComparisonOutput& c) -> OutputValue { return c.options.r_ftrunc; }, "",
     "f_trunc / f1"},
    {"scheme",
     [](const ComparisonOutput& c) -> OutputValue {
       return std::string(ToString(c.options.scheme));
     },
     "", "`explicit-modal` or `implicit-full`"},
    {"status",
     [](const ComparisonOutput& c) -> OutputValue {
       return std::string(ToString(c.result.status));
     },
     "", "the run's status"},
    {"message", [](const ComparisonOutput& c) -> OutputValue { return c.result.message; }, "",
     "why it failed, or was not scored"},
    {"n_modes",
     [](const ComparisonOutput& c) -> OutputValue { return std::int64_t{c.result.n_modes}; }, "",
     "modes kept"},
    {"n_elements",
     [](const ComparisonOutput& c) -> OutputValue { return std::int64_t{c.result.n_elements}; }, "",
     "FE elements"},
    {"n_dofs",
     [](const ComparisonOutput& c) -> OutputValue { return std::int64_t{c.result.n_dofs}; }, "",
     "unknowns"},
    {"dt_s", [](const ComparisonOutput& c) -> OutputValue { return c.result.numerical.dt_used_s; },
     "s", "time step used"},
    {"dt_requested_s",
     [](const ComparisonOutput& c) -> OutputValue { return c.result.numerical.dt_requested_s; },
     "s", "time step asked"},
    {"dt_paper_s",
     [](const ComparisonOutput& c) -> OutputValue { return c.result.bounds.dt_paper_s; }, "s",
     "the bound 1/(4 f_trunc)"},
    {"dt_sharp_s",
     [](const ComparisonOutput& c) -> OutputValue { return c.result.bounds.dt_sharp_s; }, "s",
     "the bound 2/ω_max"},
    {"steps",
     [](const ComparisonOutput& c) -> OutputValue { return c.result.numerical.steps_taken; }, "",
     "time steps taken"},
    {"window_s", [](const ComparisonOutput& c) -> OutputValue { return c.options.window_s; }, "s",
     "observation window"},
    {"ref_convergence",
     [](const ComparisonOutput& c) -> OutputValue {
       return c.result.reference->convergence.difference;
     },
     "", "the reference's estimated error (docs/physics.md §2)"},
    {"ref_estimate_tip",
     [](const ComparisonOutput& c) -> OutputValue {
       return c.result.reference->convergence.tip.error;
     },
     "", "its part on the tip, a fraction of the amplitude"},
    {"ref_estimate_impulse",
     [](const ComparisonOutput& c) -> OutputValue {
       return c.result.reference->convergence.impulse.error;
     },
     "", "its part on the first-shock impulse, relative"},
    {"ref_estimate_err",
     [](const ComparisonOutput& c) -> OutputValue {
       return c.result.reference->convergence.induced_err.error;
     },
     "", "the part of the Err it induces"},
    {"r_fref",
     [](const ComparisonOutput& c) -> OutputValue {
       return c.result.reference->convergence.r_fref;
     },
     "", "the reference's truncation"},
    {"r_fref_check",
     [](const ComparisonOutput& c) -> OutputValue {
       return c.result.reference->convergence.r_fref_check;
     },
     "", "the truncation it is checked against"},
    {"ref_transitions",
     [](const ComparisonOutput& c) -> OutputValue {
       return std::int64_t{c.result.reference->summary.n_transitions};
     },
     "", "the reference's phase changes"},
    {"wall_ref_s",
     [](const ComparisonOutput& c) -> OutputValue { return c.result.reference->wall_s; }, "s",
     "wall time of the reference"},
    {"wall_num_s",
     [](const ComparisonOutput& c) -> OutputValue { return c.result.numerical.wall_s; }, "s",
     "wall time of the numerical run"},
    {"cpu_num_s", [](const ComparisonOutput& c) -> OutputValue { return c.result.numerical.cpu_s; },
     "s", "CPU time of the numerical run"},
    {"max_energy_ratio",
     [](const ComparisonOutput& c) -> OutputValue { return c.result.numerical.max_energy_ratio; },
     "", "largest total energy over the initial energy"},
};

}  // namespace shockmap
