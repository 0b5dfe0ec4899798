#pragma once
// A comparison as one JSON object: the same figures `shockmap compare` prints.

#include <nlohmann/json.hpp>

#include "compare/comparison.h"

namespace shockmap {

nlohmann::json ShockToJson(const Shock& shock);

// Keys: rk, rftrunc, scheme, status, message, one per score of the registry (err, srf, ...;
// null when not scored), n_modes,
// n_elements, n_dofs, dt_s, dt_requested_s, dt_paper_s, dt_sharp_s, steps, window_s,
// ref_convergence, r_fref, r_fref_check, ref_transitions, wall_ref_s, wall_num_s, cpu_num_s,
// max_energy_ratio, first_shock_num, first_shock_ref (null when none).
nlohmann::json ComparisonToJson(const CantileverImpact& problem, const ComparisonOptions& options,
                                const ComparisonResult& result);

}  // namespace shockmap
