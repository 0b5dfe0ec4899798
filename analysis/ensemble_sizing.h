#pragma once
// Sizing statistics of an ensemble study (docs/ensembles.md, "Sizing"): for every clearance
// state and numerical setting, per zone and for the hottest zone, the quantiles of the members'
// largest force with their order-statistic intervals, Wilks' upper tolerance limit, a bootstrap
// cross-check, the mean impact statistics, the sizing statistics of the wear volume; each
// setting judged against the refined one.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "db/ensemble_members.h"
#include "specs/zone_family.h"
#include "statistics/bootstrap.h"
#include "statistics/quantile_interval.h"
#include "statistics/wilks.h"

namespace shockmap {

struct SizingOptions {
  double quantile = 0.95;    // The sizing quantile.
  double confidence = 0.95;  // Of every interval and of Wilks' limit.
  // A setting agrees with the refined one at a zone when their intervals of the sizing
  // quantile, each widened by tolerance x the refined estimate, overlap.
  double tolerance = 0.05;
  // The hottest zone is the highest of the zones whose name holds this text (all when empty):
  // "-pin_" keeps the wires between pins, "pin_" those of the pins.
  std::string hottest_among;
  int bootstrap_resamples = 2000;
  std::uint64_t bootstrap_seed = 1;
};

// The means over members of a zone's impact statistics (absent when no member streamed them).
struct MeanImpacts {
  double impacts_per_s = 0.0, rebounds_per_impact = 0.0, mean_impact_duration_s = 0.0,
         contact_time_fraction = 0.0, mean_force_n = 0.0, rms_force_n = 0.0, impulse_n_s = 0.0;
  std::optional<double> wear_work_rate_w;  // Where the scene bends in both planes.
};

// The sizing statistics of a zone's wear volume over the members (docs/ensembles.md, "Wear
// sizing"): the sizing quantile with its order-statistic interval, Wilks' limit (the design
// value) and the mean.
struct WearSizing {
  QuantileInterval sizing;  // At SizingOptions::quantile.
  int wilks_order = 0;      // 0: too few members for order 1.
  std::optional<ToleranceLimit> wilks;
  double mean_m3 = 0.0;
};

struct ZoneSizing {
  int zone = 0;
  std::string name;
  ZoneFamily family = ZoneFamily::kOther;
  int members = 0;
  QuantileInterval p50, p95, p99, sizing;  // sizing: at SizingOptions::quantile.
  int wilks_order = 0;                     // 0: too few members for order 1.
  std::optional<ToleranceLimit> wilks;
  Interval bootstrap;                  // Of the sizing quantile.
  std::optional<double> nominal_n;     // The state's nominal run.
  std::optional<MeanImpacts> impacts;  // Over the members.
  std::optional<WearSizing> wear;      // When every member has the zone's wear volume.
};

// The hottest zone of one family (docs/ensembles.md, "Sizing by zone family"): the highest
// sizing estimate among the family's zones at the state's refined setting.
struct FamilyHottest {
  ZoneFamily family = ZoneFamily::kOther;
  int zone = 0;                // Index in GroupSizing::zones.
  std::optional<bool> agrees;  // With the state's refined setting, as hottest_agrees.
};

// One clearance state at one numerical setting.
struct GroupSizing {
  std::string state, setting_json;
  bool refined = false;
  int members = 0;
  double mean_wall_s = 0.0, mean_cpu_s = 0.0;  // Per member.
  std::vector<ZoneSizing> zones;               // In the scene's zone order.
  int hottest = 0;  // Index in zones: the highest sizing estimate at the state's refined setting.
  // Against the state's refined setting (absent for the refined one itself, or while either
  // interval is unbounded: too few members to judge).
  std::optional<bool> hottest_agrees;
  // One per family the scene has (among the zones --hottest-among keeps), in ZoneFamily order.
  std::vector<FamilyHottest> families;
  int zones_agreeing = 0, zones_disagreeing = 0;  // The others are undecided.
};

struct EnsembleSizing {
  std::string study;
  SizingOptions options;
  std::vector<std::string> zone_names;
  std::vector<ZoneFamily> zone_families;  // Of each zone, from the beams it joins.
  std::vector<GroupSizing> groups;        // States in the file's order, then settings.
  std::int64_t pending = 0, failed = 0, superseded = 0;
};

// The stored members that the study file, as last run, still has: an index below its member
// count, one of its clearance states, one of its settings (compared by value). Members of an
// earlier file (more members, a state or a setting since removed) are dropped and counted in
// `superseded` (if computed), so that the statistics and the counts of members pending and not
// ok are those of the current file.
StoredEnsemble CurrentMembers(StoredEnsemble stored);

// Throws InputError when the options are out of range, or the study holds no computed member.
EnsembleSizing SizeEnsemble(const StoredEnsemble& stored, const std::string& study,
                            const SizingOptions& options);

// The sizing statistics of one zone over `forces` (the members' largest forces, in member
// order). Precondition: forces is not empty.
ZoneSizing SizeZone(const std::vector<double>& forces, const SizingOptions& options);

// The sizing statistics of one zone's wear volumes (in member order). Precondition: volumes
// is not empty.
WearSizing SizeWear(const std::vector<double>& volumes, const SizingOptions& options);

// Whether two zones' sizing intervals agree within the tolerance (see SizingOptions); nullopt
// when either interval is unbounded.
std::optional<bool> Agrees(const ZoneSizing& setting, const ZoneSizing& refined, double tolerance);

// The sizing estimate of the first n members for growing n (10, or all when fewer, to all;
// about 12 per decade), and the least-squares slope of log(interval width) against log(n) over
// the bounded ones.
struct ConvergencePoint {
  int members = 0;
  QuantileInterval sizing;
};
std::vector<ConvergencePoint> SizingConvergence(const std::vector<double>& forces,
                                                const SizingOptions& options);
// NaN when fewer than two points have a bounded interval of positive width.
double WidthSlope(const std::vector<ConvergencePoint>& points);

// The mean width of the sizing interval over `resamples` samples of n members drawn with
// replacement from `forces` (their empirical distribution), for n from the smallest that bounds
// both sides to forces.size(), about 12 per decade; and the least-squares slope of its
// logarithm against log(n). A single nested sequence of members (SizingConvergence) gives a
// noisy slope; this is its expectation under the sample's own distribution.
struct WidthScaling {
  std::vector<std::pair<int, double>> mean_width;  // (members, mean width)
  double slope = 0.0;                              // NaN with fewer than two sizes.
};
WidthScaling MeanWidthScaling(const std::vector<double>& forces, const SizingOptions& options,
                              int resamples = 400, std::uint64_t seed = 1);

// The members' largest forces in one zone of one group, in member order.
std::vector<double> ZoneForces(const StoredEnsemble& stored, const GroupSizing& group, int zone);

}  // namespace shockmap
