#pragma once
// The tables of `shockmap sizing` (docs/ensembles.md, "Sizing"): one row per clearance state,
// setting and zone family for the family's hottest zone (docs/ensembles.md, "Sizing by zone
// family"), or one per state, setting and zone, of the largest force or of the wear volume;
// intervals as their two ends (infinite when unbounded: too few members for that side). The compact
// form for the terminal fits about 120 characters: the sizing quantile as "estimate [lower, upper]"
// text, every number to 4 significant digits, an unbounded side as "-"; the full columns are the
// CSV and JSON ones.

#include <string>
#include <vector>

#include "analysis/ensemble_sizing.h"
#include "core/scene.h"
#include "db/read_only_query.h"

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

// The sentences beneath the terminal's table (HottestZoneTable compact, or MostWornZoneTable
// with `wear`): the members Wilks' limit needs when some row has none, what "-" means, and
// where the columns left out are.
std::vector<std::string> SizingFootnotes(const EnsembleSizing& sizing, bool wear);

// One line per setting other than the refined one (named by views/setting_names.h), per state:
// how many zones agree with the refined setting, how many do not, how many are undecided, and
// what the hottest zone does.
std::vector<std::string> AgreementLines(const EnsembleSizing& sizing, const Scene& scene);

}  // namespace shockmap
