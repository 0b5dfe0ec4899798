#pragma once
// What the physics of a scene is: beams, contact zones, the effects declared, the solver and the
// outputs requested (docs/physics.md §5, docs/architecture.md). Plain description structs; parsing
// lives outside core (studies/scene_file), building lives in core/scene_model.

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/beam_sections.h"
#include "core/contact_law.h"
#include "core/end_condition.h"
#include "core/impact_statistics.h"
#include "core/stability_bounds.h"
#include "core/wear.h"

namespace shockmap {

// Planar scenes bend in y only; full ones in y and z, with the same modes in both planes.
enum class BendingPlanes { kPlanar, kBoth };

// A uniform beam (ei_n_m2, rho_a_kg_per_m over length_m), or one of `sections` from the base up
// (their lengths summing to length_m; ei_n_m2 and rho_a_kg_per_m then unused); either may carry
// point masses (core/beam_sections.h).
struct SceneBeam {
  std::string name;
  double length_m = 1.0;
  double ei_n_m2 = 0.0;
  double rho_a_kg_per_m = 0.0;
  std::vector<BeamSection> sections;
  std::vector<BeamPointMass> point_masses;
  int n_elements = 20;
  EndCondition at_zero = EndCondition::kClamped;
  EndCondition at_length = EndCondition::kFree;
  // Translational springs to the base at each end (N/m, 0 for none): "elastic" ends.
  double spring_at_zero_n_per_m = 0.0;
  double spring_at_length_n_per_m = 0.0;
  double y_m = 0.0, z_m = 0.0;  // Position in the cross-section (for maps).
  // This beam's own truncation, overriding the solver's: an absolute frequency or a ratio of
  // its first elastic frequency.
  std::optional<double> f_trunc_hz, r_ftrunc;
};

struct FeStructure;

// A structure from an FE code (core/fe_structure.h): its matrices as read, and its own
// truncation overriding the solver's, as a beam's. x runs along the beams' axis (heights), y
// and z across it, so that a beam's deflection (u_y, u_z) at a height is the motion (0, u_y, u_z)
// in the structures' frame.
struct SceneStructure {
  std::string name;
  std::shared_ptr<const FeStructure> fe;
  std::optional<double> f_trunc_hz, r_ftrunc;
};

// A power law F = k d^p for a zone's normal force (Hertz: p = 3/2).
struct ScenePowerLaw {
  double coefficient = 0.0;  // k, N/m^p.
  double exponent = 1.5;     // p in [1, 3].
  // The penetration at which the stability bound takes the law's tangent stiffness p k d^(p-1)
  // (the largest the zone is expected to reach; a run that goes deeper is flagged).
  double bound_penetration_m = 0.0;
};

// A contact at one height: beam a against a stop fixed to the base (beam_b < 0) or against
// beam b. Contact when the penetration d = n . (u_a - u_b) - gap is positive; the force
// F = k d + c d' (never pulling), or k d^p + c d' with a power law, pushes a along -n and b
// along +n. With friction (scenes bending in both planes), a tangential force along
// t = (-n_z, n_y) acts on a and its reaction on b (docs/physics.md §7).
//
// A side may instead be a structure's node (structure_a or structure_b >= 0, the side's beam
// index -1): the zone then has a normal in 3D (normal_xyz), and its tangent for friction is
// t = x × n normalized (t = (0, -n_z, n_y) when n lies across the axis, as a beam zone's), or
// y × n when n lies along x. height_m is the beam side's height, or the node's x.
struct SceneZone {
  std::string name;
  int beam_a = 0;
  int beam_b = -1;
  int structure_a = -1, node_a = 0;
  int structure_b = -1, node_b = 0;
  double height_m = 0.0;
  double normal_y = 1.0, normal_z = 0.0;              // Unit vector from a towards b (or the stop).
  std::optional<std::array<double, 3>> normal_xyz{};  // Zones with a node: (x, y, z), unit.
  double gap_m = 0.0;
  // The linear law's k; with a power law, its tangent stiffness at the bound penetration (what
  // the stability bound gives the zone).
  double stiffness_n_per_m = 0.0;
  double damping_n_s_per_m = 0.0;
  double y_m = 0.0, z_m = 0.0;               // Where the zone sits in the cross-section (for maps).
  std::optional<ScenePowerLaw> power_law{};  // In place of the linear law.
  std::optional<FrictionLaw> friction{};

