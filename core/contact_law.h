#pragma once
// The laws of a contact (docs/physics.md §7): a normal law on the penetration, and an optional
// Coulomb friction with a tangential stiffness in the style of code_aster's DIS_CHOC. Every
// model evaluates its contacts through these: the scene's contact stations, the full FE model,
// the static preload equilibrium and the stability bounds.

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace shockmap {

// The linear penalty's elastic force k max(0, d) (paper eq. 5), 0 for an open or NaN
// penetration. The contact stations' kernel (core/station_kernels.cpp) computes it eight zones
// at a time, each lane as this does, and calls it for the zones left over.
inline double LinearPenaltyForce(double stiffness, double penetration) {
  return stiffness * std::max(0.0, penetration);
}

// F = k d^p + c d' while the penetration d > 0, clamped at 0 (a stop never pulls); 0 when open.
// p = 1 is the linear penalty (paper eq. 5), p = 3/2 Hertz's contact of a sphere on a plane.
struct NormalLaw {
  double stiffness = 0.0;          // k: N/m when p = 1, N/m^p otherwise.
  double damping_n_s_per_m = 0.0;  // c: viscous, acts only in contact.
  double exponent = 1.0;           // p >= 1.
  // For p > 1, whose tangent stiffness vanishes at d = 0: the penetration at which the
  // explicit scheme's stability bound takes it (BoundStiffness). Given with every power law, of
  // exponent 1 too; 0 for the linear penalty.
  double bound_penetration_m = 0.0;

  bool IsLinear() const { return exponent == 1.0; }
  // A power law of any exponent (a scene's `power_law`), whose reached penetrations a run
  // checks against its bound penetration (core/reached_bound.h).
  bool HasBoundPenetration() const { return bound_penetration_m > 0.0; }

  // k d^p for d > 0, else 0 (N).
  double ElasticForce(double d) const {
    if (IsLinear()) return LinearPenaltyForce(stiffness, d);
    return d > 0.0 ? stiffness * std::pow(d, exponent) : 0.0;
  }
  // max(0, k d^p + c d') for d > 0, else 0 (N).
  double Force(double d, double rate) const {
    if (!(d > 0.0)) return 0.0;
    return std::max(0.0, ElasticForce(d) + damping_n_s_per_m * rate);
  }
  // The elastic energy k d^(p+1) / (p+1) for d > 0, else 0 (J).
  double Energy(double d) const {
    if (!(d > 0.0)) return 0.0;
    if (IsLinear()) return 0.5 * stiffness * d * d;
    return stiffness * std::pow(d, exponent + 1.0) / (exponent + 1.0);
  }
  // dF/dd of the elastic part, p k d^(p-1) for d > 0, else 0 (N/m).
  double TangentStiffness(double d) const {
    if (IsLinear()) return d > 0.0 ? stiffness : 0.0;
    return d > 0.0 ? exponent * stiffness * std::pow(d, exponent - 1.0) : 0.0;
  }
  // The stiffness the sharp stability bound gives the closed contact: k when linear, else the
  // tangent stiffness at bound_penetration_m (N/m).
  double BoundStiffness() const {
    return IsLinear() ? stiffness : TangentStiffness(bound_penetration_m);
  }
};

// How a zone with friction decides between sticking and sliding (docs/physics.md §7.2).
enum class FrictionConvention {
  // The default: the spring's elastic trial force against the Coulomb limit (a return mapping).
  kReturnMapping,
  // code_aster's DIS_CHOC in a modal transient (its ftang routine): the slip rate's sign decides.
  kCodeAster,
};

// Coulomb friction regularized by a tangential spring, as DIS_CHOC: while the contact is closed
// a spring k_t, in parallel with a damper c_t, ties the two sides' tangential slip s to an
// anchor s0; the force it carries is capped at mu N (N the normal force). Sticking holds up to
// the static coefficient; beyond, the zone slides under the sliding coefficient's force and the
// anchor follows so that the spring holds that force. The convention says when a zone passes
// from one to the other (docs/physics.md §7.2).
struct FrictionLaw {
  double coefficient = 0.0;                   // mu: sliding (code_aster's COULOMB_DYNA).
  double static_coefficient = 0.0;            // mu_s >= mu: sticking (COULOMB_STAT).
  double tangential_stiffness_n_per_m = 0.0;  // k_t > 0 (RIGI_TAN).
  double tangential_damping_n_s_per_m = 0.0;  // c_t >= 0, while sticking (AMOR_TAN).
  FrictionConvention convention = FrictionConvention::kReturnMapping;

  // Whether the force depends on the slip rate: with a damper, or in code_aster's convention.
  bool ReadsSlipRate() const {
    return tangential_damping_n_s_per_m != 0.0 || convention == FrictionConvention::kCodeAster;
  }
};

// One zone's friction between steps.
struct FrictionState {
  double anchor_m = 0.0;  // s0: the slip at which the tangential spring is relaxed.
  double force_n = 0.0;   // The latest tangential force on side a, along the zone's tangent.
  bool sliding = false;   // The latest force is mu N, the anchor following.
  // The work the slider dissipated in the latest update (J): the structure's work -F ds less
  // what the spring stored (FrictionForce says how each convention counts it).
  double slid_work_j = 0.0;
  // code_aster's convention only: the slip and slip rate of the latest update (ftang's OLDVT),
  // and the latest sliding force and the slip it slid at (OLDFT, OLDXLO), kept apart as ftang
  // keeps them, so that a stick starts from that force exactly: s0 = OLDXLO + OLDFT / k_t.
  double slip_m = 0.0;
  double slip_rate_m_s = 0.0;
  double slide_force_n = 0.0;
  double slide_slip_m = 0.0;
};

// The state of a zone whose contact closes at slip s (m), the spring relaxed. In the default
// convention the zone starts sticking, anchored at s. In code_aster's it starts as DIS_CHOC's
// state after an open step: sliding, with no previous slip rate, so that it slides at once when
// the sides move faster than kCodeAsterSlidingSpeedMS, and else sticks anchored at s (DIS_CHOC
// anchors it at the slip of the open step before, one step's slip away). A zone closed when the
// run starts has no open step before it: DIS_CHOC's anchor is then the origin of the
// obstacle's frame, far away, so the zone slides at its first update; here no anchor at all
// (infinite) has that effect.
inline FrictionState ClosingFrictionState(const FrictionLaw& law, double slip_m,
                                          bool at_run_start) {
  FrictionState state;
  state.anchor_m = slip_m;
  state.slip_m = slip_m;
  state.slide_slip_m = slip_m;
  if (law.convention == FrictionConvention::kCodeAster) {
    state.sliding = true;
    if (at_run_start) {
      state.anchor_m = std::numeric_limits<double>::infinity();
      state.slide_slip_m = state.anchor_m;
    }
  }
  return state;
}

// The default convention's tangential force on side a along the tangent (N) at slip s (m) and
// slip rate s' (m/s) under the normal force N >= 0, the state updated: an elastic trial
// -k_t (s - s0) - c_t s', kept while within the limit (mu_s N sticking, mu N sliding), else
// mu N along the trial with the anchor moved to s + F / k_t (a return mapping), the slider's
// work -F (s0 - s0_before) recorded: the energy the spring did not store of the structure's
// work -F ds, F^2 / (2 k_t) following N included.
inline double ReturnMappingFrictionForce(const FrictionLaw& law, double normal_force_n,
                                         double slip_m, double slip_rate_m_s,
                                         FrictionState& state) {
  const double trial = -law.tangential_stiffness_n_per_m * (slip_m - state.anchor_m) -
                       law.tangential_damping_n_s_per_m * slip_rate_m_s;
  const double limit = (state.sliding ? law.coefficient : law.static_coefficient) * normal_force_n;
  if (std::abs(trial) <= limit) {
    state.sliding = false;
    state.force_n = trial;
    state.slid_work_j = 0.0;
  } else {
    state.sliding = true;
    state.force_n = std::copysign(law.coefficient * normal_force_n, trial);
    const double anchor_before = state.anchor_m;
    state.anchor_m = slip_m + state.force_n / law.tangential_stiffness_n_per_m;
    state.slid_work_j = -state.force_n * (state.anchor_m - anchor_before);
  }
  return state.force_n;
}

// The slip rate (m/s) at or below which code_aster's DIS_CHOC does not let a zone keep sliding
// (ftang's 1.d-6 on the tangential speed).
inline constexpr double kCodeAsterSlidingSpeedMS = 1e-6;

// code_aster's convention (DIS_CHOC's ftang, one tangential direction): a sliding zone keeps
// sliding, F = -mu N sign(s'), while its slip rate keeps its sign (s' s'_before >= 0) and
// exceeds kCodeAsterSlidingSpeedMS; the anchor then sits where the spring holds F. Otherwise
// (a reversal, a slow slip, or a zone that stuck) it sticks from the latest sliding force:
// F = OLDFT - k_t (s - OLDXLO) - c_t s', i.e. -k_t (s - s0) - c_t s'. A sticking force
// beyond mu_s N makes it slide at once under -mu N sign(s') (0 when |s'| is within the machine
// epsilon, as ftang's r8prem), the anchor reset.
// The slider's work is the structure's work -F (s - s_before) less the change of the spring's
// energy, exactly, since the force may reverse in one step.
inline double CodeAsterFrictionForce(const FrictionLaw& law, double normal_force_n, double slip_m,
                                     double slip_rate_m_s, FrictionState& state) {
  const double k_t = law.tangential_stiffness_n_per_m;
  const double stretch_before = state.slip_m - state.anchor_m;
  const double energy_before =
      std::isfinite(stretch_before) ? 0.5 * k_t * stretch_before * stretch_before : 0.0;
  const bool keeps_sliding = state.sliding && slip_rate_m_s * state.slip_rate_m_s >= 0.0 &&
                             std::abs(slip_rate_m_s) > kCodeAsterSlidingSpeedMS;
  bool slides = keeps_sliding;
  if (!keeps_sliding) {
    state.force_n = state.slide_force_n - k_t * (slip_m - state.slide_slip_m) -
                    law.tangential_damping_n_s_per_m * slip_rate_m_s;
    slides = std::abs(state.force_n) > law.static_coefficient * normal_force_n;
  }
  if (slides) {
    state.force_n = std::abs(slip_rate_m_s) <= std::numeric_limits<double>::epsilon()
                        ? 0.0
                        : -std::copysign(law.coefficient * normal_force_n, slip_rate_m_s);
    state.slide_force_n = state.force_n;
    state.slide_slip_m = slip_m;
    state.anchor_m = slip_m + state.force_n / k_t;
    const double energy = 0.5 * state.force_n * state.force_n / k_t;
    state.slid_work_j = -state.force_n * (slip_m - state.slip_m) - (energy - energy_before);
  } else {
    state.slid_work_j = 0.0;
  }
  state.sliding = slides;
  state.slip_m = slip_m;
  state.slip_rate_m_s = slip_rate_m_s;
  return state.force_n;
}

// The tangential force on side a along the tangent (N) at slip s (m) and slip rate s' (m/s)
// under the normal force N >= 0, the state updated, in the law's convention.
inline double FrictionForce(const FrictionLaw& law, double normal_force_n, double slip_m,
                            double slip_rate_m_s, FrictionState& state) {
  if (law.convention == FrictionConvention::kCodeAster) {
    return CodeAsterFrictionForce(law, normal_force_n, slip_m, slip_rate_m_s, state);
  }
  return ReturnMappingFrictionForce(law, normal_force_n, slip_m, slip_rate_m_s, state);
}

// The energy in the tangential spring at slip s (J).
inline double FrictionEnergy(const FrictionLaw& law, const FrictionState& state, double slip_m) {
  const double stretch = slip_m - state.anchor_m;
  return 0.5 * law.tangential_stiffness_n_per_m * stretch * stretch;
}

// The power friction dissipates over an update of dt_s at slip rate s' (W): the slider's work
// over the step, and while sticking the damper's c_t s'^2.
inline double FrictionDissipatedPower(const FrictionLaw& law, const FrictionState& state,
                                      double dt_s, double slip_rate_m_s) {
  const double damper =
      state.sliding ? 0.0 : law.tangential_damping_n_s_per_m * slip_rate_m_s * slip_rate_m_s;
  return state.slid_work_j / dt_s + damper;
}

// A contact's laws: the normal one, and friction when the zone declares it.
struct ContactLaw {
  NormalLaw normal;
  std::optional<FrictionLaw> friction;
};

}  // namespace shockmap
