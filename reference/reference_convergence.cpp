#include "reference/reference_convergence.h"

#include <algorithm>

namespace shockmap {

double FinerTruncation(double r_fref) { return kReferenceCheckRatio * r_fref; }

double CoarserTruncation(double r_fref) { return std::max(1.0, r_fref / kReferenceCheckRatio); }

}  // namespace shockmap
