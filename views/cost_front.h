#pragma once
// What accuracy costs in time, shown: each R_k's cost table (analysis/cost_front.h) as a
// headline, a table and a plot of Err against CPU time with its Pareto front.

#include <filesystem>
#include <string>
#include <vector>

#include "analysis/cost_front.h"
#include "records/table.h"

namespace shockmap {

// The sentence heading a table: its R_k (and the --rk asked), how many points pass, those that
// pass only by error cancellation, the implicit / explicit ratio.
std::string CostHeadline(const CostTable& table);
// The table's rows as columns, for the report's sortable table: scheme, r_ftrunc,
// dt_over_dt_sharp, cpu_s, steps_x_modes, err, srf, passes (yes, no, fragile), pareto ("*").
Table CostRowsTable(const CostTable& table);
// Every table as terminal text: its headline, then its rows.
std::string CostSummary(const std::vector<CostTable>& tables);
// Err against CPU time of one table, the Pareto front joined, the Err threshold drawn when one
// judges; the explicit points coloured by their R_ftrunc. Throws InputError when empty.
void DrawCost(const std::string& study, const CostTable& table, const std::filesystem::path& file);

}  // namespace shockmap
