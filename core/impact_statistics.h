#pragma once
// Impact statistics of one contact zone over a run, in the vocabulary of code_aster's
// POST_DYNA_MODA_T (docs/physics.md §6), accumulated step by step: no history is kept.

#include <limits>
#include <string>

namespace shockmap {

// How contacts are told apart and grouped into impacts (POST_DYNA_MODA_T's SEUIL_FORCE and
// DUREE_REPOS).
struct ImpactCounting {
  // Contact means force strictly above this (N). 0: a compression-only spring carries exactly
  // zero force when open, so every positive force is contact.
  double force_threshold_n = 0.0;
  // Contacts separated by less than this (s) are one impact, the later ones its rebounds. 0
  // counts every contact as an impact. A fraction of the zone's slowest period, e.g. 0.1 T1.
  double rest_duration_s = 0.0;

  // Both finite and >= 0.
  bool IsValid(std::string* error) const;
};

// Over a run of duration T (docs/physics.md §6). A contact is a maximal interval with the
// force above the threshold, its ends found between steps (ImpactAccumulator); an impact is a
// group of contacts each starting less than rest_duration_s after the previous one ended.
struct ImpactStatistics {
  int impacts = 0;                         // Impacts started during the run.
  double impacts_per_s = 0.0;              // impacts / T.
  double rebounds_per_impact = 0.0;        // (contacts - impacts) / impacts; 0 without impacts.
  double mean_impact_duration_s = 0.0;     // First contact's start to last contact's end.
  double longest_impact_duration_s = 0.0;  // Of the impacts above.
  double contact_time_fraction = 0.0;      // Time in contact / T, in [0, 1].
  double mean_force_n = 0.0;               // Impulse / T: over the whole time.
  double mean_force_in_contact_n = 0.0;    // Integral of F over contact / time in contact.
  double rms_force_n = 0.0;                // sqrt(integral of F^2 / T).
  double max_force_n = 0.0;                // Largest force at a step.
  double impulse_n_s = 0.0;                // Integral of F over the run.
  // Archard's wear work rate (POST_USURE's "puissance d'usure"): the time average of the normal
  // force times the tangential sliding speed at the zone (W). Only where the model carries the
  // tangential motion (scenes bending in both planes): otherwise wear_available is false and
  // the rate NaN.
  bool wear_available = false;
  double wear_work_rate_w = std::numeric_limits<double>::quiet_NaN();
  int contacts = 0;  // Contacts, rebounds included.
  // A contact is under way at the start or at the end of the run: the first or last impact
  // is cut by the run, and its duration is only a lower bound.
  bool truncated = false;
};

// Streams one zone's force through a run. The force is taken piecewise linear between steps,
// except where a penalty contact opens or closes: the step's zero sample is the clamp (the stop
// never pulls), not a point of the force's line, so there the crossing of zero is extrapolated
// from the slope of the two samples inside the contact (clamped to the step; the step's middle
// when the contact has no such slope, e.g. a one-step contact). Interpolating to the zero sample
// instead would lengthen every contact by dt / 2 at each end. Integrals use the trapezoidal rule
// on the pieces (docs/physics.md §6).
class ImpactAccumulator {
 public:
  // Precondition: counting.IsValid(). The state at t = 0: its force and sliding speed.
  explicit ImpactAccumulator(ImpactCounting counting = {}, double initial_force_n = 0.0,
                             double initial_sliding_speed_m_s = 0.0);

  // The next step, dt_s after the previous one: the zone's normal force (N, >= 0) and its
  // tangential sliding speed (m/s, >= 0; NaN when the model does not carry it, which makes the
  // wear work rate unavailable).
  void Add(double force_n, double sliding_speed_m_s, double dt_s);

  // The statistics over [0, duration_s] (duration_s > 0: the time the steps covered).
  ImpactStatistics Finish(double duration_s) const;

 private:
  // A sample of the force: time, force, sliding speed.
  struct Sample {
    double t_s = 0.0, force_n = 0.0, speed_m_s = 0.0;
  };
  bool InContact(double force_n) const { return force_n > counting_.force_threshold_n; }
  // Integrates the linear piece from a to b, with its contact part and crossings.
  void Piece(const Sample& a, const Sample& b);
  // The step that opened the contact, now that the sample after it is known (or not).
  void ResolveOpening(const Sample* next);
  void StartContact(double t_s);
  void CloseImpact();
  // Finish's figures once no opening is pending.
  ImpactStatistics Statistics(double duration_s) const;

  ImpactCounting counting_;
  Sample before_last_, last_;  // The two latest samples (before_last_ unset at the start).
  bool has_before_last_ = false;
  // The step [before_last_, last_] rose from a zero force: integrated once the next sample
  // gives the slope.
  bool opening_pending_ = false;
  // Integrals over the run (N s, N^2 s, J) and over contact (N s, s).
  double impulse_n_s_ = 0.0, squared_n2_s_ = 0.0, wear_work_j_ = 0.0;
  double contact_impulse_n_s_ = 0.0, contact_time_s_ = 0.0;
  double max_force_n_ = 0.0;
  bool wear_available_ = true;
  // The open impact (impacts_ > 0): its start and the end of its last finished contact.
  int impacts_ = 0, contacts_ = 0;
  bool in_contact_ = false;
  double impact_start_s_ = 0.0, last_contact_end_s_ = 0.0;
  double closed_duration_sum_s_ = 0.0, longest_closed_s_ = 0.0;
  bool started_in_contact_ = false;
};

}  // namespace shockmap
