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

#include <Eigen/Dense>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace shockmap {

// One zone in modal coordinates. Offsets are the first coordinate of each beam's block in y
// and z (-1 when absent: planar scenes, or a stop instead of beam b).
struct ZoneTerm {
  int a_y = -1, a_z = -1, b_y = -1, b_z = -1;
  std::vector<double> phi_a, phi_b;  // Mode shapes at the zone's height (1/sqrt(kg)).
  double normal_y = 1.0, normal_z = 0.0;
  double gap_m = 0.0, stiffness_n_per_m = 0.0, damping_n_s_per_m = 0.0;
};

class ContactStations {
 public:
  // Stations are the distinct (block, mode shape) pairs of the zones' two sides, grouped by
  // beam so that a beam's stations are evaluated together. Zones keep their order.
  explicit ContactStations(const std::vector<ZoneTerm>& zones);

  // The step's contact forces: every station's displacement at x, every zone's penalty force
  // F = max(0, k d + c d') (d' from v, evaluated only at the stations of closed damped zones,
  // once per station and step), each closed zone's force added to a on both beams' modes.
  void AddForces(const Eigen::VectorXd& x, const Eigen::VectorXd& v, Eigen::VectorXd& a);
  // The force of each zone (N, >= 0) in the last AddForces.
  std::span<const double> Forces() const { return force_; }

  // u_a - u_b at the zone's height, (y, z) components (m), at the last AddForces' x.
  std::array<double, 2> RelativeDisplacement(int zone) const;
  // v_a - v_b at the zone's height, (y, z) components (m/s), at state v.
  std::array<double, 2> RelativeVelocity(int zone, const Eigen::VectorXd& v) const;

  // Sum over closed zones of the penalty energy k d^2 / 2 at x (J).
  double ContactEnergy(const Eigen::VectorXd& x) const;
  // p plus the power taken out by contact damping at (x, v): the terms (F - k d) d' of the
  // closed damped zones added to p one by one, in zone order.
  double AddDampingPower(const Eigen::VectorXd& x, const Eigen::VectorXd& v, double p) const;
  bool AnyDamping() const { return !damped_.empty(); }
  // y += sum_z k_z r_z r_z^T x: the stiffness of every zone closed, applied to x.
  void AddClosedStiffness(const Eigen::VectorXd& x, Eigen::VectorXd& y) const;

 private:
  // The stations of one beam: slots [first, first + width), width padded to the kernel's lane
  // count with zero shapes; shapes at `shapes` in mode-major order (modes x width).
  struct Block {
    int y = -1, z = -1, modes = 0, first = 0, width = 0, count = 0, shapes = 0;
  };
  // Per slot (slot 0 is the base: zero motion, its force discarded).
  struct Slots {
    std::vector<double> y, z;
  };

  void Evaluate(const Eigen::VectorXd& x, Slots& out) const;
  double Normal(int zone, const Slots& u) const;
  // A slot's (y, z) values at a state, from its row (the base: zero).
  std::array<double, 2> SlotAt(int slot, const Eigen::VectorXd& state) const;
  double NormalAt(int zone, const Eigen::VectorXd& state) const;
  void VelocityAt(int slot, const Eigen::VectorXd& v);
  // a += the forces (y, z) of one zone side on its slot's modes (nothing for the base).
  void AddToSlot(int slot, double force_y, double force_z, Eigen::VectorXd& a) const;

  std::vector<Block> blocks_;
  std::vector<double> shapes_;  // Mode-major matrices, shared by blocks of equal shapes.
  std::vector<double> rows_;    // Per slot, its mode shape (modes contiguous).
  std::vector<int> slot_row_;   // Offset of each slot's row in rows_ (-1: base, padding).
  std::vector<int> slot_y_, slot_z_, slot_modes_;
  // Zones, structure of arrays.
  std::vector<int> slot_a_, slot_b_;
  std::vector<double> normal_y_, normal_z_, gap_, stiffness_, damping_;
  std::vector<int> damped_;  // The zones with contact damping.
  // The step's state.
  Slots displacement_, velocity_;
  std::vector<std::uint64_t> velocity_step_;  // The step a slot's velocity belongs to.
  std::uint64_t step_ = 0;
  std::vector<double> force_;
  std::vector<int> closed_;  // The zones closed in this step, in zone order.
  // EnergyAt and the stiffness operator evaluate into this: one thread per system.
  mutable Slots scratch_;
};

}  // namespace shockmap
