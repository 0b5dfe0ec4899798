#include "reference/reference_solver.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "core/input_error.h"

#include "core/cpu_timer.h"
#include "core/validity.h"
#include "reference/rank_one_update.h"
#include "reference/rotating_modal_sum.h"
#include "reference/tip_modes.h"

namespace shockmap {

bool ReferenceOptions::IsValid(std::string* error) const {
  return RequireAtLeast("r_fref", r_fref, 1.0, error) &&
         RequirePositive("end_time_s", end_time_s, error) &&
         RequireAtLeast("crossing_samples_per_period", crossing_samples_per_period, 4, error) &&
         RequireAtLeast("max_transitions", max_transitions, 1, error) &&
         RequireNonNegative("target_error", target_error, error);
}

// One linear configuration in its own modal coordinates: free (the clamped-free modes) or on
// the spring (the eigenvectors of the free modes' stiffness plus the spring in series with the
// residual flexibility), the tip as a weighted sum of them about a static offset (nonzero only
// on the spring with a nonzero gap).
struct ReferenceSolution::Configuration {
  Eigen::VectorXd omega_d;
  Eigen::VectorXd tip;      // u(L) per unit modal coordinate (m).
  double half_alpha = 0.0;  // alpha / 2 (1/s)
  double tip_offset_m = 0.0;

  int NumModes() const { return static_cast<int>(omega_d.size()); }

  // Tip deflection tau after the start of phase p.
  double Tip(const ReferencePhase& p, double tau) const {
    double u = 0.0;
    for (int i = 0; i < omega_d.size(); ++i) {
      const double w = omega_d[i] * tau;
      u += tip[i] * (p.a[i] * std::cos(w) + p.b[i] * std::sin(w));
    }
    return tip_offset_m + std::exp(-half_alpha * tau) * u;
  }

  // The integral of the tip deflection over [0, tau] of phase p: each term
  // Re((a_i - j b_i) (e^{z_i tau} - 1) / z_i), z_i = -alpha / 2 + j omega_d,i.
  double TipIntegral(const ReferencePhase& p, double tau) const {
    double sum = 0.0;
    for (int i = 0; i < omega_d.size(); ++i) {
      const std::complex<double> z(-half_alpha, omega_d[i]);
      const std::complex<double> weight(p.a[i], -p.b[i]);
      sum += tip[i] * std::real(weight * (std::exp(z * tau) - 1.0) / z);
    }
    return tip_offset_m * tau + sum;
  }

  // A bound on |du(L)/dtau| over the whole phase p: sum_i |tip_i| |a_i - j b_i| (omega_d,i +
  // alpha / 2), since every term's amplitude only decays.
  double TipSpeedBound(const ReferencePhase& p) const {
    const Eigen::ArrayXd amplitude = (p.a.array().square() + p.b.array().square()).sqrt();
    return (tip.array().abs() * amplitude * (omega_d.array() + half_alpha)).sum();
  }

  // Modal displacements and velocities tau after the start of phase p.
  void State(const ReferencePhase& p, double tau, Eigen::VectorXd& q, Eigen::VectorXd& qd) const {
    const double decay = std::exp(-half_alpha * tau);
    const Eigen::ArrayXd w = omega_d.array() * tau;
    const Eigen::ArrayXd c = w.cos(), s = w.sin();
    q = (decay * (p.a.array() * c + p.b.array() * s)).matrix();
    qd = (decay * omega_d.array() * (p.b.array() * c - p.a.array() * s)).matrix() - half_alpha * q;
  }

