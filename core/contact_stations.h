#pragma once
// The contact zones of a scene evaluated per station: a station is one beam at one height where
// zones act (docs/performance.md, "Explicit steps and bundles"). A step evaluates each station's
// displacement once (all stations of a beam together), reads every zone's penetration from its
// two stations and adds each closed zone's force on both beams' modes (paper eq. 7). In a bundle
// a pin takes part in about six zones per wire height, so this costs one modal sum per station
// instead of one per zone and beam.
//
// The forces are added zone by zone in zone order, not summed per station first: that is the
// order of the zone-by-zone step this replaces, so results are equal bit for bit. The row
// bundle's rattling amplifies a change of the last digit to 26 % in a zone's largest force over
// 0.5 s (measured with per-station sums); the per-zone projection measured 10 % dearer than
// per-station sums on the 217-pin bundle (docs/performance.md).
//
// Per-zone quantities stay reachable: Forces() (zone order, the last step's), and
// RelativeDisplacement / RelativeVelocity of a zone (u_a - u_b and v_a - v_b at its height, y
// and z), from which any normal or tangential component follows.
//
// Each zone's force follows its law (core/contact_law.h). The linear penalty, the law of every
// zone of the shipped scenes, is evaluated for all zones at once without a branch; zones with a
// power law then have their force replaced, and zones with friction add their tangential force
// along t = (-n_z, n_y) (scenes bending in both planes) when they are projected. A scene without
// either runs the loops it ran before them.

#include <Eigen/Dense>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/contact_law.h"
#include "core/station_kernels.h"

namespace shockmap {

// Part of a zone side given in the zone's own frame: over the coordinates from `offset`, the
// rows whose products with them are the side's motion along the zone's normal and along its
// tangent (1/sqrt(kg)).
struct FrameSegment {
  int offset = 0;
  std::vector<double> normal, tangent;
};

// One zone in modal coordinates. Offsets are the first coordinate of each beam's block in y
// and z (-1 when absent: planar scenes, or a stop instead of beam b).
//
// A zone at a structure's node is given in its own frame instead (frame_a not empty): each side
// a sum of segments (a structure's block, or a beam's y and z blocks weighted by the normal's
// and the tangent's components), the offsets and shapes above unused (-1, empty), frame_b empty
// against a stop, and the normal (1, 0): a station's y is then the side's normal motion and its
// z its tangential one, so that every law reads the zone as it reads a beam's.
struct ZoneTerm {
  int a_y = -1, a_z = -1, b_y = -1, b_z = -1;
  std::vector<double> phi_a, phi_b;  // Mode shapes at the zone's height (1/sqrt(kg)).
  std::vector<FrameSegment> frame_a, frame_b;
  double normal_y = 1.0, normal_z = 0.0;
  double gap_m = 0.0;
  ContactLaw law;  // Friction only where both sides bend in y and z, or in the zone's frame.

  bool InFrame() const { return !frame_a.empty(); }
};

// The zone's row along a direction (dir_y, dir_z): the normal for (n_y, n_z), the tangent for
// (-n_z, n_y), in a state of n coordinates: d . (u_a - u_b) = row . x (in the zone's frame for a
// zone in its own frame).
Eigen::VectorXd ZoneRow(const ZoneTerm& z, int n, double dir_y, double dir_z);

class ContactStations {
 public:
  // Stations are the distinct (block, mode shape) pairs of the zones' two sides, grouped by
  // beam so that a beam's stations are evaluated together, then one frame station per side of
  // each zone in its own frame. Zones keep their order.
  explicit ContactStations(const std::vector<ZoneTerm>& zones);

  // The step's contact forces: every station's displacement at x, every zone's normal force
  // F = max(0, k d^p + c d') (d' from v, evaluated only at the stations of closed damped or
  // rubbing zones, once per station and step), and each closed zone's force, with its friction
  // force, added to a on both beams' modes. Friction states advance: one call per step.
  // t_s: the time of the state, whose difference from the previous call's is the step the
  // friction's work is spread over.
  void AddForces(double t_s, const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                 Eigen::VectorXd& a);
  // The normal force of each zone (N, >= 0) in the last AddForces.
  std::span<const double> Forces() const { return force_; }
  // A zone's tangential force on side a along t in the last AddForces (0 when open or without
  // friction), and whether it stuck (true only for a closed zone with friction).
  double TangentialForce(int zone) const;
  bool Sticks(int zone) const;
  bool HasFriction(int zone) const { return friction_of_[zone] >= 0; }
  // The largest penetration each zone reached over the AddForces calls, for zones with a power
  // law (0 for the others).
  std::vector<double> LargestPenetrations() const;

  // u_a - u_b at the zone's height, (y, z) components (m), at the last AddForces' x.
  std::array<double, 2> RelativeDisplacement(int zone) const;
  // v_a - v_b at the zone's height, (y, z) components (m/s), at state v.
  std::array<double, 2> RelativeVelocity(int zone, const Eigen::VectorXd& v) const;

