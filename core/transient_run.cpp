#include "core/transient_run.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "core/cpu_timer.h"
#include "core/elementwise_passes.h"
#include "core/fused_sums.h"
#include "core/impact_tracker.h"
#include "core/increment_stepper.h"
#include "core/validity.h"

namespace shockmap {

bool TransientOptions::IsValid(std::string* error) const {
  if (!RequirePositive("end_time_s", end_time_s, error) || !RequirePositive("dt_s", dt_s, error) ||
      !RequireAtLeast("record_stride", record_stride, 1, error) ||
      !RequireAtLeast("divergence_check_stride", divergence_check_stride, 1, error) ||
      !RequireAtLeast("energy_growth_limit", energy_growth_limit, 1.0, error) ||
      !RequireAtLeast("unstable_energy_ratio", unstable_energy_ratio, 1.0, error)) {
    return false;
  }
  if (track_impact_statistics && !impact_counting.IsValid(error)) return false;
  const double steps = std::ceil(end_time_s / dt_s - 1e-9);
  if (steps > static_cast<double>(max_steps)) {
    if (error != nullptr) {
      std::ostringstream out;
      out << "end_time_s / dt_s = " << steps << " steps: must be <= " << max_steps;
      *error = out.str();
    }
    return false;
  }
  return true;
}

namespace {

struct Recorder {
  const TransientOptions& options;
  TransientResult& result;
  std::size_t zones = 0;  // The system's contacts, from Start.

  // `records`: how many records a run to the end takes; the histories hold that much from the
  // start, so that recording never moves them. `contacts`: the system's.
  void Start(double dt_record, std::size_t records, std::size_t contacts) {
    zones = contacts;
    auto init = [&](std::vector<UniformSignal>& v, std::size_t n) {
      v.assign(n, UniformSignal{0.0, dt_record, {}});
      for (auto& s : v) s.values.reserve(records);
    };
    init(result.displacement_m, options.observed_rows.size());
    init(result.velocity_m_s, options.record_velocity ? options.observed_rows.size() : 0);
    if (options.record_contact_forces) {
      init(result.contact_force_n,
           options.recorded_contacts.empty() ? contacts : options.recorded_contacts.size());
    }
    if (options.record_energy) {
      for (auto* s : {&result.energy.kinetic_j, &result.energy.strain_j, &result.energy.contact_j,
                      &result.energy.dissipated_j, &result.energy.external_work_j}) {
        *s = UniformSignal{0.0, dt_record, {}};
        s->values.reserve(records);
      }
    }
  }

  // The observed rows at (x, v): row . x, and row . v when velocities are recorded.
  void RecordObserved(const Eigen::VectorXd& x, const Eigen::VectorXd& v) {
    for (std::size_t i = 0; i < options.observed_rows.size(); ++i) {
      if (options.record_velocity) {
        const auto [displacement, velocity] = DotBoth(options.observed_rows[i], x, v);
        result.displacement_m[i].values.push_back(displacement);
        result.velocity_m_s[i].values.push_back(velocity);
      } else {
        result.displacement_m[i].values.push_back(options.observed_rows[i].dot(x));
      }
    }
  }

  // The records of a block of `steps` steps, step s's observed displacements at
  // observed[s * rows + j] and zone forces at forces[s * zones + c]: steps to_record - 1,
  // then every record_stride-th. to_record counts down to the next record as a step loop
  // would, and is left so for the next block. True when the block's last step was recorded.
  bool RecordBlock(const double* observed, const double* forces, int steps, int& to_record) {
    const int stride = options.record_stride, first = to_record - 1;
    if (first >= steps) {
      to_record -= steps;
      return false;
    }
    const int rows = static_cast<int>(options.observed_rows.size());
    const int width = static_cast<int>(zones);
    for (int j = 0; j < rows; ++j) {
      AppendEvery(result.displacement_m[j].values, observed + j, rows, first, steps);
    }
    if (options.record_contact_forces) {
      for (std::size_t c = 0; c < result.contact_force_n.size(); ++c) {
        const int zone =
            options.recorded_contacts.empty() ? static_cast<int>(c) : options.recorded_contacts[c];
        AppendEvery(result.contact_force_n[c].values, forces + zone, width, first, steps);
      }
    }
    const int last = first + (steps - 1 - first) / stride * stride;
    to_record = stride - (steps - 1 - last);
    return last == steps - 1;
  }