  // Coefficients of a phase starting from modal state (q, qd).
  void StartPhase(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, ReferencePhase& p) const {
    p.a = q;
    p.b = ((qd + half_alpha * q).array() / omega_d.array()).matrix();
  }
};

ReferenceSolution::ReferenceSolution(const CantileverImpact& problem,
                                     std::vector<ReferencePhase> phases,
                                     std::shared_ptr<const Configuration> free,
                                     std::shared_ptr<const Configuration> contact,
                                     ReferenceSummary summary)
    : gap_m_(problem.gap_m),
      stiffness_n_per_m_(problem.SpringStiffness()),
      phases_(std::move(phases)),
      free_(std::move(free)),
      contact_(std::move(contact)),
      summary_(summary) {}

const ReferencePhase& ReferenceSolution::PhaseAt(double t_s) const {
  auto it = std::upper_bound(phases_.begin(), phases_.end(), t_s,
                             [](double t, const ReferencePhase& p) { return t < p.start_s; });
  return it == phases_.begin() ? phases_.front() : *std::prev(it);
}

const ReferenceSolution::Configuration& ReferenceSolution::ConfigurationOf(
    const ReferencePhase& p) const {
  return p.in_contact ? *contact_ : *free_;
}

double ReferenceSolution::PhaseEnergy(std::size_t index) const {
  const ReferencePhase& p = phases_.at(index);
  const Eigen::ArrayXd w2 = ConfigurationOf(p).omega_d.array().square();
  return 0.5 * (w2 * (p.a.array().square() + p.b.array().square())).sum();
}

std::vector<ReferenceContact> ReferenceSolution::Contacts(double end_s) const {
  std::vector<ReferenceContact> contacts;
  for (std::size_t j = 0; j < phases_.size() && phases_[j].start_s < end_s; ++j) {
    const ReferencePhase& p = phases_[j];
    if (!p.in_contact) continue;
    const double end = j + 1 < phases_.size() ? std::min(phases_[j + 1].start_s, end_s) : end_s;
    const double duration = end - p.start_s;
    const double impulse =
        stiffness_n_per_m_ * (gap_m_ * duration - contact_->TipIntegral(p, duration));
    contacts.push_back({p.start_s, end, impulse});
  }
  return contacts;
}

double ReferenceSolution::TipDisplacement(double t_s) const {
  const ReferencePhase& p = PhaseAt(t_s);
  return ConfigurationOf(p).Tip(p, t_s - p.start_s);
}

double ReferenceSolution::ContactForce(double t_s) const {
  const ReferencePhase& p = PhaseAt(t_s);
  if (!p.in_contact) return 0.0;
  return std::max(0.0, stiffness_n_per_m_ * (gap_m_ - contact_->Tip(p, t_s - p.start_s)));
}

void ReferenceSolution::Sample(double dt_s, double end_s, UniformSignal& tip,
                               UniformSignal* force) const {
  tip = {0.0, dt_s, {}};
  const auto n = static_cast<std::size_t>(std::floor(end_s / dt_s + 1e-9)) + 1;
  tip.values.resize(n);
  if (force != nullptr) *force = {0.0, dt_s, std::vector<double>(n, 0.0)};
  const RotatingModalSum free_template(free_->omega_d, free_->half_alpha, dt_s);
  const RotatingModalSum contact_template(contact_->omega_d, contact_->half_alpha, dt_s);
  RotatingModalSum free_sum = free_template, contact_sum = contact_template;
  std::size_t i = 0;
  for (std::size_t j = 0; j < phases_.size() && i < n; ++j) {
    // Sample i belongs to the last phase starting at or before it, as in PhaseAt.
    const double next_start =
        j + 1 < phases_.size() ? phases_[j + 1].start_s : std::numeric_limits<double>::infinity();
    std::size_t end = i;
    while (end < n && tip.TimeAt(end) < next_start) ++end;
    if (end == i) continue;
    const ReferencePhase& p = phases_[j];
    const Configuration& c = ConfigurationOf(p);
    RotatingModalSum& sum = p.in_contact ? contact_sum : free_sum;
    sum.Start(c.tip.cwiseProduct(p.a), c.tip.cwiseProduct(p.b), tip.TimeAt(i) - p.start_s);
    sum.NextInto(tip.values.data() + i, static_cast<long>(end - i));
    for (; i < end; ++i) {
      const double u = c.tip_offset_m + tip.values[i];
      tip.values[i] = u;
      if (force != nullptr && p.in_contact) {
        force->values[i] = std::max(0.0, stiffness_n_per_m_ * (gap_m_ - u));
      }
    }
  }
}

UniformSignal ReferenceSolution::SampleTipDisplacement(double dt_s, double end_s) const {
  UniformSignal tip;
  Sample(dt_s, end_s, tip, nullptr);
  return tip;
}

ReferenceHistories ReferenceSolution::SampleHistories(double dt_s, double end_s) const {
  ReferenceHistories h;
  Sample(dt_s, end_s, h.tip_m, &h.force_n);
  return h;
}

namespace {

using Configuration = ReferenceSolution::Configuration;

// Damped frequencies of mass-proportional damping C = alpha M, the same in every basis.
Eigen::VectorXd DampedFrequencies(const CantileverImpact& problem, const Eigen::VectorXd& omega) {
  const double half_alpha = 0.5 * problem.mass_damping_per_s;
  Eigen::VectorXd omega_d(omega.size());
  for (int i = 0; i < omega.size(); ++i) {
    if (half_alpha >= omega[i]) {
      std::ostringstream msg;
      msg << "mass_damping_per_s = " << problem.mass_damping_per_s << ": overdamps mode " << i + 1
          << " (omega = " << omega[i] << " rad/s); the reference needs alpha / 2 < omega_1";
      throw InputError(msg.str());
    }
    omega_d[i] = std::sqrt(omega[i] * omega[i] - half_alpha * half_alpha);
  }
  return omega_d;
}

// The two configurations over the clamped-free modes below f_ref (docs/physics.md §2) and the
// changes of coordinates between them.
struct ReferenceModel {
  std::shared_ptr<Configuration> free, contact;
  Eigen::MatrixXd to_contact;         // Z^T: free modal coordinates -> contact ones.
  Eigen::MatrixXd to_free;            // Z
  Eigen::VectorXd static_free;        // q*: the static state on the spring, free coordinates
  Eigen::VectorXd static_contact;     // Z^T q*
  double residual_flexibility = 0.0;  // of the modes above f_ref at the tip (m / N)
};

// On the spring, u(L) = t^T q + R F with F = k_s (g - u(L)) the spring's force and R the
// residual flexibility: the spring acts on the modes as k_eff = k_s / (1 + k_s R) on t^T q.
// Its modes are those of diag(omega^2) + k_eff t t^T (a rank-one update), and the tip in them is
// u(L) = (t^T q + k_s R g) / (1 + k_s R).
ReferenceModel MakeReferenceModel(const CantileverImpact& problem, double f_ref_hz) {
  const TipModes modes = ClampedFreeTipModes(problem.beam, f_ref_hz);
  const double k_s = problem.SpringStiffness();
  const double r = modes.residual_flexibility_m_per_n;
  const double k_eff = k_s / (1.0 + k_s * r);
  const RankOneEigen spring =
      EigenOfRankOneUpdate(modes.omega_rad_s.array().square().matrix(), modes.tip, k_eff);
  ReferenceModel m;
  m.residual_flexibility = r;
  m.free = std::make_shared<Configuration>();
  m.free->half_alpha = 0.5 * problem.mass_damping_per_s;
  m.free->omega_d = DampedFrequencies(problem, modes.omega_rad_s);
  m.free->tip = modes.tip;
  m.contact = std::make_shared<Configuration>();
  m.contact->half_alpha = m.free->half_alpha;
  m.contact->omega_d = DampedFrequencies(problem, spring.values.cwiseSqrt());
  const Eigen::VectorXd tip_contact = spring.vectors.transpose() * modes.tip;
  m.contact->tip = tip_contact / (1.0 + k_s * r);
  m.to_contact = spring.vectors.transpose();
  m.to_free = spring.vectors;
  // q* = k_eff g (D + k_eff t t^T)^-1 t, the spring's static state with gap g.
  m.static_contact = (k_eff * problem.gap_m * tip_contact.array() / spring.values.array()).matrix();
  m.static_free = spring.vectors * m.static_contact;
  m.contact->tip_offset_m =
      (modes.tip.dot(m.static_free) + k_s * r * problem.gap_m) / (1.0 + k_s * r);
  return m;
}

// The tip's walk over tau = k step, k >= 1, of phase p (RotatingModalSum).
class TipWalk {
 public:
  TipWalk(const Configuration& c, double step)
      : c_(c), sum_(c.omega_d, c.half_alpha, step), step_(step) {}
  void Start(const ReferencePhase& p) {
    sum_.Start(c_.tip.cwiseProduct(p.a), c_.tip.cwiseProduct(p.b), step_);
  }
  double Next() { return c_.tip_offset_m + sum_.Next(); }
  void Skip(long samples) { sum_.Skip(samples); }

