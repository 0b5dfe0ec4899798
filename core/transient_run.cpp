#include "core/transient_run.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "core/cpu_timer.h"
#include "core/fused_sums.h"
#include "core/impact_tracker.h"
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
  const SecondOrderSystem& system;
  const TransientOptions& options;
  TransientResult& result;

  // `records`: how many records a run to the end takes; the histories hold that much from the
  // start, so that recording never moves them.
  void Start(double dt_record, std::size_t records) {
    auto init = [&](std::vector<UniformSignal>& v, std::size_t n) {
      v.assign(n, UniformSignal{0.0, dt_record, {}});
      for (auto& s : v) s.values.reserve(records);
    };
    init(result.displacement_m, options.observed_rows.size());
    init(result.velocity_m_s, options.record_velocity ? options.observed_rows.size() : 0);
    if (options.record_contact_forces) {
      init(result.contact_force_n, options.recorded_contacts.empty()
                                       ? system.LastContactForces().size()
                                       : options.recorded_contacts.size());
    }
    if (options.record_energy) {
      for (auto* s : {&result.energy.kinetic_j, &result.energy.strain_j, &result.energy.contact_j,
                      &result.energy.dissipated_j, &result.energy.external_work_j}) {
        *s = UniformSignal{0.0, dt_record, {}};
        s->values.reserve(records);
      }
    }
  }

  void Record(const Eigen::VectorXd& x, const Eigen::VectorXd& v, double dissipated_j,
              double work_j) {
    for (std::size_t i = 0; i < options.observed_rows.size(); ++i) {
      if (options.record_velocity) {
        const auto [displacement, velocity] = DotBoth(options.observed_rows[i], x, v);
        result.displacement_m[i].values.push_back(displacement);
        result.velocity_m_s[i].values.push_back(velocity);
      } else {
        result.displacement_m[i].values.push_back(options.observed_rows[i].dot(x));
      }
    }
    if (options.record_contact_forces) {
      const auto forces = system.LastContactForces();
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
    if (options.record_energy) {
      const Energies e = system.EnergyAt(x, v);
      result.energy.kinetic_j.values.push_back(e.kinetic_j);
      result.energy.strain_j.values.push_back(e.strain_j);
      result.energy.contact_j.values.push_back(e.contact_j);
      result.energy.dissipated_j.values.push_back(dissipated_j);
      result.energy.external_work_j.values.push_back(work_j);
    }
  }
};

}  // namespace

TransientResult RunTransient(SecondOrderSystem& system, NewmarkParameters scheme,
                             const Eigen::VectorXd& x0, const Eigen::VectorXd& v0,
                             const TransientOptions& options) {
  const CpuTimer timer;
  TransientResult result;
  RunSummary& summary = result.summary;
  summary.dt_requested_s = options.dt_s;
  summary.steps_requested = std::max<std::int64_t>(
      1, static_cast<std::int64_t>(std::ceil(options.end_time_s / options.dt_s - 1e-9)));
  summary.dt_used_s = options.end_time_s / static_cast<double>(summary.steps_requested);
  const double dt = summary.dt_used_s;

  Recorder recorder{system, options, result};
  recorder.Start(dt * options.record_stride,
                 static_cast<std::size_t>(summary.steps_requested / options.record_stride) + 1);
  std::optional<ImpactTracker> impacts;
  auto finish = [&](RunStatus status, std::string message) {
    if (impacts && summary.steps_taken > 0) {
      result.impact_statistics = impacts->Finish(summary.steps_taken);
    }
    summary.status = status;
    summary.message = std::move(message);
    summary.wall_s = timer.WallSeconds();
    summary.cpu_s = timer.CpuSeconds();
    return std::move(result);
  };

  NewmarkIntegrator integrator(scheme, system);
  if (!integrator.Init(x0, v0)) {
    return finish(RunStatus::kFailed, "initial acceleration: the system solve failed");
  }
  const bool dissipates = system.Dissipates();
  double dissipated = 0.0;
  double power_before = dissipates ? system.DissipatedPower(x0, v0) : 0.0;
  // Work of the external loads, and the total of its magnitude: the scale energy is judged
  // against when loads feed it (a base shock starts from rest).
  const bool loaded = system.HasExternalLoads();
  double work = 0.0, work_magnitude = 0.0;
  double load_power_before = loaded ? system.ExternalPower(0.0, v0) : 0.0;
  summary.initial_energy_j = system.EnergyAt(x0, v0).Total();
  recorder.Record(integrator.X(), integrator.V(), 0.0, 0.0);
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
      return finish(RunStatus::kFailed, msg.str());
    }
    summary.steps_taken = n;
    if (options.track_max_contact_force) {
      const auto forces = system.LastContactForces();
      for (std::size_t c = 0; c < forces.size(); ++c) {
        result.max_contact_force_n[c] = std::max(result.max_contact_force_n[c], forces[c]);
      }
    }
    if (impacts) impacts->Step(integrator.V());
    if (dissipates) {
      const double power_now = system.DissipatedPower(integrator.X(), integrator.V());
      dissipated += 0.5 * dt * (power_before + power_now);
      power_before = power_now;
    }
    if (loaded) {
      const double power_now = system.ExternalPower(integrator.T(), integrator.V());
      work += 0.5 * dt * (load_power_before + power_now);
      work_magnitude += 0.5 * dt * (std::abs(load_power_before) + std::abs(power_now));
      load_power_before = power_now;
    }
    if (--to_record == 0) {
      to_record = options.record_stride;
      recorder.Record(integrator.X(), integrator.V(), dissipated, work);
    }
    if (--to_check == 0 || n == summary.steps_requested) {
      to_check = options.divergence_check_stride;
      const double total = system.EnergyAt(integrator.X(), integrator.V()).Total() + dissipated;
      if (!std::isfinite(total) || !integrator.X().allFinite()) {
        std::ostringstream msg;
        msg << "non-finite state at step " << n << " (t = " << n * dt << " s)";
        return finish(RunStatus::kDiverged, msg.str());
      }
      const double scale = summary.initial_energy_j + work_magnitude;
      if (scale > 0.0) {
        const double ratio = total / scale;
        summary.max_energy_ratio = std::max(summary.max_energy_ratio, ratio);
        if (ratio > options.energy_growth_limit) {
          std::ostringstream msg;
          msg << "energy grew to " << ratio << " times its initial value at step " << n
              << " (t = " << n * dt << " s), limit " << options.energy_growth_limit;
          return finish(RunStatus::kDiverged, msg.str());
        }
      }
      if (options.on_progress) options.on_progress(integrator.T());
    }
  }
  if (!dissipates && summary.max_energy_ratio > options.unstable_energy_ratio) {
    std::ostringstream msg;
    msg << "undamped, energy grew to " << summary.max_energy_ratio
        << " times its initial value (unstable above " << options.unstable_energy_ratio << ")";
    return finish(RunStatus::kUnstable, msg.str());
  }
  return finish(RunStatus::kOk, "");
}

}  // namespace shockmap
