#include "core/cantilever_impact.h"

#include <algorithm>
#include <cmath>

#include "core/beam_fe.h"
#include "core/full_fe_contact_system.h"
#include "core/modal_basis.h"
#include "core/scene_model.h"
#include "core/validity.h"

namespace shockmap {

bool CantileverImpact::IsValid(std::string* error) const {
  return beam.IsValid(error) && RequirePositive("r_k", r_k, error) &&
         RequireFinite("gap_m", gap_m, error) &&
         RequirePositive("initial_tip_m", initial_tip_m, error) &&
         RequireNonNegative("contact_damping_n_s_per_m", contact_damping_n_s_per_m, error) &&
         RequireNonNegative("mass_damping_per_s", mass_damping_per_s, error);
}

int DefaultElementCount(double r_ftrunc) {
  // Mode b = beta L at the truncation: f / f1 = (b / b1)^2. Cubic Hermite elements give a
  // relative frequency error of (beta h)^4 / 1440 (measured on the clamped-free beam), so
  // beta h <= 0.6 keeps every retained mode within 1e-4.
  const double b_trunc = kClampedFreeB1 * std::sqrt(r_ftrunc);
  return std::max(20, static_cast<int>(std::ceil(b_trunc / 0.6)));
}

Scene CanonicalScene(const CantileverImpact& problem, double r_ftrunc, int n_elements) {
  Scene scene;
  scene.name = "cantilever_impact";
  SceneBeam beam;
  beam.name = "beam";
  beam.length_m = problem.beam.length_m;
  beam.ei_n_m2 = problem.beam.ei_n_m2;
  beam.rho_a_kg_per_m = problem.beam.rho_a_kg_per_m;
  beam.n_elements = n_elements > 0 ? n_elements : DefaultElementCount(r_ftrunc);
  beam.at_zero = EndCondition::kClamped;
  beam.at_length = EndCondition::kFree;
  scene.beams = {beam};
  // The stop lies below the tip: the normal points from the beam to it, -y, and the tip's
  // penetration n . u - g_scene = -u + gap_m is the problem's g - u (paper eq. 5).
  SceneZone stop;
  stop.name = "tip_spring";
  stop.height_m = problem.beam.length_m;
  stop.normal_y = -1.0;
  stop.gap_m = -problem.gap_m;
  stop.stiffness_n_per_m = problem.SpringStiffness();
  stop.damping_n_s_per_m = problem.contact_damping_n_s_per_m;
  scene.zones = {stop};
  if (problem.mass_damping_per_s > 0.0) {
    // C = alpha M projects to 2 xi_i Omega_i = alpha for every mass-normalized mode.
    scene.modal_damping = ModalDampingEffect{{}, problem.mass_damping_per_s};
  }
  InitialStateEffect released;
  released.tip_m = problem.initial_tip_m;  // The first mode's largest deflection is the tip's.
  scene.initial_state = {released};
  scene.solver.f_trunc_hz = r_ftrunc * problem.F1Hz();
  scene.outputs.displacements = {{"tip", 0, problem.beam.length_m, 0}};
  scene.outputs.contact_forces = true;
  scene.outputs.energies = true;
  return scene;
}

ImpactModel BuildImpactModel(const CantileverImpact& problem, Scheme scheme, double r_ftrunc,
                             int n_elements) {
  ImpactModel model;
  model.n_elements = n_elements > 0 ? n_elements : DefaultElementCount(r_ftrunc);
  if (scheme == Scheme::kExplicitModal) {
    SceneModel reduced = BuildSceneModel(CanonicalScene(problem, r_ftrunc, model.n_elements));
    model.n_modes = reduced.modes_per_beam.at(0);
    model.bounds = reduced.bounds;
    model.system = std::move(reduced.system);
    model.x0 = std::move(reduced.x0);
    model.tip_row = std::move(reduced.observed_rows.at(0));
  } else {
    const FeBeamModel fe =
        AssembleBeam(problem.beam, model.n_elements, EndCondition::kClamped, EndCondition::kFree);
    const double f_trunc_hz = r_ftrunc * problem.F1Hz();
    ModalBasis basis = ComputeModalBasis(fe, f_trunc_hz);
    // The first mode carries the initial state; FE frequencies lie above the analytic ones, so
    // r_ftrunc = 1 would otherwise keep nothing.
    if (basis.NumModes() == 0) basis = ComputeLowestModes(fe, 1);
    model.n_modes = basis.NumModes();
    const Eigen::VectorXd tip_row_fe = fe.DeflectionRow(problem.beam.length_m);
    const Eigen::VectorXd tip_row_modal = basis.shapes.transpose() * tip_row_fe;
    const NormalLaw spring{problem.SpringStiffness(), problem.contact_damping_n_s_per_m};
    const PointContact modal_contact{tip_row_modal, problem.gap_m, spring};
    model.bounds = ComputeStabilityBounds(
        basis.omega_rad_s, std::max(f_trunc_hz, basis.HighestFrequencyHz()), {modal_contact});
    const PointContact fe_contact{tip_row_fe, problem.gap_m, spring};
    model.system = std::make_unique<FullFeContactSystem>(
        fe.mass, fe.stiffness, problem.mass_damping_per_s, std::vector{fe_contact});
    model.x0 = (problem.initial_tip_m / tip_row_modal[0]) * basis.shapes.col(0);
    model.tip_row = tip_row_fe;
  }
  model.n_dofs = model.system->Size();
  model.v0 = Eigen::VectorXd::Zero(model.n_dofs);
  return model;
}

}  // namespace shockmap