 private:
  const Configuration& c_;
  RotatingModalSum sum_;
  double step_;
};

// Brent's root of s in [lo, hi], returning the end of the final bracket on hi's side.
template <typename F>
double RefineCrossing(const F& s, double lo, double hi) {
  struct Ctx {
    const F* f;
  } ctx{&s};
  gsl_function fn;
  fn.function = [](double t, void* x) { return (*static_cast<Ctx*>(x)->f)(t); };
  fn.params = &ctx;
  std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), gsl_root_fsolver_free);
  gsl_root_fsolver_set(solver.get(), &fn, lo, hi);
  for (int iter = 0; iter < 200; ++iter) {
    gsl_root_fsolver_iterate(solver.get());
    lo = gsl_root_fsolver_x_lower(solver.get());
    hi = gsl_root_fsolver_x_upper(solver.get());
    if (gsl_root_test_interval(lo, hi, 1e-15, 1e-14) == GSL_SUCCESS) break;
  }
  return hi;
}

// A skip re-anchors the walk (a sine and a cosine per mode, the cost of some tens of rotations):
// it is taken only over at least this many samples.
constexpr long kShortestSkip = 64;

// First tau in (0, tau_max] where the tip leaves the phase's side of the gap, or nullopt.
// The tip is sampled at tau = k step (by `walk`, step = shortest period / samples per period)
// and at tau_max; a sign change is refined by Brent on the exact sum. Samples are skipped where
// no crossing can lie: from a sample at distance |s| inside, the tip cannot reach the gap within
// |s| / V, V = TipSpeedBound (docs/physics.md §2). A phase that starts inside is watched from
// its first instant (step / 1000), so that a re-contact shorter than one sample right after a
// transition is bracketed too. A phase that starts on the wrong side (the tip a hair off the
// gap at a transition) is watched from the first sample inside; if none comes within one
// shortest period the phase is a graze and ends at once (tau = 0).
std::optional<double> FindExit(const Configuration& c, TipWalk& walk, const ReferencePhase& p,
                               double gap, double step, double tau_max) {
  auto s = [&](double tau) { return c.Tip(p, tau) - gap; };
  auto inside = [&](double v) { return p.in_contact ? v < 0.0 : v > 0.0; };
  auto outside = [&](double v) { return p.in_contact ? v > 0.0 : v < 0.0; };
  const double grace = 16.0 * step;
  const double first = std::min(1e-3 * step, tau_max);
  const double reach_per_step = c.TipSpeedBound(p) * step;
  const long last_sample = static_cast<long>(tau_max / step);
  bool seen_inside = inside(s(first));
  double prev = seen_inside ? first : 0.0;
  walk.Start(p);
  for (long k = 1;; ++k) {
    const double tau_k = static_cast<double>(k) * step;
    const double tau = std::min(tau_k, tau_max);
    const double v = tau_k < tau_max ? walk.Next() - gap : s(tau);
    if (!seen_inside) {
      if (inside(v)) {
        seen_inside = true;
      } else if (tau >= grace) {
        return 0.0;
      }
    } else if (outside(v)) {
      return RefineCrossing(s, prev, tau);  // The outside end: the next phase starts across.
    }
    prev = tau;
    if (tau >= tau_max) return std::nullopt;
    // Samples k + 1 .. k + skip lie strictly inside: the tip moves less than |v| by k + skip + 1.
    const long skip =
        std::min(static_cast<long>(std::abs(v) / reach_per_step) - 1, last_sample - k - 1);
    if (seen_inside && inside(v) && skip >= kShortestSkip) {
      walk.Skip(skip);
      k += skip;
      prev = static_cast<double>(k) * step;
    }
  }
}

}  // namespace

