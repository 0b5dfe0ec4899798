#pragma once
// Impact statistics of one contact zone over a run, in the vocabulary of code_aster's
// POST_DYNA_MODA_T (docs/physics.md §6), accumulated step by step: no history is kept. Two
// conventions: shockmap's own (ImpactAccumulator, below), and code_aster's counting on the
// samples (core/code_aster_impact_counter.h).

#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace shockmap {

// How the statistics are defined (docs/physics.md §6, the two side by side).
enum class ImpactConvention {
  // Contacts' ends found between steps, integrals of the force's line, impacts counted when
  // they start, real-valued rates and fractions.
  kShockmap,
  // POST_DYNA_MODA_T's counting routines on the samples: impacts counted when they end in the
  // window, integer rates and percentages, force statistics over the samples above the
  // threshold only.
  kCodeAster,
};
std::string ToString(ImpactConvention convention);  // "shockmap", "code_aster"

// How contacts are told apart and grouped into impacts (POST_DYNA_MODA_T's SEUIL_FORCE and
// DUREE_REPOS), in which convention, over which window of the run (INST_INIT, INST_FIN).
struct ImpactCounting {
  // Contact means force strictly above this (N). 0: a compression-only spring carries exactly
  // zero force when open, so every positive force is contact.
  double force_threshold_n = 0.0;
  // Contacts separated by less than this (s) are one impact, the later ones its rebounds. 0
  // counts every contact as an impact (code_aster's default). A fraction of the zone's slowest
  // period, e.g. 0.1 T1.
  double rest_duration_s = 0.0;
  ImpactConvention convention = ImpactConvention::kShockmap;
  // The window of the run the statistics cover (s); the end may lie beyond the run's. Each
  // convention snaps it to steps its own way (docs/physics.md §6.1).
  double window_start_s = 0.0;
  double window_end_s = std::numeric_limits<double>::infinity();

  // Threshold and rest duration finite and >= 0; window start finite, >= 0 and before its end.
  bool IsValid(std::string* error) const;
};

// One impact of a zone (a row of code_aster's IMPACT table).
struct ImpactRecord {
  double start_s = 0.0;           // Its first contact's start.
  double duration_s = 0.0;        // To its last contact's end.
  double peak_force_n = 0.0;      // The largest force at a step.
  double peak_time_s = 0.0;       // When.
  double impulse_n_s = 0.0;       // Integral of the force over its contacts.
  double impact_speed_m_s = 0.0;  // The penetration rate as the zone closed (NaN: not known).
  int contacts = 0;               // Its contacts: 1 + its rebounds.
  bool truncated = false;         // Cut by the window's start or end.
};

// One zone at one step, as the statistics read it.
struct ZoneSample {
  double force_n = 0.0;  // Normal force (N, >= 0).
  // |t . (v_a - v_b)| (m/s); NaN when the model does not carry the tangential motion.
  double sliding_speed_m_s = 0.0;
  double tangential_force_n = 0.0;  // |F_t| (N), with friction.
  bool sticks = false;              // Friction holds the two sides: they do not slide.
  // The penetration rate (m/s, > 0 closing), for zones whose impacts are listed.
  double penetration_rate_m_s = std::numeric_limits<double>::quiet_NaN();
};

// Over a window of duration T (docs/physics.md §6). A contact is a maximal interval with the
// force above the threshold; an impact is a group of contacts each starting less than
// rest_duration_s after the previous one ended. Each field in shockmap's convention; in
// code_aster's, the definition docs/physics.md §6.2 sets beside it.
struct ImpactStatistics {
  ImpactConvention convention = ImpactConvention::kShockmap;
  double window_start_s = 0.0, window_end_s = 0.0;  // As snapped to steps.
  int impacts = 0;                                  // Impacts started during the window.
  double impacts_per_s = 0.0;                       // impacts / T.
  double rebounds_per_impact = 0.0;        // (contacts - impacts) / impacts; 0 without impacts.
  double mean_impact_duration_s = 0.0;     // First contact's start to last contact's end.
  double longest_impact_duration_s = 0.0;  // Of the impacts above.
  double mean_contact_duration_s = 0.0;    // Time in contact / contacts.
  double contact_time_fraction = 0.0;      // Time in contact / T, in [0, 1].
  double mean_force_n = 0.0;               // Impulse / T: over the whole time.
  double mean_force_in_contact_n = 0.0;    // Integral of F over contact / time in contact.
  double rms_force_n = 0.0;                // sqrt(integral of F^2 / T).
  double rms_force_in_contact_n = 0.0;     // sqrt(integral of F^2 over contact / its time).
  double max_force_n = 0.0;                // Largest force at a step.
  double impulse_n_s = 0.0;                // Integral of F over the window.
  // Archard's wear work rate (POST_USURE's "puissance d'usure"): the time average of the normal
  // force times the tangential sliding speed at the zone (W). With friction, only the time the
  // zone slides counts (sliding_only), as code_aster skips its adherent samples. Only where the
  // model carries the tangential motion (scenes bending in both planes): otherwise
  // wear_available is false and the rate NaN.
  bool wear_available = false;
  double wear_work_rate_w = std::numeric_limits<double>::quiet_NaN();
  bool sliding_only = false;  // The zone has friction.
  // With friction: the time average of |F_t| times the sliding speed while sliding, the power
  // friction dissipates (W); NaN without friction.
  double friction_power_w = std::numeric_limits<double>::quiet_NaN();
  int contacts = 0;  // Contacts, rebounds included.
  // A contact is under way at the start or at the end of the window: the first or last impact
  // is cut by it, and its duration is only a lower bound.
  bool truncated = false;
  // One per impact, in time order, for the zones whose impacts are listed (else empty).
  std::vector<ImpactRecord> records;
};