  // row . v of every observed row, when velocities are recorded.
  void RecordVelocities(const Eigen::VectorXd& v) {
    if (!options.record_velocity) return;
    for (std::size_t i = 0; i < options.observed_rows.size(); ++i) {
      result.velocity_m_s[i].values.push_back(options.observed_rows[i].dot(v));
    }
  }

  // values[s * width] for s = first, first + record_stride, ... < steps, appended to `to`
  // (whose capacity holds them: no reallocation, no per-value check).
  void AppendEvery(std::vector<double>& to, const double* values, int width, int first,
                   int steps) const {
    const std::size_t old = to.size();
    to.resize(old + static_cast<std::size_t>((steps - 1 - first) / options.record_stride + 1));
    double* out = to.data() + old;
    for (int s = first; s < steps; s += options.record_stride) *out++ = values[s * width];
  }

  void RecordForces(std::span<const double> forces) {
    if (!options.record_contact_forces) return;
    if (options.recorded_contacts.empty()) {
      for (std::size_t c = 0; c < forces.size(); ++c) {
        result.contact_force_n[c].values.push_back(forces[c]);
      }
    } else {
      for (std::size_t c = 0; c < options.recorded_contacts.size(); ++c) {
        result.contact_force_n[c].values.push_back(forces[options.recorded_contacts[c]]);
      }
    }
  }

  // e_now() gives the energies at the recorded state; it is called only when they are recorded.
  template <typename EnergiesNow>
  void RecordEnergy(EnergiesNow e_now, double dissipated_j, double work_j) {
    if (!options.record_energy) return;
    const Energies e = e_now();
    result.energy.kinetic_j.values.push_back(e.kinetic_j);
    result.energy.strain_j.values.push_back(e.strain_j);
    result.energy.contact_j.values.push_back(e.contact_j);
    result.energy.dissipated_j.values.push_back(dissipated_j);
    result.energy.external_work_j.values.push_back(work_j);
  }
};

// What every run keeps beside its steps: the timer, the summary and the divergence checks.
class Bookkeeping {
 public:
  explicit Bookkeeping(const TransientOptions& options) : options_(options) {
    RunSummary& summary = result_.summary;
    summary.dt_requested_s = options.dt_s;
    summary.steps_requested = std::max<std::int64_t>(
        1, static_cast<std::int64_t>(std::ceil(options.end_time_s / options.dt_s - 1e-9)));
    summary.dt_used_s = options.end_time_s / static_cast<double>(summary.steps_requested);
  }

  TransientResult& Result() { return result_; }
  double Dt() const { return result_.summary.dt_used_s; }
  std::int64_t Steps() const { return result_.summary.steps_requested; }
  std::size_t Records() const {
    return static_cast<std::size_t>(Steps() / options_.record_stride) + 1;
  }
  double DtRecord() const { return Dt() * options_.record_stride; }

  // The check after step n at simulated time t_s: the total energy (dissipated work included)
  // against the initial energy plus the loads' work magnitude. False when the run diverged
  // (the summary then says how).
  bool Check(std::int64_t n, double t_s, double total, bool finite_state, double work_magnitude) {
    RunSummary& summary = result_.summary;
    if (!std::isfinite(total) || !finite_state) {
      std::ostringstream msg;
      msg << "non-finite state at step " << n << " (t = " << n * Dt() << " s)";
      return Stop(RunStatus::kDiverged, msg.str());
    }
    const double scale = summary.initial_energy_j + work_magnitude;
    if (scale > 0.0) {
      const double ratio = total / scale;
      summary.max_energy_ratio = std::max(summary.max_energy_ratio, ratio);
      if (ratio > options_.energy_growth_limit) {
        std::ostringstream msg;
        msg << "energy grew to " << ratio << " times its initial value at step " << n
            << " (t = " << n * Dt() << " s), limit " << options_.energy_growth_limit;
        return Stop(RunStatus::kDiverged, msg.str());
      }
    }
    if (options_.on_progress) options_.on_progress(t_s);
    return true;
  }

  // After the last step: an undamped run whose energy grew past the unstable ratio is
  // kUnstable, others kOk.
  void Complete(bool dissipates) {
    const RunSummary& summary = result_.summary;
    if (!dissipates && summary.max_energy_ratio > options_.unstable_energy_ratio) {
      std::ostringstream msg;
      msg << "undamped, energy grew to " << summary.max_energy_ratio
          << " times its initial value (unstable above " << options_.unstable_energy_ratio << ")";
      Stop(RunStatus::kUnstable, msg.str());
      return;
    }
    Stop(RunStatus::kOk, "");
  }

