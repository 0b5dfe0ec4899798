#pragma once
// The advice check (analysis/advice_check.h) as a designer reads it: the verdict's paragraph and
// the table per clearance state and zone family.

#include <string>

#include "analysis/advice_check.h"
#include "records/table.h"

namespace shockmap {

// The verdict a designer can sign, one paragraph: where the advice held, at what CPU per member
// and how much cheaper than the converged rung; or where it failed, by how much, and which
// rung would do.
std::string AdviceVerdict(const AdviceCheck& check, double quantile);

// Per state and family: every rung's sizing quantile with its interval, coarsest first, the
// advised and the converged rung named in their column's header ("x 1, advised (N)"), whether
// the advice holds, whether the coarser rung would, the rung that suffices.
Table AdviceCheckTable(const AdviceCheck& check);

}  // namespace shockmap
