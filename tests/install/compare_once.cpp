// The paper's Fig. 3 point through the installed library: R_k = 3000, R_ftrunc = 300 is right
// (README: Err 0.035, SRf 0.993). Exit 0 when Err < 0.1 and SRf > 0.9.
#include <cstdio>
#include <optional>

#include <shockmap/compare/comparison.h>

int main() {
  shockmap::CantileverImpact problem;
  problem.r_k = 3000;
  shockmap::ComparisonOptions options;
  options.r_ftrunc = 300;
  const shockmap::ComparisonResult r = shockmap::RunComparison(problem, options);
  const std::optional<double> err = r.scores["err"], srf = r.scores["srf"];
  std::printf("Err %.4f SRf %.4f\n", err.value_or(-1.0), srf.value_or(-1.0));
  return err && srf && *err < 0.1 && *srf > 0.9 ? 0 : 1;
}