  // The zone's laws as the models evaluate them.
  ContactLaw Law() const;
  bool AtNode() const { return normal_xyz.has_value(); }
  bool AgainstStop() const { return beam_b < 0 && structure_b < 0; }
};

struct ModalDampingEffect {
  std::vector<double> ratios;  // xi per mode (the last repeats); empty: mass-proportional.
  double mass_proportional_per_s = 0.0;
};

// Acceleration of the base every beam is attached to, along (dir_y, dir_z): a half-sine pulse,
// or a table interpolated linearly (zero outside it). Responses are relative to the base.
struct BaseMotionEffect {
  double dir_y = 1.0, dir_z = 0.0;
  double amplitude_m_s2 = 0.0, duration_s = 0.0, start_s = 0.0;  // Half-sine.
  std::vector<double> table_t_s, table_a_m_s2;                   // Or a table.
  double At(double t_s) const;
};

// A force at one point of one beam: a step at start_s, or a ramp over ramp_s, then constant.
struct StaticForceEffect {
  int beam = 0;
  double height_m = 0.0;
  double dir_y = 1.0, dir_z = 0.0;
  double force_n = 0.0;
  double start_s = 0.0;
  double ramp_s = 0.0;
  double At(double t_s) const;
};

// Initial state of one beam in one direction, any combination of: its `mode` (1-based) scaled so
// that its largest deflection is `tip_m`; the static deflection (in the retained basis) under a
// force `static_force_n` at `height_m`; a uniform velocity.
//
// At a structure's node (structure >= 0, beam unused): the static deflection under a force
// `static_force_n` at `node` along `direction_xyz`, and a uniform velocity along direction_xyz.
struct InitialStateEffect {
  int beam = 0;
  int structure = -1, node = 0;
  std::array<double, 3> direction_xyz{0.0, 1.0, 0.0};
  int direction = 0;  // 0: y, 1: z.
  int mode = 1;
  double tip_m = 0.0;
  double velocity_m_s = 0.0;
  double static_force_n = 0.0;
  double height_m = 0.0;
};

struct SceneSolver {
  double r_ftrunc = 300.0;           // Of each beam's own first elastic frequency, unless
  std::optional<double> f_trunc_hz;  // an absolute truncation is given (beams may override).
  // Static correction modes (ENRI_STAT) at the heights of every beam's zones and along the
  // normals of every structure's zones at its nodes.
  bool static_correction = false;
  TimeStepRequest dt;
  double end_time_s = 0.0;
};

// A beam's deflection at a height, or a structure's node's motion along a unit direction
// (structure >= 0, beam unused).
struct ObservedPoint {
  std::string name;
  int beam = 0;
  double height_m = 0.0;
  int direction = 0;  // 0: y, 1: z.
  int structure = -1, node = 0;
  std::array<double, 3> direction_xyz{0.0, 1.0, 0.0};
};

// Nothing unrequested is recorded.
struct SceneOutputs {
  std::vector<ObservedPoint> displacements;
  bool contact_forces = false;  // Force histories: of these zones, or of every zone if empty.
  std::vector<int> contact_force_zones;
  bool energies = false;
  bool max_contact_force = false;  // Per zone, over the whole run.
  bool shocks = false;  // Shock statistics of the zones whose force histories are recorded.
  double rest_duration_s = 0.0;  // Shock grouping; required with shocks.
  // Impact statistics of every zone (docs/physics.md §6), streamed: no history needed.
  bool impact_statistics = false;
  ImpactCounting impact_counting;       // Its rest duration required (>= 0) with impact_statistics.
  std::vector<int> impact_table_zones;  // The zones whose impacts are listed one by one.
  int record_stride = 1;
};

struct Scene {
  std::string name;
  std::string description;
  BendingPlanes planes = BendingPlanes::kPlanar;
  std::vector<SceneBeam> beams;
  std::vector<SceneStructure> structures;  // Their coordinates follow the beams'.
  std::vector<SceneZone> zones;
  std::optional<ModalDampingEffect> modal_damping;
  std::optional<BaseMotionEffect> base_motion;
  std::vector<StaticForceEffect> static_forces;
  std::vector<InitialStateEffect> initial_state;
  std::optional<WearLaw> wear;  // Wear volumes of the zones (needs impact statistics).
  SceneSolver solver;
  SceneOutputs outputs;

  int Directions() const { return planes == BendingPlanes::kBoth ? 2 : 1; }
  // The name of a zone's side a or b: its beam's, its structure's with the node
  // ("plate#12"), or "stop".
  std::string SideName(const SceneZone& z, bool side_b) const;
};

}  // namespace shockmap