  // Ends the run with a status; false.
  bool Stop(RunStatus status, std::string message) {
    result_.summary.status = status;
    result_.summary.message = std::move(message);
    return false;
  }

  // The result, its times taken.
  TransientResult Finish() {
    result_.summary.wall_s = timer_.WallSeconds();
    result_.summary.cpu_s = timer_.CpuSeconds();
    return std::move(result_);
  }

 private:
  const CpuTimer timer_;
  const TransientOptions& options_;
  TransientResult result_;
};

// The energy balance's running integrals over the steps (trapezoidal in time, from the powers
// at each step's ends): the work dissipated, the loads' work and the total of its magnitude,
// the scale energy is judged against when loads feed it (a base shock starts from rest). Zero
// for a system that neither dissipates nor is loaded.
class EnergyLedger {
 public:
  EnergyLedger(SecondOrderSystem& system, const Eigen::VectorXd& x0, const Eigen::VectorXd& v0)
      : system_(system), active_(system.Dissipates() || system.HasExternalLoads()) {
    if (active_) before_ = system.PowersAt(0.0, x0, v0);
  }

  // After a step of dt ending at time t in state (x, v).
  void Step(double dt, double t, const Eigen::VectorXd& x, const Eigen::VectorXd& v) {
    if (!active_) return;
    const auto now = system_.PowersAt(t, x, v);
    dissipated_ += 0.5 * dt * (before_.dissipated_w + now.dissipated_w);
    work_ += 0.5 * dt * (before_.external_w + now.external_w);
    work_magnitude_ += 0.5 * dt * (std::abs(before_.external_w) + std::abs(now.external_w));
    before_ = now;
  }

  double Dissipated() const { return dissipated_; }
  double Work() const { return work_; }
  double WorkMagnitude() const { return work_magnitude_; }

