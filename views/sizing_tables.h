#pragma once
// The tables of `shockmap sizing` (docs/ensembles.md, "Sizing"): one row per clearance state
// and setting for its hottest zone, or one per state, setting and zone, of the largest force or
// of the wear volume; intervals as their two
// ends (NULL when unbounded: too few members for that side), or, in the compact form for the
// terminal, as "estimate [lower, upper]" text.

#include <string>
#include <vector>

#include "db/read_only_query.h"
#include "views/ensemble_sizing.h"

namespace shockmap {

Table HottestZoneTable(const EnsembleSizing& sizing, bool compact);
Table ZoneTable(const EnsembleSizing& sizing);
// The wear volume's sizing, one row per state, setting and zone that has it (none without a
// wear law): its sizing quantile with the interval, Wilks' limit (the design value), its mean,
// and the force's sizing estimate beside it.
Table WearTable(const EnsembleSizing& sizing);
// The same for the zone of each state and setting with the highest sizing wear, its interval
// as "estimate [lower, upper]" text.
Table MostWornZoneTable(const EnsembleSizing& sizing);

// One line per setting other than the refined one, per state: how many zones agree with the
// refined setting, how many do not, how many are undecided, and what the hottest zone does.
std::vector<std::string> AgreementLines(const EnsembleSizing& sizing);

}  // namespace shockmap
