#include "core/contact_stations.h"

#include <algorithm>
#include <map>
#include <tuple>

#include "core/station_kernels.h"

namespace shockmap {
namespace {

// A station being collected: the beam's block and its distinct shapes in order of appearance.
struct BlockDraft {
  std::vector<const std::vector<double>*> shapes;
  std::map<std::vector<double>, int> index;
  int Add(const std::vector<double>& phi) {
    const auto [it, added] = index.emplace(phi, static_cast<int>(shapes.size()));
    if (added) shapes.push_back(&phi);
    return it->second;
  }
};

}  // namespace

ContactStations::ContactStations(const std::vector<ZoneTerm>& zones) {
  // Blocks keyed by their coordinates (beam order); each zone side names (block, station).
  std::map<std::pair<int, int>, BlockDraft> drafts;
  std::vector<std::array<std::tuple<int, int, int>, 2>> sides;
  for (const ZoneTerm& z : zones) {
    std::array<std::tuple<int, int, int>, 2> side{std::tuple{-1, -1, -1}, std::tuple{-1, -1, -1}};
    if (z.InFrame()) {
      sides.push_back(side);
      continue;
    }
    side[0] = {z.a_y, z.a_z, drafts[{z.a_y, z.a_z}].Add(z.phi_a)};
    if (z.b_y >= 0 || z.b_z >= 0) side[1] = {z.b_y, z.b_z, drafts[{z.b_y, z.b_z}].Add(z.phi_b)};
    sides.push_back(side);
  }
  std::map<std::pair<int, int>, int> first_slot;
  std::map<std::vector<double>, int> shared;  // Shape matrices already stored.
  int slots = 1;                              // Slot 0: the base.
  slot_row_ = {-1};
  slot_y_ = {-1};
  slot_z_ = {-1};
  slot_modes_ = {0};
  for (const auto& [coordinates, draft] : drafts) {
    StationBlock b;
    b.y = coordinates.first;
    b.z = coordinates.second;
    b.modes = static_cast<int>(draft.shapes.front()->size());
    b.count = static_cast<int>(draft.shapes.size());
    b.width = StationWidth(b.count);
    b.first = slots;
    std::vector<double> matrix(static_cast<std::size_t>(b.modes) * b.width, 0.0);
    for (int h = 0; h < b.count; ++h) {
      for (int i = 0; i < b.modes; ++i) matrix[i * b.width + h] = (*draft.shapes[h])[i];
    }
    matrix.push_back(b.modes);  // The key also holds the shape of the matrix.
    const auto [it, added] = shared.emplace(matrix, static_cast<int>(shapes_.size()));
    if (added) shapes_.insert(shapes_.end(), matrix.begin(), matrix.end() - 1);
    b.shapes = it->second;
    for (int h = 0; h < b.width; ++h) {
      slot_row_.push_back(h < b.count ? static_cast<int>(rows_.size()) : -1);
      if (h < b.count) rows_.insert(rows_.end(), draft.shapes[h]->begin(), draft.shapes[h]->end());
      slot_y_.push_back(b.y);
      slot_z_.push_back(b.z);
      slot_modes_.push_back(b.modes);
    }
    first_slot[coordinates] = b.first;
    slots += b.width;
    blocks_.push_back(b);
  }
  first_frame_slot_ = slots;
  // One frame station per side of each zone in its own frame (the base for a stop).
  auto add_frame = [&](const std::vector<FrameSegment>& segments) {
    if (segments.empty()) return 0;
    frames_.push_back(segments);
    slot_row_.push_back(-1);
    slot_y_.push_back(-1);
    slot_z_.push_back(-1);
    slot_modes_.push_back(0);
    return slots++;
  };
  for (std::size_t i = 0; i < zones.size(); ++i) {
    const ZoneTerm& z = zones[i];
    auto slot_of = [&](const std::tuple<int, int, int>& s) {
      const auto [y, zz, station] = s;
      return station < 0 ? 0 : first_slot.at({y, zz}) + station;
    };
    slot_a_.push_back(z.InFrame() ? add_frame(z.frame_a) : slot_of(sides[i][0]));
    slot_b_.push_back(z.InFrame() ? add_frame(z.frame_b) : slot_of(sides[i][1]));
    normal_y_.push_back(z.normal_y);
    normal_z_.push_back(z.normal_z);
    gap_.push_back(z.gap_m);
    stiffness_.push_back(z.law.normal.stiffness);
    damping_.push_back(z.law.normal.damping_n_s_per_m);
    laws_.push_back(z.law);
    if (z.law.normal.damping_n_s_per_m != 0.0) damped_.push_back(static_cast<int>(i));
    if (z.law.normal.HasBoundPenetration()) power_.push_back(static_cast<int>(i));
    friction_of_.push_back(z.law.friction ? static_cast<int>(frictions_.size()) : -1);
    if (z.law.friction) frictions_.push_back({*z.law.friction, {}, 0});
  }
  largest_penetration_.assign(power_.size(), 0.0);
  for (Slots* s : {&displacement_, &velocity_, &scratch_}) {
    s->yz.assign(2 * static_cast<std::size_t>(slots), 0.0);
  }
  velocity_step_.assign(slots, 0);
  force_.assign(zones.size(), 0.0);
  closed_.assign(zones.size(), 0);
  station_forces_.reserve(2 * zones.size());
}

void ContactStations::Evaluate(const Eigen::VectorXd& x, Slots& out) const {
  EvaluateStations(blocks_, shapes_.data(), x.data(), out.yz.data());
  if (!frames_.empty()) EvaluateFrames(x, out);
}

std::array<double, 2> ContactStations::FrameAt(int slot, const Eigen::VectorXd& state) const {
  std::array<double, 2> u{0.0, 0.0};
  for (const FrameSegment& s : Frame(slot)) {
    const int n = static_cast<int>(s.normal.size());
    u[0] += StationDot(s.normal.data(), state.data() + s.offset, n);
    u[1] += StationDot(s.tangent.data(), state.data() + s.offset, n);
  }
  return u;
}

void ContactStations::EvaluateFrames(const Eigen::VectorXd& x, Slots& out) const {
  for (int slot = first_frame_slot_; slot < static_cast<int>(slot_row_.size()); ++slot) {
    const auto u = FrameAt(slot, x);
    out.yz[2 * slot] = u[0];
    out.yz[2 * slot + 1] = u[1];
  }
}

void ContactStations::AddFrameForce(int slot, double force_n, double force_t, double* a) const {
  for (const FrameSegment& s : Frame(slot)) {
    for (std::size_t i = 0; i < s.normal.size(); ++i)
      a[s.offset + static_cast<int>(i)] += force_n * s.normal[i] + force_t * s.tangent[i];
  }
}

// n . (u_a - u_b), in the order the zone-by-zone sum used (the base reads zero).
double ContactStations::Normal(int zone, const Slots& u) const {
  const int a = slot_a_[zone], b = slot_b_[zone];
  const double ny = normal_y_[zone], nz = normal_z_[zone];
  return ny * u.Y(a) + nz * u.Z(a) - ny * u.Y(b) - nz * u.Z(b);
}

std::array<double, 2> ContactStations::SlotAt(int slot, const Eigen::VectorXd& state) const {
  if (slot == 0) return {0.0, 0.0};
  if (IsFrame(slot)) return FrameAt(slot, state);
  const double* row = rows_.data() + slot_row_[slot];
  const int n = slot_modes_[slot];
  return {StationDot(row, state.data() + slot_y_[slot], n),
          slot_z_[slot] >= 0 ? StationDot(row, state.data() + slot_z_[slot], n) : 0.0};
}

double ContactStations::Tangential(int zone, const Slots& u) const {
  const int a = slot_a_[zone], b = slot_b_[zone];
  const double ny = normal_y_[zone], nz = normal_z_[zone];
  return -nz * u.Y(a) + ny * u.Z(a) + nz * u.Y(b) - ny * u.Z(b);
}

double ContactStations::NormalAt(int zone, const Eigen::VectorXd& state) const {
  const auto ua = SlotAt(slot_a_[zone], state), ub = SlotAt(slot_b_[zone], state);
  const double ny = normal_y_[zone], nz = normal_z_[zone];
  return ny * ua[0] + nz * ua[1] - ny * ub[0] - nz * ub[1];
}

void ContactStations::VelocityAt(int slot, const Eigen::VectorXd& v) {
  if (velocity_step_[slot] == step_) return;
  velocity_step_[slot] = step_;
  const auto w = SlotAt(slot, v);
  velocity_.yz[2 * slot] = w[0];
  velocity_.yz[2 * slot + 1] = w[1];
}

void ContactStations::Push(int slot, double force_y, double force_z) {
  if (slot == 0) return;
  (IsFrame(slot) ? frame_forces_ : station_forces_).push_back({slot, force_y, force_z});
}

void ContactStations::AddForces(double t_s, const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                                Eigen::VectorXd& a) {
  Evaluate(x, displacement_);
  ++step_;
  dt_s_ = t_s - t_s_;
  t_s_ = t_s;
  // First the linear penalty forces and the list of closed zones; then the power laws' forces;
  // then the closed zones' damping, friction and projection, in zone order.
  const PenaltyZones zones{slot_a_.data(),
                           slot_b_.data(),
                           normal_y_.data(),
                           normal_z_.data(),
                           gap_.data(),
                           stiffness_.data(),
                           static_cast<int>(force_.size())};
  const int n_closed =
      LinearPenaltyForces(zones, displacement_.yz.data(), force_.data(), closed_.data());
  if (!power_.empty()) ApplyPowerLaws();
  friction_power_w_ = 0.0;
  if (frictions_.empty()) {
    ProjectClosed<false>(n_closed, v, a);
  } else {
    ProjectClosed<true>(n_closed, v, a);
  }
}

void ContactStations::ApplyPowerLaws() {
  for (std::size_t j = 0; j < power_.size(); ++j) {
    const int i = power_[j];
    const double penetration = Normal(i, displacement_) - gap_[i];
    // Of exponent 1, the law is the linear penalty, whose force is already set.
    if (!laws_[i].normal.IsLinear()) force_[i] = laws_[i].normal.ElasticForce(penetration);
    largest_penetration_[j] = std::max(largest_penetration_[j], penetration);
  }
}

template <bool kFriction>
void ContactStations::ProjectClosed(int n_closed, const Eigen::VectorXd& v, Eigen::VectorXd& a) {
  const int* const slot_a = slot_a_.data();
  const int* const slot_b = slot_b_.data();
  const double* const ny = normal_y_.data();
  const double* const nz = normal_z_.data();
  const double* const c = damping_.data();
  double* const force = force_.data();
  const int* const closed = closed_.data();
  station_forces_.clear();
  frame_forces_.clear();
  for (int j = 0; j < n_closed; ++j) {
    const int i = closed[j], sa = slot_a[i], sb = slot_b[i];
    if (c[i] != 0.0) {
      VelocityAt(sa, v);
      VelocityAt(sb, v);
      force[i] = std::max(0.0, force[i] + c[i] * Normal(i, velocity_));
    }
    const double f = force[i];
    if constexpr (kFriction) {
      if (friction_of_[i] >= 0) {
        // The friction force along t = (-n_z, n_y), on a, and its reaction on b.
        const double ft = RubbingForce(i, f, v);
        Push(sa, -f * ny[i] - ft * nz[i], -f * nz[i] + ft * ny[i]);
        Push(sb, f * ny[i] + ft * nz[i], f * nz[i] - ft * ny[i]);
        continue;
      }
    }
    Push(sa, -f * ny[i], -f * nz[i]);
    Push(sb, f * ny[i], f * nz[i]);
  }
  const StationLayout layout{rows_.data(), slot_row_.data(), slot_y_.data(), slot_z_.data(),
                             slot_modes_.data()};
  AddStationForces(station_forces_, layout, a.data());
  for (const StationForce& f : frame_forces_) AddFrameForce(f.slot, f.y, f.z, a.data());
}

double ContactStations::RubbingForce(int zone, double f, const Eigen::VectorXd& v) {
  Rubbing& r = frictions_[friction_of_[zone]];
  const double slip = Tangential(zone, displacement_);
  // A contact closing (not closed at the step before): its spring starts relaxed. The first
  // call (step 1) is the run's initial state.
  if (r.closed_step == 0 || r.closed_step + 1 != step_) {
    r.state = ClosingFrictionState(r.law, slip, step_ == 1);
  }
  r.closed_step = step_;
  // The slip rate enters through the tangential damper, or code_aster's convention: evaluated
  // only then.
  const double rate = r.law.ReadsSlipRate() ? SlipRate(zone, v) : 0.0;
  const double force = FrictionForce(r.law, f, slip, rate, r.state);
  if (dt_s_ > 0.0) friction_power_w_ += FrictionDissipatedPower(r.law, r.state, dt_s_, rate);
  return force;
}

double ContactStations::SlipRate(int zone, const Eigen::VectorXd& v) {
  VelocityAt(slot_a_[zone], v);
  VelocityAt(slot_b_[zone], v);
  return Tangential(zone, velocity_);
}

double ContactStations::TangentialForce(int zone) const {
  const int j = friction_of_[zone];
  return j >= 0 && frictions_[j].closed_step == step_ ? frictions_[j].state.force_n : 0.0;
}

bool ContactStations::Sticks(int zone) const {
  const int j = friction_of_[zone];
  return j >= 0 && frictions_[j].closed_step == step_ && !frictions_[j].state.sliding;
}

std::vector<double> ContactStations::LargestPenetrations() const {
  std::vector<double> largest(force_.size(), 0.0);
  for (std::size_t j = 0; j < power_.size(); ++j) largest[power_[j]] = largest_penetration_[j];
  return largest;
}

std::array<double, 2> ContactStations::RelativeDisplacement(int zone) const {
  const int a = slot_a_[zone], b = slot_b_[zone];
  return {displacement_.Y(a) - displacement_.Y(b), displacement_.Z(a) - displacement_.Z(b)};
}

std::array<double, 2> ContactStations::RelativeVelocity(int zone, const Eigen::VectorXd& v) const {
  const auto wa = SlotAt(slot_a_[zone], v), wb = SlotAt(slot_b_[zone], v);
  return {wa[0] - wb[0], wa[1] - wb[1]};
}

double ContactStations::ContactEnergy(const Eigen::VectorXd& x) const {
  Evaluate(x, scratch_);
  double e = 0.0;
  for (std::size_t i = 0; i < force_.size(); ++i) {
    const double d = Normal(static_cast<int>(i), scratch_) - gap_[i];
    if (d > 0.0) e += laws_[i].normal.Energy(d);
  }
  for (std::size_t i = 0; i < force_.size(); ++i) {
    const int j = friction_of_[i];
    if (j < 0 || frictions_[j].closed_step != step_) continue;
    const int zone = static_cast<int>(i);
    if (Normal(zone, scratch_) - gap_[i] <= 0.0) continue;
    e += FrictionEnergy(frictions_[j].law, frictions_[j].state, Tangential(zone, scratch_));
  }
  return e;
}

double ContactStations::AddDampingPower(const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                                        double p) const {
  for (int i : damped_) {
    const double d = NormalAt(i, x) - gap_[i];
    if (d <= 0.0) continue;
    // d/dt (kinetic + strain + spring) = (F_e - F) d': what leaves is (F - F_e) d'.
    const double rate = NormalAt(i, v);
    const NormalLaw& law = laws_[i].normal;
    p += (law.Force(d, rate) - law.ElasticForce(d)) * rate;
  }
  // Friction's power was found by the solve of the step that reached (x, v).
  return p + friction_power_w_;
}

std::vector<double> ContactStations::BoundStiffnesses() const {
  std::vector<double> k;
  for (const ContactLaw& law : laws_) k.push_back(law.normal.BoundStiffness());
  return k;
}

void ContactStations::AddClosedStiffness(const Eigen::VectorXd& x,
                                         std::span<const double> normal_stiffness,
                                         Eigen::VectorXd& y) const {
  Evaluate(x, scratch_);
  // Per station, the generalized force k_z (r_z . x) n with the sign of its side, and
  // k_t (t_z . x) t for the zones with friction.
  std::vector<double> gy(slot_row_.size(), 0.0), gz(slot_row_.size(), 0.0);
  for (std::size_t i = 0; i < force_.size(); ++i) {
    const int zone = static_cast<int>(i);
    const double f = normal_stiffness[i] * Normal(zone, scratch_);
    gy[slot_a_[i]] += f * normal_y_[i];
    gz[slot_a_[i]] += f * normal_z_[i];
    gy[slot_b_[i]] -= f * normal_y_[i];
    gz[slot_b_[i]] -= f * normal_z_[i];
    if (friction_of_[i] < 0) continue;
    const double ft =
        frictions_[friction_of_[i]].law.tangential_stiffness_n_per_m * Tangential(zone, scratch_);
    gy[slot_a_[i]] -= ft * normal_z_[i];
    gz[slot_a_[i]] += ft * normal_y_[i];
    gy[slot_b_[i]] += ft * normal_z_[i];
    gz[slot_b_[i]] -= ft * normal_y_[i];
  }
  for (std::size_t s = 1; s < gy.size(); ++s) {
    if (IsFrame(static_cast<int>(s))) {
      AddFrameForce(static_cast<int>(s), gy[s], gz[s], y.data());
      continue;
    }
    if (slot_row_[s] < 0) continue;
    const double* row = rows_.data() + slot_row_[s];
    for (int i = 0; i < slot_modes_[s]; ++i) {
      y[slot_y_[s] + i] += gy[s] * row[i];
      if (slot_z_[s] >= 0) y[slot_z_[s] + i] += gz[s] * row[i];
    }
  }
}

Eigen::VectorXd ZoneRow(const ZoneTerm& z, int n, double dir_y, double dir_z) {
  Eigen::VectorXd r = Eigen::VectorXd::Zero(n);
  auto put = [&](int offset, double scale, const std::vector<double>& phi) {
    if (offset < 0) return;
    for (std::size_t i = 0; i < phi.size(); ++i) r[offset + static_cast<int>(i)] += scale * phi[i];
  };
  put(z.a_y, dir_y, z.phi_a);
  put(z.a_z, dir_z, z.phi_a);
  put(z.b_y, -dir_y, z.phi_b);
  put(z.b_z, -dir_z, z.phi_b);
  auto put_frame = [&](double scale, const std::vector<FrameSegment>& side) {
    for (const FrameSegment& s : side) {
      for (std::size_t i = 0; i < s.normal.size(); ++i) {
        r[s.offset + static_cast<int>(i)] += scale * (dir_y * s.normal[i] + dir_z * s.tangent[i]);
      }
    }
  };
  put_frame(1.0, z.frame_a);
  put_frame(-1.0, z.frame_b);
  return r;
}

}  // namespace shockmap