ReferenceSolution SolveReference(const CantileverImpact& problem, const ReferenceOptions& options) {
  if (problem.contact_damping_n_s_per_m != 0.0) {
    std::ostringstream msg;
    msg << "contact_damping_n_s_per_m = " << problem.contact_damping_n_s_per_m
        << ": the reference represents only zero or mass-proportional damping (the same "
           "operator with and without the spring); use 0";
    throw InputError(msg.str());
  }
  gsl_set_error_handler_off();
  const CpuTimer timer;
  const ReferenceModel model = MakeReferenceModel(problem, options.r_fref * problem.F1Hz());
  const auto& free = model.free;
  const auto& contact = model.contact;

  ReferenceSummary summary;
  summary.n_modes_free = free->NumModes();
  summary.n_modes_contact = contact->NumModes();
  summary.residual_flexibility_m_per_n = model.residual_flexibility;
  const double omega_max = std::max(free->omega_d.maxCoeff(), contact->omega_d.maxCoeff());
  summary.shortest_period_s = 2.0 * std::numbers::pi / omega_max;
  const double step = summary.shortest_period_s / options.crossing_samples_per_period;

  // Released at rest from the first clamped-free mode, tip at initial_tip_m.
  Eigen::VectorXd q = Eigen::VectorXd::Zero(free->NumModes());
  Eigen::VectorXd qd = Eigen::VectorXd::Zero(free->NumModes());
  q[0] = problem.initial_tip_m / free->tip[0];
  std::vector<ReferencePhase> phases(1);
  phases[0].start_s = 0.0;
  phases[0].in_contact = problem.initial_tip_m < problem.gap_m;
  if (phases[0].in_contact) {
    contact->StartPhase(model.to_contact * q - model.static_contact, model.to_contact * qd,
                        phases[0]);
  } else {
    free->StartPhase(q, qd, phases[0]);
  }

  TipWalk free_walk(*free, step), contact_walk(*contact, step);
  while (true) {
    const ReferencePhase& p = phases.back();
    const Configuration& c = p.in_contact ? *contact : *free;
    TipWalk& walk = p.in_contact ? contact_walk : free_walk;
    const auto exit = FindExit(c, walk, p, problem.gap_m, step, options.end_time_s - p.start_s);
    if (!exit) break;
    if (summary.n_transitions >= options.max_transitions) {
      std::ostringstream msg;
      msg << "max_transitions = " << options.max_transitions
          << " reached at t = " << p.start_s + *exit
          << " s before end_time_s = " << options.end_time_s;
      throw std::runtime_error(msg.str());
    }
    c.State(p, *exit, q, qd);
    ReferencePhase next;
    next.start_s = p.start_s + *exit;
    next.in_contact = !p.in_contact;
    if (next.in_contact) {
      contact->StartPhase(model.to_contact * q - model.static_contact, model.to_contact * qd, next);
    } else {
      free->StartPhase(model.to_free * q + model.static_free, model.to_free * qd, next);
    }
    phases.push_back(std::move(next));
    ++summary.n_transitions;
  }
  summary.wall_s = timer.WallSeconds();
  return ReferenceSolution(problem, std::move(phases), free, contact, summary);
}

}  // namespace shockmap