 private:
  SecondOrderSystem& system_;
  const bool active_;
  SecondOrderSystem::Powers before_;
  double dissipated_ = 0.0, work_ = 0.0, work_magnitude_ = 0.0;
};

bool IsCentralDifference(NewmarkParameters scheme) {
  return scheme.beta == 0.0 && scheme.gamma == 0.5;
}

// The general run: Newmark's step on any system, every option honoured.
TransientResult RunNewmark(SecondOrderSystem& system, NewmarkParameters scheme,
                           const Eigen::VectorXd& x0, const Eigen::VectorXd& v0,
                           const TransientOptions& options, Bookkeeping& book) {
  TransientResult& result = book.Result();
  RunSummary& summary = result.summary;
  const double dt = book.Dt();
  std::optional<ImpactTracker> impacts;
  auto finish = [&] {
    if (impacts && summary.steps_taken > 0) {
      result.impact_statistics = impacts->Finish(summary.steps_taken);
    }
    return book.Finish();
  };

  Recorder recorder{options, result};
  recorder.Start(book.DtRecord(), book.Records(), system.LastContactForces().size());
  NewmarkIntegrator integrator(scheme, system);
  if (!integrator.Init(x0, v0)) {
    book.Stop(RunStatus::kFailed, "initial acceleration: the system solve failed");
    return finish();
  }
  EnergyLedger ledger(system, x0, v0);
  summary.initial_energy_j = system.EnergyAt(x0, v0).Total();
  auto record = [&] {
    recorder.RecordObserved(integrator.X(), integrator.V());
    recorder.RecordForces(system.LastContactForces());
    recorder.RecordEnergy([&] { return system.EnergyAt(integrator.X(), integrator.V()); },
                          ledger.Dissipated(), ledger.Work());
  };
  record();
  if (options.track_max_contact_force) {
    const auto forces = system.LastContactForces();
    result.max_contact_force_n.assign(forces.begin(), forces.end());
  }
  if (options.track_impact_statistics) {
    impacts.emplace(system, options.impact_counting, options.listed_impact_contacts, v0, dt);
  }

  // Steps until the next record and the next check: counted down, no division per step.
  int to_record = options.record_stride, to_check = options.divergence_check_stride;
  for (std::int64_t n = 1; n <= summary.steps_requested; ++n) {
    if (!integrator.Step(dt)) {
      summary.steps_taken = n - 1;
      std::ostringstream msg;
      msg << "step " << n << " (t = " << n * dt << " s): the system solve failed";
      book.Stop(RunStatus::kFailed, msg.str());
      return finish();
    }
    summary.steps_taken = n;
    if (options.track_max_contact_force) {
      RaiseToMaxInPlace(result.max_contact_force_n, system.LastContactForces());
    }
    if (impacts) impacts->Step(integrator.V());
    ledger.Step(dt, integrator.T(), integrator.X(), integrator.V());
    if (--to_record == 0) {
      to_record = options.record_stride;
      record();
    }
    if (--to_check == 0 || n == summary.steps_requested) {
      to_check = options.divergence_check_stride;
      const double total =
          system.EnergyAt(integrator.X(), integrator.V()).Total() + ledger.Dissipated();
      if (!book.Check(n, integrator.T(), total, integrator.X().allFinite(),
                      ledger.WorkMagnitude())) {
        return finish();
      }
    }
  }
  book.Complete(system.Dissipates());
  return finish();
}

// The run in increment form (core/increment_stepper.h), for the systems and options it takes:
// no dissipation, loads or impact statistics. Steps go by blocks between checks; a record
// needing the velocity or the energies takes blocks of one step.
TransientResult RunInIncrements(IncrementStepper& stepper, const SecondOrderSystem& system,
                                const Eigen::VectorXd& x0, const Eigen::VectorXd& v0,
                                const TransientOptions& options, Bookkeeping& book) {
  TransientResult& result = book.Result();
  RunSummary& summary = result.summary;
  const int rows = stepper.Rows(), zones = stepper.Zones();
  Recorder recorder{options, result};
  recorder.Start(book.DtRecord(), book.Records(), static_cast<std::size_t>(zones));
  stepper.Init(x0, v0);
  summary.initial_energy_j = system.EnergyAt(x0, v0).Total();
  // Records of velocities and energies need the state at each recorded step: blocks of one.
  const bool state_per_record = options.record_velocity || options.record_energy;
  auto record_state = [&] {
    recorder.RecordVelocities(stepper.V());
    recorder.RecordEnergy([&] { return system.EnergyAt(stepper.X(), stepper.V()); }, 0.0, 0.0);
  };
  std::vector<double> observed(options.observed_rows.size());
  for (int j = 0; j < rows; ++j) observed[j] = options.observed_rows[j].dot(x0);
  int to_record = 1;
  recorder.RecordBlock(observed.data(), stepper.Forces().data(), 1, to_record);
  record_state();
  if (options.track_max_contact_force) {
    result.max_contact_force_n.assign(stepper.Forces().begin(), stepper.Forces().end());
  }

  const int block = state_per_record ? 1 : options.divergence_check_stride;
  std::vector<double> forces(static_cast<std::size_t>(block * zones));
  observed.resize(static_cast<std::size_t>(block * rows));
  int to_check = options.divergence_check_stride;
  while (summary.steps_taken < summary.steps_requested) {
    const int steps = static_cast<int>(
        std::min<std::int64_t>({block, to_check, summary.steps_requested - summary.steps_taken}));
    stepper.Advance(steps, observed.data(), forces.data());
    if (options.track_max_contact_force) {
      for (int s = 0; s < steps; ++s) {
        for (int c = 0; c < zones; ++c) {
          result.max_contact_force_n[c] =
              std::max(result.max_contact_force_n[c], forces[s * zones + c]);
        }
      }
    }
    if (recorder.RecordBlock(observed.data(), forces.data(), steps, to_record) &&
        state_per_record) {
      record_state();
    }
    summary.steps_taken += steps;
    to_check -= steps;
    if (to_check == 0 || summary.steps_taken == summary.steps_requested) {
      to_check = options.divergence_check_stride;
      const Eigen::VectorXd& x = stepper.X();
      const double total = system.EnergyAt(x, stepper.V()).Total();
      if (!book.Check(summary.steps_taken, stepper.T(), total, x.allFinite(), 0.0)) {
        return book.Finish();
      }
    }
  }
  book.Complete(false);
  return book.Finish();
}

}  // namespace

TransientResult RunTransient(SecondOrderSystem& system, NewmarkParameters scheme,
                             const Eigen::VectorXd& x0, const Eigen::VectorXd& v0,
                             const TransientOptions& options) {
  Bookkeeping book(options);
  if (IsCentralDifference(scheme) && !options.track_impact_statistics) {
    if (auto stepper = IncrementStepper::For(system, book.Dt(), options.observed_rows)) {
      return RunInIncrements(*stepper, system, x0, v0, options, book);
    }
  }
  return RunNewmark(system, scheme, x0, v0, options, book);
}

}  // namespace shockmap
