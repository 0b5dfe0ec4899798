#include "formats/comparison_json.h"

namespace shockmap {
namespace {

template <typename T>
nlohmann::json OrNull(const std::optional<T>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

nlohmann::json FirstShock(const std::vector<Shock>& shocks) {
  return shocks.empty() ? nlohmann::json(nullptr) : ShockToJson(shocks.front());
}

}  // namespace

nlohmann::json ShockToJson(const Shock& shock) {
  return {{"start_s", shock.start_s},         {"end_s", shock.end_s},
          {"duration_s", shock.Duration()},   {"peak_force_n", shock.peak_force_n},
          {"peak_time_s", shock.peak_time_s}, {"impulse_n_s", shock.impulse_n_s},
          {"rebounds", shock.Rebounds()},     {"truncated", shock.truncated}};
}

nlohmann::json ComparisonToJson(const CantileverImpact& problem, const ComparisonOptions& options,
                                const ComparisonResult& result) {
  const ReferenceRun& ref = *result.reference;
  nlohmann::json json = {{"rk", problem.r_k},
                         {"rftrunc", options.r_ftrunc},
                         {"scheme", ToString(options.scheme)},
                         {"status", ToString(result.status)},
                         {"message", result.message},
                         {"n_modes", result.n_modes},
                         {"n_elements", result.n_elements},
                         {"n_dofs", result.n_dofs},
                         {"dt_s", result.numerical.dt_used_s},
                         {"dt_requested_s", result.numerical.dt_requested_s},
                         {"dt_paper_s", result.bounds.dt_paper_s},
                         {"dt_sharp_s", result.bounds.dt_sharp_s},
                         {"steps", result.numerical.steps_taken},
                         {"window_s", options.window_s},
                         {"ref_convergence", ref.convergence.difference},
                         {"ref_estimate_tip", ref.convergence.tip.error},
                         {"ref_estimate_impulse", ref.convergence.impulse.error},
                         {"ref_estimate_err", ref.convergence.induced_err.error},
                         {"reference_undecided", result.undecided},
                         {"r_fref", ref.convergence.r_fref},
                         {"r_fref_check", ref.convergence.r_fref_check},
                         {"ref_transitions", ref.summary.n_transitions},
                         {"wall_ref_s", ref.wall_s},
                         {"wall_num_s", result.numerical.wall_s},
                         {"cpu_num_s", result.numerical.cpu_s},
                         {"max_energy_ratio", result.numerical.max_energy_ratio},
                         {"first_shock_num", FirstShock(result.shocks_numerical)},
                         {"first_shock_ref", FirstShock(ref.shocks)}};
  for (const ScoreDefinition& score : Scores()) {
    json[std::string(score.name)] = OrNull(result.scores[score.name]);
  }
  return json;
}

}  // namespace shockmap