// Streams one zone's force through a window in shockmap's convention. The force is taken
// piecewise linear between steps, except where a penalty contact opens or closes: the step's
// zero sample is the clamp (the stop never pulls), not a point of the force's line, so there the
// crossing of zero is extrapolated from the slope of the two samples inside the contact
// (clamped to the step; the step's middle when the contact has no such slope, e.g. a one-step
// contact). Interpolating to the zero sample instead would lengthen every contact by dt / 2 at
// each end. Integrals use the trapezoidal rule on the pieces (docs/physics.md §6).
class ImpactAccumulator {
 public:
  // What the accumulator is told besides the counting.
  struct Options {
    double origin_s = 0.0;  // The time of the first sample (the window's start).
    bool friction = false;  // The zone has friction: wear counts while it slides only.
    bool records = false;   // Keep one ImpactRecord per impact.
  };

  // Precondition: counting.IsValid(). The state at t = 0: its force and sliding speed.
  explicit ImpactAccumulator(ImpactCounting counting = {}, double initial_force_n = 0.0,
                             double initial_sliding_speed_m_s = 0.0);
  // The state at the window's start: its sample.
  ImpactAccumulator(ImpactCounting counting, const ZoneSample& initial, Options options);

  // The next step, dt_s after the previous one: the zone's normal force (N, >= 0) and its
  // tangential sliding speed (m/s, >= 0; NaN when the model does not carry it, which makes the
  // wear work rate unavailable).
  void Add(double force_n, double sliding_speed_m_s, double dt_s);
  // The same with the zone's whole sample: a sample that sticks slides at speed 0.
  void Add(const ZoneSample& sample, double dt_s);

  // The statistics over [0, duration_s] from the first sample (duration_s > 0: the time the
  // steps covered).
  ImpactStatistics Finish(double duration_s) const;

 private:
  // A sample of the force: time, force, sliding speed (0 while sticking), and the friction
  // force's power |F_t| times that speed.
  struct Sample {
    double t_s = 0.0, force_n = 0.0, speed_m_s = 0.0, friction_w = 0.0;
  };
  // The sample as integrated.
  Sample Integrated(double t_s, const ZoneSample& sample) const;
  bool InContact(double force_n) const { return force_n > counting_.force_threshold_n; }
  // Integrates the linear piece from a to b, with its contact part and crossings.
  void Piece(const Sample& a, const Sample& b);
  // The step that opened the contact, now that the sample after it is known (or not).
  void ResolveOpening(const Sample* next);
  void StartContact(double t_s);
  void CloseImpact();
  // A sample inside a contact: a candidate for its impact's peak.
  void Peak(const Sample& s);
  // The open impact's record, ending at end_s.
  ImpactRecord OpenRecord(double end_s, bool cut) const;
  // Finish's figures once no opening is pending.
  ImpactStatistics Statistics(double duration_s) const;

  ImpactCounting counting_;
  Options options_;
  Sample before_last_, last_;  // The two latest samples (before_last_ unset at the start).
  bool has_before_last_ = false;
  // The step [before_last_, last_] rose from a zero force: integrated once the next sample
  // gives the slope.
  bool opening_pending_ = false;
  // Integrals over the run (N s, N^2 s, J, J) and over contact (N s, N^2 s, s).
  double impulse_n_s_ = 0.0, squared_n2_s_ = 0.0, wear_work_j_ = 0.0, friction_work_j_ = 0.0;
  double contact_impulse_n_s_ = 0.0, contact_squared_n2_s_ = 0.0, contact_time_s_ = 0.0;
  double max_force_n_ = 0.0;
  bool wear_available_ = true;
  // The open impact (impacts_ > 0): its start and the end of its last finished contact.
  int impacts_ = 0, contacts_ = 0;
  bool in_contact_ = false;
  double impact_start_s_ = 0.0, last_contact_end_s_ = 0.0;
  double closed_duration_sum_s_ = 0.0, longest_closed_s_ = 0.0;
  bool started_in_contact_ = false;
  // The penetration rate when the force last rose from zero, and the open impact's record.
  double closing_rate_m_s_ = std::numeric_limits<double>::quiet_NaN();
  ImpactRecord open_;
  std::vector<ImpactRecord> records_;
};

}  // namespace shockmap