  // Sum over closed zones of the elastic energy of their normal law at x, and of the energy in
  // the tangential springs of those rubbing in the last AddForces (J).
  double ContactEnergy(const Eigen::VectorXd& x) const;
  // p plus the power taken out by contact damping at (x, v): the terms (F - F_e) d' of the
  // closed damped zones added to p one by one, in zone order (F_e the law's elastic force), then
  // the power friction dissipated over the step the last AddForces solved
  // (FrictionDissipatedPower: x and v are the state that step reached).
  double AddDampingPower(const Eigen::VectorXd& x, const Eigen::VectorXd& v, double p) const;
  bool AnyDamping() const { return !damped_.empty() || !frictions_.empty(); }
  // Each zone's stiffness in the sharp bound: its normal law's BoundStiffness().
  std::vector<double> BoundStiffnesses() const;
  // y += sum_z (k_z r_z r_z^T + k_t,z t_z t_z^T) x: every zone closed with the normal stiffness
  // k_z given (zone order), and the tangential springs of the zones with friction sticking.
  void AddClosedStiffness(const Eigen::VectorXd& x, std::span<const double> normal_stiffness,
                          Eigen::VectorXd& y) const;

 private:
  // Per slot (slot 0 is the base: zero motion, its force discarded), its (y, z) side by side:
  // a zone reads both of a station in one load.
  struct Slots {
    std::vector<double> yz;
    double Y(int slot) const { return yz[2 * slot]; }
    double Z(int slot) const { return yz[2 * slot + 1]; }
  };

  // A zone's friction: its law, its state, and the step it was last closed at.
  struct Rubbing {
    FrictionLaw law;
    FrictionState state;
    std::uint64_t closed_step = 0;
  };

  void Evaluate(const Eigen::VectorXd& x, Slots& out) const;
  double Normal(int zone, const Slots& u) const;
  // t . (u_a - u_b), t = (-n_z, n_y).
  double Tangential(int zone, const Slots& u) const;
  // The power-law zones' forces, replacing the linear ones of the first pass.
  void ApplyPowerLaws();
  // The closed zones' damping, friction (when kFriction) and projection, in zone order.
  template <bool kFriction>
  void ProjectClosed(int n_closed, const Eigen::VectorXd& v, Eigen::VectorXd& a);
  // t . (v_a - v_b) at v, the stations' velocities evaluated once per step.
  double SlipRate(int zone, const Eigen::VectorXd& v);
  // The friction force of a closed zone under normal force f, its state advanced.
  double RubbingForce(int zone, double f, const Eigen::VectorXd& v);
  // A slot's (y, z) values at a state, from its row (the base: zero).
  std::array<double, 2> SlotAt(int slot, const Eigen::VectorXd& state) const;
  double NormalAt(int zone, const Eigen::VectorXd& state) const;
  void VelocityAt(int slot, const Eigen::VectorXd& v);
  // Queues the force (y, z) of one zone side on its slot (nothing for the base): the queue is
  // added to the modes at the end of ProjectClosed, in order.
  void Push(int slot, double force_y, double force_z);
  // The frame stations: the slots from first_frame_slot_ on, each (normal, tangent) from its
  // segments.
  bool IsFrame(int slot) const { return slot >= first_frame_slot_; }
  const std::vector<FrameSegment>& Frame(int slot) const {
    return frames_[static_cast<std::size_t>(slot - first_frame_slot_)];
  }
  std::array<double, 2> FrameAt(int slot, const Eigen::VectorXd& state) const;
  void EvaluateFrames(const Eigen::VectorXd& x, Slots& out) const;
  // a += f_n (normal rows) + f_t (tangent rows) of a frame station.
  void AddFrameForce(int slot, double force_n, double force_t, double* a) const;

  std::vector<StationBlock> blocks_;
  std::vector<double> shapes_;  // Mode-major matrices, shared by blocks of equal shapes.
  std::vector<double> rows_;    // Per slot, its mode shape (modes contiguous).
  std::vector<int> slot_row_;   // Offset of each slot's row in rows_ (-1: base, padding).
  std::vector<int> slot_y_, slot_z_, slot_modes_;
  int first_frame_slot_ = 0;
  std::vector<std::vector<FrameSegment>> frames_;
  std::vector<StationForce> frame_forces_;  // The step's forces on frame stations, in order.
  // Zones, structure of arrays.
  std::vector<int> slot_a_, slot_b_;
  std::vector<double> normal_y_, normal_z_, gap_, stiffness_, damping_;
  std::vector<int> damped_;  // The zones with contact damping.
  std::vector<ContactLaw> laws_;
  std::vector<int> power_;                   // The zones whose normal law is a power law.
  std::vector<double> largest_penetration_;  // Per power_ entry.
  std::vector<int> friction_of_;             // Per zone, its index in frictions_ (-1: none).
  std::vector<Rubbing> frictions_;
  // The step's state.
  Slots displacement_, velocity_;
  std::vector<std::uint64_t> velocity_step_;  // The step a slot's velocity belongs to.
  std::uint64_t step_ = 0;
  std::vector<double> force_;
  std::vector<int> closed_;                   // The zones closed in this step, in zone order.
  std::vector<StationForce> station_forces_;  // The step's forces per station side, in order.
  // EnergyAt and the stiffness operator evaluate into this: one thread per system.
  mutable Slots scratch_;
  double friction_power_w_ = 0.0;  // Friction's over the last AddForces' step (W).
  double t_s_ = 0.0, dt_s_ = 0.0;  // The last AddForces' time and step.
};

}  // namespace shockmap
