#include "formats/scene_file.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

#include "core/beam_fe.h"
#include "core/fe_structure.h"
#include "core/modal_basis.h"
#include "core/scene_model.h"
#include "core/transient_run.h"
#include "formats/acceleration_csv.h"
#include "formats/json_reader.h"
#include "formats/structure_files.h"

namespace shockmap {
namespace {

using Json = nlohmann::json;

// Limits that catch units mistakes rather than physics: a scene beyond them is a typing error.
constexpr int kMaxBeams = 10000;
constexpr int kMaxZones = 1'000'000;

// What a run holds in memory per beam and per contact zone: the peak resident size of
// `shockmap simulate` on scenes/bundle_row.json grown to 2000 and 4000 pins with 1, 7 and 21
// wire heights grew by about 0.9 kB per beam and 1.1 kB per zone (8000 pins with 7 heights:
// 77 MB).
constexpr double kRunBytesPerBeam = 1.0e3;
constexpr double kRunBytesPerZone = 1.1e3;

// "a scene may hold at most 10000 beams; 10001 beams [and Z contact zones] would take
// about M GB of memory to run": the limit on beams, with the estimate for `beams`.
std::string BeamLimit(double beams, double zones) {
  const double bytes = beams * kRunBytesPerBeam + zones * kRunBytesPerZone;
  return fmt::format(
      "a scene may hold at most {} beams; {:.0f} beams{} would take about {:.2g} GB "
      "of memory to run",
      kMaxBeams, beams, zones > 0 ? fmt::format(" and {:.0f} contact zones", zones) : "",
      bytes / 1e9);
}

// A wire height as it names its zones: rounded to the micrometre, in the shortest digits that
// read back as that value (0.9144, not the 0.9144000000000001 a linspace computes).
std::string HeightLabel(double height_m) {
  std::array<char, 32> digits{};
  const double rounded = std::round(height_m * 1e6) / 1e6;
  const auto end = std::to_chars(digits.data(), digits.data() + digits.size(), rounded).ptr;
  return {digits.data(), end};
}

// Beyond the eigenproblem budget of core/modal_basis.h when the distinct beam models of `beams`
// are solved (once each: one eigensolution gives the first elastic frequency and the basis),
// the estimate; else "".
std::string BasesExcess(const std::vector<SceneBeam>& beams) {
  std::set<std::tuple<double, double, double, std::vector<BeamSection>, std::vector<BeamPointMass>,
                      int, EndCondition, EndCondition, double, double, std::optional<double>,
                      std::optional<double>>>
      distinct;
  std::vector<int> unknowns;
  for (const SceneBeam& b : beams) {
    if (distinct
            .insert({b.length_m, b.ei_n_m2, b.rho_a_kg_per_m, b.sections, b.point_masses,
                     b.n_elements, b.at_zero, b.at_length, b.spring_at_zero_n_per_m,
                     b.spring_at_length_n_per_m, b.f_trunc_hz, b.r_ftrunc})
            .second)
      unknowns.push_back(BeamUnknowns(b.n_elements));
  }
  return EigenBudgetExcess(unknowns, 1);
}

double Positive(JsonObjectReader& r, const std::string& key, double hi = 1e15) {
  const double v = r.RequiredNumber(key);
  if (!(v > 0.0) || v > hi)
    r.Fail(key, "value " + Shown(Json(v)) + " must be > 0 and <= " + Shown(Json(hi)));
  return v;
}

double InRange(JsonObjectReader& r, const std::string& key, double fallback, double lo, double hi) {
  const double v = r.Number(key, fallback);
  if (v < lo || v > hi) {
    r.Fail(key, "value " + Shown(Json(v)) + " must lie in [" + Shown(Json(lo)) + ", " +
                    Shown(Json(hi)) + "]");
  }
  return v;
}

std::pair<double, double> Vector2(JsonObjectReader& r, const std::string& key,
                                  std::pair<double, double> fallback, bool unit) {
  const Json* v = r.Get(key);
  if (v == nullptr) return fallback;
  if (!v->is_array() || v->size() != 2) r.Fail(key, "expected [y, z], got " + Shown(*v));
  double y = NumberAt((*v)[0], r.File(), r.PathOf(key) + "[0]");
  double z = NumberAt((*v)[1], r.File(), r.PathOf(key) + "[1]");
  if (unit) {
    const double norm = std::hypot(y, z);
    if (norm < 1e-12) r.Fail(key, "a direction must not be zero, got " + Shown(*v));
    y /= norm, z /= norm;
  }
  return {y, z};
}

int Direction(JsonObjectReader& r, const std::string& key) {
  const std::string d = r.String(key, "y");
  if (d != "y" && d != "z") r.Fail(key, "\"" + d + "\" is not a direction: use \"y\" or \"z\"");
  return d == "y" ? 0 : 1;
}

std::pair<EndCondition, EndCondition> Ends(JsonObjectReader& r) {
  const Json* v = r.Get("ends");
  if (v == nullptr) return {EndCondition::kClamped, EndCondition::kFree};
  if (!v->is_array() || v->size() != 2)
    r.Fail("ends", "expected [at x = 0, at x = L], got " + Shown(*v));
  EndCondition e[2];
  for (int i = 0; i < 2; ++i) {
    const auto c =
        (*v)[i].is_string() ? EndConditionFromString((*v)[i].get<std::string>()) : std::nullopt;
    if (!c)
      FailAt(r.File(), r.PathOf("ends") + "[" + std::to_string(i) + "]",
             Shown((*v)[i]) +
                 " is not an end: use \"clamped\", \"pinned\" or \"free\" (with "
                 "end_springs_n_per_m for elastic)");
    e[i] = *c;
  }
  return {e[0], e[1]};
}

template <typename F>
void EachItem(JsonObjectReader& parent, const std::string& key, F parse) {
  const Json* list = parent.Get(key);
  if (list == nullptr) return;
  if (!list->is_array()) parent.Fail(key, "expected a list, got " + Shown(*list));
  for (std::size_t i = 0; i < list->size(); ++i) {
    JsonObjectReader item((*list)[i], parent.File(),
                          parent.PathOf(key) + "[" + std::to_string(i) + "]");
    parse(item);
    item.Finish();
  }
}

// A beam's sections and point masses beyond these are typing mistakes: a pin has a handful.
constexpr std::size_t kMaxSections = 1000;
constexpr std::size_t kMaxPointMasses = 1000;
// The sections' lengths sum to the beam's length to this fraction of it.
constexpr double kSectionsSumTolerance = 1e-9;

// A beam's sections from the base up (docs/scenes.md, "Non-uniform beams"): each length_m,
// ei_n_m2 and rho_a_kg_per_m > 0, no section shorter than kSameNodeFraction of the beam, and
// their lengths summing to the beam's length_m.
std::vector<BeamSection> ParseSections(JsonObjectReader& r, double length_m) {
  const Json* list = r.Get("sections");
  if (!list->is_array() || list->empty() || list->size() > kMaxSections) {
    r.Fail("sections", "expected a list of 1 to " + std::to_string(kMaxSections) +
                           " sections {length_m, ei_n_m2, rho_a_kg_per_m} from the base up, got " +
                           Shown(*list));
  }
  std::vector<BeamSection> sections;
  double sum = 0.0;
  EachItem(r, "sections", [&](JsonObjectReader& item) {
    BeamSection section;
    section.length_m = Positive(item, "length_m", 1e3);
    if (section.length_m < kSameNodeFraction * length_m) {
      item.Fail("length_m", "value " + Shown(Json(section.length_m)) + " m is shorter than " +
                                Shown(Json(kSameNodeFraction)) + " of the beam's length_m (" +
                                Shown(Json(length_m)) + " m)");
    }
    section.ei_n_m2 = Positive(item, "ei_n_m2");
    section.rho_a_kg_per_m = Positive(item, "rho_a_kg_per_m", 1e6);
    sum += section.length_m;
    sections.push_back(section);
  });
  if (std::abs(sum - length_m) > kSectionsSumTolerance * length_m) {
    r.Fail("sections", fmt::format("the sections' lengths sum to {:.12g} m, not to the beam's "
                                   "length_m ({:.12g} m): they must sum to it, to {:g} relative",
                                   sum, length_m, kSectionsSumTolerance));
  }
  return sections;
}

// A beam's point masses: each at height_m in [0, length_m], mass_kg > 0, rotary_inertia_kg_m2
// >= 0 (default 0).
std::vector<BeamPointMass> ParsePointMasses(JsonObjectReader& r, double length_m) {
  const Json* list = r.Get("point_masses");
  if (list == nullptr) return {};
  if (!list->is_array() || list->size() > kMaxPointMasses) {
    r.Fail("point_masses", "expected a list of at most " + std::to_string(kMaxPointMasses) +
                               " point masses {height_m, mass_kg, rotary_inertia_kg_m2}, got " +
                               Shown(*list));
  }
  std::vector<BeamPointMass> masses;
  EachItem(r, "point_masses", [&](JsonObjectReader& item) {
    BeamPointMass m;
    m.height_m = item.RequiredNumber("height_m");
    if (m.height_m < 0.0 || m.height_m > length_m) {
      item.Fail("height_m", "value " + Shown(Json(m.height_m)) +
                                " m lies outside the beam: a point mass sits at a height in [0, " +
                                Shown(Json(length_m)) + "] m");
    }
    m.mass_kg = Positive(item, "mass_kg", 1e6);
    m.rotary_inertia_kg_m2 = InRange(item, "rotary_inertia_kg_m2", 0.0, 0.0, 1e6);
    masses.push_back(m);
  });
  return masses;
}

// A beam's EI and rho A: uniform (ei_n_m2, rho_a_kg_per_m) or by sections, not both; and its
// point masses.
void ParseBeamMakeUp(JsonObjectReader& r, SceneBeam& b) {
  if (r.Has("sections")) {
    for (const char* key : {"ei_n_m2", "rho_a_kg_per_m"}) {
      if (r.Has(key))
        r.Fail(key,
               "give sections (each with its EI and rho A) or ei_n_m2 and rho_a_kg_per_m "
               "(a uniform beam), not both");
    }
    b.sections = ParseSections(r, b.length_m);
  } else {
    b.ei_n_m2 = Positive(r, "ei_n_m2");
    b.rho_a_kg_per_m = Positive(r, "rho_a_kg_per_m", 1e6);
  }
  b.point_masses = ParsePointMasses(r, b.length_m);
}

SceneBeam ParseBeamProperties(JsonObjectReader& r) {
  SceneBeam b;
  b.length_m = Positive(r, "length_m", 1e3);
  ParseBeamMakeUp(r, b);
  b.n_elements = r.Integer("elements", b.n_elements);
  if (b.n_elements < 1)
    r.Fail("elements", "value " + std::to_string(b.n_elements) + " must be >= 1");
  if (const auto pieces = static_cast<int>(MeshBreaks(SectionsOf(b)).size()) - 1;
      b.n_elements < pieces) {
    r.Fail("elements",
           "value " + std::to_string(b.n_elements) +
               ": the sections' ends and the point masses split the beam into " +
               std::to_string(pieces) +
               " pieces of at least one element each; give elements >= " + std::to_string(pieces));
  }
  if (const std::string excess = BasesExcess({b}); !excess.empty())
    r.Fail("elements", "value " + std::to_string(b.n_elements) + ": " + excess);
  std::tie(b.at_zero, b.at_length) = Ends(r);
  const auto springs = Vector2(r, "end_springs_n_per_m", {0.0, 0.0}, false);
  if (springs.first < 0 || springs.second < 0)
    r.Fail("end_springs_n_per_m", "springs must be >= 0");
  b.spring_at_zero_n_per_m = springs.first;
  b.spring_at_length_n_per_m = springs.second;
  if (r.Has("r_ftrunc") && r.Has("f_trunc_hz"))
    r.Fail("f_trunc_hz", "give r_ftrunc or f_trunc_hz, not both");
  if (r.Has("r_ftrunc")) b.r_ftrunc = InRange(r, "r_ftrunc", 0.0, 1.0, 1e5);
  if (r.Has("f_trunc_hz")) b.f_trunc_hz = Positive(r, "f_trunc_hz", 1e7);
  if (b.at_zero == EndCondition::kFree && b.at_length == EndCondition::kFree &&
      springs.first == 0 && springs.second == 0) {
    r.Fail("ends", "a free-free beam without end springs has rigid-body modes and no support");
  }
  return b;
}

// Gap values for `count` zones: a number, {"uniform": g}, {"list": [...]} or
// {"normal": {"mean", "std", "seed", "min"}} (drawn with mt19937_64 and Box-Muller, so the same
// seed gives the same gaps on every platform). A negative gap (a preload) must be shallower
// than the pin pitch: deeper, a pin would sit past its neighbour.
std::vector<double> Gaps(const Json& v, const std::string& file, const std::string& path,
                         std::size_t count, double pitch_m) {
  auto check = [&](double g, const std::string& at) {
    if (std::abs(g) > 1.0) FailAt(file, at, "gap " + Shown(Json(g)) + " m must lie in [-1, 1] m");
    if (!(g > -pitch_m)) {
      FailAt(file, at,
             "gap " + Shown(Json(g)) + " m is a preload deeper than the pin pitch (" +
                 Shown(Json(pitch_m)) + " m): a negative gap must lie in (-pitch, 0)");
    }
    return g;
  };
  if (v.is_number()) return std::vector<double>(count, check(NumberAt(v, file, path), path));
  JsonObjectReader r(v, file, path);
  std::vector<double> gaps;
  if (r.Has("uniform")) {
    gaps.assign(count, check(r.RequiredNumber("uniform"), r.PathOf("uniform")));
  } else if (const Json* list = r.Get("list")) {
    if (!list->is_array() || list->size() != count) {
      r.Fail("list",
             "expected " + std::to_string(count) + " gaps (one per zone), got " + Shown(*list));
    }
    for (std::size_t i = 0; i < count; ++i) {
      const std::string at = r.PathOf("list") + "[" + std::to_string(i) + "]";
      gaps.push_back(check(NumberAt((*list)[i], file, at), at));
    }
  } else if (const Json* normal = r.Get("normal")) {
    JsonObjectReader n(*normal, file, r.PathOf("normal"));
    const double mean = n.RequiredNumber("mean");
    const double sd = n.RequiredNumber("std");
    const double lo = n.Number("min", 0.0);
    const int seed = n.Integer("seed", 1);
    n.Finish();
    if (sd < 0) n.Fail("std", "must be >= 0");
    check(lo, n.PathOf("min"));
    std::mt19937_64 rng(static_cast<std::uint64_t>(seed));
    auto uniform = [&] { return (static_cast<double>(rng() >> 11) + 0.5) * 0x1.0p-53; };
    for (std::size_t i = 0; i < count; ++i) {
      const double g =
          mean + sd * std::sqrt(-2.0 * std::log(uniform())) * std::cos(2.0 * M_PI * uniform());
      gaps.push_back(check(std::max(lo, g), r.PathOf("normal")));
    }
  } else {
    r.Fail("", "expected a number, {\"uniform\": g}, {\"list\": [...]} or {\"normal\": {...}}");
  }
  r.Finish();
  return gaps;
}

std::vector<double> Heights(const Json& v, const std::string& file, const std::string& path) {
  std::vector<double> h;
  if (v.is_array()) {
    for (std::size_t i = 0; i < v.size(); ++i)
      h.push_back(NumberAt(v[i], file, path + "[" + std::to_string(i) + "]"));
  } else {
    JsonObjectReader r(v, file, path);
    const Json* lin = r.Get("linspace");
    r.Finish();
    if (lin == nullptr || !lin->is_array() || lin->size() != 3 || !(*lin)[2].is_number_integer()) {
      FailAt(file, path, "expected a list of heights or {\"linspace\": [first, last, count]}");
    }
    const double a = NumberAt((*lin)[0], file, path), b = NumberAt((*lin)[1], file, path);
    const auto n = (*lin)[2].get<std::int64_t>();
    if (n < 1 || n > 10000) FailAt(file, path + ".linspace[2]", "count must lie in [1, 10000]");
    for (std::int64_t i = 0; i < n; ++i)
      h.push_back(n == 1 ? a : a + (b - a) * static_cast<double>(i) / static_cast<double>(n - 1));
  }
  if (h.empty()) FailAt(file, path, "give at least one height");
  std::set<std::string> labels;
  for (double height : h) {
    if (!labels.insert(HeightLabel(height)).second) {
      FailAt(file, path,
             "height " + Shown(Json(height)) + " m is given twice (to the micrometre, " +
                 HeightLabel(height) + " m); heights must differ, since they name the zones");
    }
  }
  return h;
}

// A zone's laws as a file gives them, in zones[] or bundle.wire: stiffness_n_per_m (the linear
// penalty) or power_law, damping_n_s_per_m, and friction (docs/physics.md §7).
struct ZoneLaws {
  double stiffness_n_per_m = 0.0, damping_n_s_per_m = 0.0;
  std::optional<ScenePowerLaw> power_law;
  std::optional<FrictionLaw> friction;

  void ApplyTo(SceneZone& z) const {
    z.stiffness_n_per_m = stiffness_n_per_m;
    z.damping_n_s_per_m = damping_n_s_per_m;
    z.power_law = power_law;
    z.friction = friction;
  }
};

ScenePowerLaw ParsePowerLaw(JsonObjectReader& p) {
  ScenePowerLaw law;
  law.coefficient = Positive(p, "coefficient_n_per_m_exponent", 1e20);
  law.exponent = InRange(p, "exponent", law.exponent, 1.0, 3.0);
  law.bound_penetration_m = Positive(p, "bound_penetration_m", 1.0);
  return law;
}

FrictionLaw ParseFriction(JsonObjectReader& f) {
  FrictionLaw law;
  law.coefficient = Positive(f, "coefficient", 10.0);
  law.static_coefficient = InRange(f, "static_coefficient", law.coefficient, law.coefficient, 10.0);
  law.tangential_stiffness_n_per_m = Positive(f, "tangential_stiffness_n_per_m");
  law.tangential_damping_n_s_per_m = InRange(f, "tangential_damping_n_s_per_m", 0.0, 0.0, 1e9);
  const std::string convention = f.String("convention", "return_mapping");
  if (convention != "return_mapping" && convention != "code_aster") {
    f.Fail("convention", Shown(Json(convention)) +
                             " is not a friction convention: use \"return_mapping\" (the "
                             "default) or \"code_aster\" (DIS_CHOC's algorithm)");
  }
  law.convention = convention == "code_aster" ? FrictionConvention::kCodeAster
                                              : FrictionConvention::kReturnMapping;
  return law;
}

// The softest tangential spring a zone may have, as a fraction of its normal stiffness. Softer,
// the spring takes a slip of mu_s N / k_t, over a million times mu_s times the penetration,
// before the zone slides: a run would never see it slide (nor wear), whatever its step.
constexpr double kMinTangentialToNormalStiffness = 1e-6;

void CheckTangentialStiffness(JsonObjectReader& f, double tangential, double normal) {
  const double least = kMinTangentialToNormalStiffness * normal;
  if (tangential < least) {
    f.Fail("tangential_stiffness_n_per_m",
           "value " + Shown(Json(tangential)) + " is below " + Shown(Json(least)) +
               ", 1e-06 times the zone's normal stiffness " + Shown(Json(normal)) +
               " N/m: so soft a spring needs a slip of over a million times the penetration "
               "before the zone slides, so it would never slide; give at least " +
               Shown(Json(least)));
  }
}

// The laws of the zones `r` describes. Friction needs the tangential motion of a scene bending
// in both planes.
ZoneLaws ParseZoneLaws(JsonObjectReader& r, BendingPlanes planes) {
  ZoneLaws laws;
  if (const Json* power = r.Get("power_law")) {
    if (r.Has("stiffness_n_per_m")) {
      r.Fail("power_law", "give stiffness_n_per_m (the linear law) or power_law, not both");
    }
    JsonObjectReader p(*power, r.File(), r.PathOf("power_law"));
    laws.power_law = ParsePowerLaw(p);
    p.Finish();
    const ScenePowerLaw& law = *laws.power_law;
    // The stiffness the stability bound takes: the tangent one at the bound penetration.
    laws.stiffness_n_per_m =
        NormalLaw{law.coefficient, 0.0, law.exponent}.TangentStiffness(law.bound_penetration_m);
  } else {
    laws.stiffness_n_per_m = Positive(r, "stiffness_n_per_m");
  }
  laws.damping_n_s_per_m = InRange(r, "damping_n_s_per_m", 0.0, 0.0, 1e9);
  if (const Json* friction = r.Get("friction")) {
    if (planes == BendingPlanes::kPlanar) {
      r.Fail("friction",
             "a planar scene has no tangential motion at its zones: friction needs "
             "\"bending\": \"both\"");
    }
    JsonObjectReader f(*friction, r.File(), r.PathOf("friction"));
    laws.friction = ParseFriction(f);
    CheckTangentialStiffness(f, laws.friction->tangential_stiffness_n_per_m,
                             laws.stiffness_n_per_m);
    f.Finish();
  }
  return laws;
}

// Pin positions in the cross-section and the lattice cell of each.
struct Lattice {
  bool row = true;
  double pitch_m = 0.0;
  int rings = 0;          // Of a hex lattice.
  std::int64_t pins = 0;  // How many the layout makes, before they are placed.
  std::string count_key;  // The key that sets it: "pins" or "rings".
  std::vector<std::pair<double, double>> positions;
  std::vector<std::array<int, 2>> cells;
};

// layout "row": `pins` pins along y; "hex": `rings` rings around a centre pin. Reads how many;
// PlacePins places them once CheckBundle has accepted that many.
Lattice ParseLattice(JsonObjectReader& r) {
  Lattice l;
  const std::string layout = r.String("layout", "row");
  if (layout != "row" && layout != "hex")
    r.Fail("layout", "\"" + layout + "\" is not a layout: use \"row\" or \"hex\"");
  l.row = layout == "row";
  l.pitch_m = Positive(r, "pin_pitch_m", 1.0);
  if (l.row) {
    l.count_key = "pins";
    l.pins = r.Integer("pins", 0);
    if (l.pins < 1) r.Fail("pins", "value " + std::to_string(l.pins) + " must be at least 1");
    return l;
  }
  l.count_key = "rings";
  l.rings = r.Integer("rings", 0);
  if (l.rings < 0 || l.rings > 50)
    r.Fail("rings", "value " + std::to_string(l.rings) + " must lie in [0, 50]");
  l.pins = 3 * l.rings * (l.rings + 1) + 1;
  return l;
}

void PlacePins(Lattice& l) {
  if (l.row) {
    for (int i = 0; i < l.pins; ++i) {
      l.positions.push_back({(i - (l.pins - 1) / 2.0) * l.pitch_m, 0.0});
      l.cells.push_back({i, 0});
    }
    return;
  }
  for (int q = -l.rings; q <= l.rings; ++q) {
    for (int s = -l.rings; s <= l.rings; ++s) {
      if (std::abs(q + s) > l.rings) continue;
      l.positions.push_back({l.pitch_m * (q + s / 2.0), l.pitch_m * s * std::sqrt(3.0) / 2.0});
      l.cells.push_back({q, s});
    }
  }
}

const Json& RequiredObject(JsonObjectReader& r, const std::string& key) {
  const Json* v = r.Get(key);
  if (v == nullptr) r.Fail(key, "required object is missing");
  return *v;
}

// The bundle's pin and wrapper beams and its wires, with the gap laws still to be drawn.
struct BundleParts {
  SceneBeam pin, wrapper;
  std::vector<double> heights;
  ZoneLaws laws;
  const Json* pin_gap = nullptr;
  const Json* wrapper_gap = nullptr;  // nullptr: the first pin gap.
  std::string heights_path, pin_gap_path, wrapper_gap_path;
};

void ParseWire(JsonObjectReader& wire, BendingPlanes planes, BundleParts& p) {
  const Json* heights = wire.Get("heights_m");
  if (heights == nullptr) wire.Fail("heights_m", "required");
  p.heights_path = wire.PathOf("heights_m");
  p.heights = Heights(*heights, wire.File(), p.heights_path);
  p.laws = ParseZoneLaws(wire, planes);
  p.pin_gap = wire.Get("gap_m");
  if (p.pin_gap == nullptr) wire.Fail("gap_m", "required");
  p.pin_gap_path = wire.PathOf("gap_m");
  wire.Finish();
}

BundleParts ParseBundleParts(JsonObjectReader& r, BendingPlanes planes) {
  BundleParts p;
  JsonObjectReader pin(RequiredObject(r, "pin"), r.File(), r.PathOf("pin"));
  p.pin = ParseBeamProperties(pin);
  pin.Finish();
  JsonObjectReader wrap(RequiredObject(r, "wrapper"), r.File(), r.PathOf("wrapper"));
  p.wrapper = ParseBeamProperties(wrap);
  p.wrapper_gap = wrap.Get("gap_m");
  p.wrapper_gap_path = wrap.PathOf("gap_m");
  wrap.Finish();
  JsonObjectReader wire(RequiredObject(r, "wire"), r.File(), r.PathOf("wire"));
  ParseWire(wire, planes, p);
  return p;
}

// Wires on both beams, and a size refused before anything is generated: at most 6 zones per
// pin and height.
// The zones a bundle generates at each wire height (docs/scenes.md): a row's neighbouring pairs
// and its two end pins against the wrapper; a hexagonal lattice's 3n(3n + 1) pairs and 12n + 6
// faces against the wrapper.
double BundleZonesPerHeight(const Lattice& l) {
  const double n = l.rings;
  return l.row ? static_cast<double>(l.pins) + 1.0 : 3.0 * n * (3.0 * n + 1.0) + 12.0 * n + 6.0;
}

// The wire heights on the beams, and the bundle's beams (with the wrapper and the `listed`
// beams of "beams") and zones within the limits, before any is generated.
void CheckBundle(const Lattice& l, const BundleParts& p, std::size_t listed,
                 const std::string& file) {
  for (double h : p.heights) {
    if (h < 0 || h > p.pin.length_m || h > p.wrapper.length_m) {
      FailAt(file, p.heights_path,
             "height " + Shown(Json(h)) + " m lies outside the pins or the wrapper");
    }
  }
  const double heights = static_cast<double>(p.heights.size());
  const double beams = static_cast<double>(listed + 1) + static_cast<double>(l.pins);
  if (beams > kMaxBeams) {
    const double zones = BundleZonesPerHeight(l) * heights;
    FailAt(file, "bundle." + l.count_key,
           fmt::format("value {} makes {} pins, {:.0f} beams with the wrapper{}: {}",
                       l.row ? l.pins : l.rings, l.pins, beams,
                       listed > 0 ? fmt::format(" and the {} of \"beams\"", listed) : "",
                       BeamLimit(beams, zones)));
  }
  const double zones = 6.0 * static_cast<double>(l.pins) * heights;
  if (zones > kMaxZones) {
    FailAt(file, "bundle",
           std::to_string(l.pins) + " pins with " + std::to_string(p.heights.size()) +
               " wire heights would make up to " + Shown(Json(zones)) + " zones: at most " +
               std::to_string(kMaxZones) + " are allowed");
  }
}

// Appends the wrapper and the pins; returns the beam index of each lattice cell.
std::map<std::array<int, 2>, int> AddBundleBeams(const Lattice& l, const BundleParts& p,
                                                 Scene& scene) {
  SceneBeam wrapper = p.wrapper;
  wrapper.name = "wrapper";
  scene.beams.push_back(wrapper);
  std::map<std::array<int, 2>, int> index;
  for (std::size_t i = 0; i < l.positions.size(); ++i) {
    SceneBeam b = p.pin;
    b.name = "pin_" + std::to_string(i);
    std::tie(b.y_m, b.z_m) = l.positions[i];
    index[l.cells[i]] = static_cast<int>(scene.beams.size());
    scene.beams.push_back(b);
  }
  return index;
}

struct BundleZones {
  std::vector<SceneZone> pairs, walls;
};

// The wrapper face a zone's normal points to: degrees from +y towards +z, in [0, 360).
long FaceDegrees(double normal_y, double normal_z) {
  const long degrees = std::lround(std::atan2(normal_z, normal_y) * 180.0 / std::numbers::pi);
  return (degrees + 360) % 360;
}

// "pin_3-pin_4@0.9144", "pin_0-wrapper@0.9144"; a pin that meets the wrapper on several faces
// (every outer pin of a hexagonal bundle, the single pin of a row) names each face by the
// direction of its normal: "pin_0-wrapper_60deg@0.9144". Zone names are unique.
std::string BundleZoneName(const Scene& scene, const SceneZone& z, bool several_faces) {
  std::string beams = scene.beams[z.beam_a].name + "-" + scene.beams[z.beam_b].name;
  if (several_faces) beams += "_" + std::to_string(FaceDegrees(z.normal_y, z.normal_z)) + "deg";
  return beams + "@" + HeightLabel(z.height_m);
}

// Zones at every wire height between neighbouring pins (each pair once) and, where a neighbour
// is missing, between the pin and the wrapper (beam `wrapper`); gaps are drawn afterwards.
BundleZones GenerateBundleZones(const Lattice& l, const BundleParts& p,
                                const std::map<std::array<int, 2>, int>& index, int wrapper,
                                const Scene& scene) {
  const std::vector<std::array<int, 2>> steps =
      l.row ? std::vector<std::array<int, 2>>{{1, 0}, {-1, 0}}
            : std::vector<std::array<int, 2>>{{1, 0}, {0, 1}, {-1, 1}, {-1, 0}, {0, -1}, {1, -1}};
  BundleZones zones;
  for (const auto& [cell, a] : index) {
    // A copy: clang 14 refuses a lambda's capture of a structured binding.
    const std::array<int, 2> at = cell;
    const auto missing = std::ranges::count_if(steps, [&](const auto& s) {
      return !index.contains({at[0] + s[0], at[1] + s[1]});
    });
    for (const auto& s : steps) {
      const double ny = l.row ? s[0] : s[0] + s[1] / 2.0;
      const double nz = l.row ? 0.0 : s[1] * std::sqrt(3.0) / 2.0;
      const auto it = index.find({cell[0] + s[0], cell[1] + s[1]});
      if (it != index.end() && it->second < a) continue;  // Each pair once.
      for (double h : p.heights) {
        SceneZone z;
        z.beam_a = a;
        z.height_m = h;
        z.normal_y = ny, z.normal_z = nz;
        p.laws.ApplyTo(z);
        z.y_m = l.positions[a - wrapper - 1].first + 0.5 * l.pitch_m * ny;
        z.z_m = l.positions[a - wrapper - 1].second + 0.5 * l.pitch_m * nz;
        z.beam_b = it != index.end() ? it->second : wrapper;
        z.name = BundleZoneName(scene, z, it == index.end() && missing > 1);
        (it != index.end() ? zones.pairs : zones.walls).push_back(z);
      }
    }
  }
  return zones;
}

// Draws the gaps (pairs first, then walls, so that a seed gives the same gaps as before) and
// appends the zones, pairs first.
void AddBundleZones(BundleZones zones, const BundleParts& p, double pitch_m,
                    const std::string& file, Scene& scene) {
  const auto pair_gaps = Gaps(*p.pin_gap, file, p.pin_gap_path, zones.pairs.size(), pitch_m);
  const auto wall_gaps =
      p.wrapper_gap != nullptr
          ? Gaps(*p.wrapper_gap, file, p.wrapper_gap_path, zones.walls.size(), pitch_m)
      : pair_gaps.empty() ? std::vector<double>(zones.walls.size(), 0.0)
                          : std::vector<double>(zones.walls.size(), pair_gaps.front());
  for (std::size_t i = 0; i < zones.pairs.size(); ++i) zones.pairs[i].gap_m = pair_gaps[i];
  for (std::size_t i = 0; i < zones.walls.size(); ++i) zones.walls[i].gap_m = wall_gaps[i];
  scene.zones.insert(scene.zones.end(), zones.pairs.begin(), zones.pairs.end());
  scene.zones.insert(scene.zones.end(), zones.walls.begin(), zones.walls.end());
}

// Expands {"bundle": {...}}: a wrapper beam named "wrapper" and pins "pin_0", "pin_1", ... in a
// row along y (layout "row") or on a hexagonal lattice with `rings` rings around a centre pin
// (layout "hex": 1 + 3 rings (rings + 1) pins), with zones at every wire height between
// neighbouring pins and between the outer pins and the wrapper.
void ExpandBundle(const Json& v, const std::string& file, Scene& scene) {
  JsonObjectReader r(v, file, "bundle");
  Lattice lattice = ParseLattice(r);
  if (!lattice.row) scene.planes = BendingPlanes::kBoth;
  const BundleParts parts = ParseBundleParts(r, scene.planes);
  r.Finish();
  CheckBundle(lattice, parts, scene.beams.size(), file);
  PlacePins(lattice);
  const int wrapper = static_cast<int>(scene.beams.size());
  const auto index = AddBundleBeams(lattice, parts, scene);
  AddBundleZones(GenerateBundleZones(lattice, parts, index, wrapper, scene), parts, lattice.pitch_m,
                 file, scene);
}

// True when `file` lies in `folder` or below it (both canonical).
bool Inside(const std::filesystem::path& file, const std::filesystem::path& folder) {
  const auto [f, _] = std::mismatch(folder.begin(), folder.end(), file.begin(), file.end());
  return f == folder.end();
}

// The data file named at `key` of the scene being read: resolved against the scene's folder,
// symbolic links followed, and accepted only inside that folder or an allowed one.
std::filesystem::path DataFile(JsonObjectReader& r, const std::string& key,
                               const SceneFileAccess& access) {
  namespace fs = std::filesystem;
  const std::string name = r.RequiredString(key);
  std::error_code ec;
  const fs::path folder = fs::weakly_canonical(fs::absolute(r.File()).parent_path(), ec);
  const fs::path file = fs::weakly_canonical(folder / name, ec);
  if (!ec && Inside(file, folder)) return file;
  for (const auto& allowed : access.allowed_folders) {
    std::error_code allowed_ec;
    const fs::path root = fs::weakly_canonical(fs::absolute(allowed), allowed_ec);
    if (!ec && !allowed_ec && Inside(file, root)) return file;
  }
  r.Fail(key, "\"" + Excerpt(name) + "\" lies outside the scene's folder " + folder.string() +
                  ": a scene's data files must lie in its folder or below it, or in a folder "
                  "given on the command line with --allow-path DIR");
}

void LoadAccelerationCsv(JsonObjectReader& r, const SceneFileAccess& access,
                         BaseMotionEffect& base) {
  const std::filesystem::path csv = DataFile(r, "csv", access);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(csv, ec))
    r.Fail("csv", csv.string() + " is not a regular file");
  std::ifstream in(csv);
  if (!in) r.Fail("csv", "cannot open " + csv.string());
  ParseAccelerationCsv(in, csv.string(), base);
}

// A structure's matrices: Matrix Market files with the CSV tables of its DOFs and nodes, or
// CalculiX's matrix storage (jobname.sti, .mas, .dof) with the deck for the nodes' coordinates;
// files resolved as a scene's data files.
std::shared_ptr<const FeStructure> ReadStructureFiles(JsonObjectReader& s,
                                                      const SceneFileAccess& access) {
  if (s.Has("matrix_market") == s.Has("calculix")) {
    s.Fail("matrix_market",
           "give \"matrix_market\": {\"stiffness\", \"mass\", \"dofs\", \"nodes\"} or "
           "\"calculix\": {\"jobname\", \"deck\"}, one of them");
  }
  FeStructure fe;
  if (const Json* mm = s.Get("matrix_market")) {
    JsonObjectReader f(*mm, s.File(), s.PathOf("matrix_market"));
    const auto stiffness = DataFile(f, "stiffness", access), mass = DataFile(f, "mass", access);
    const auto dofs = DataFile(f, "dofs", access), nodes = DataFile(f, "nodes", access);
    f.Finish();
    fe =
        ReadMatrixMarketStructure(stiffness.string(), mass.string(), dofs.string(), nodes.string());
  } else {
    JsonObjectReader f(*s.Get("calculix"), s.File(), s.PathOf("calculix"));
    const auto jobname = DataFile(f, "jobname", access), deck = DataFile(f, "deck", access);
    f.Finish();
    fe = ReadCalculixMatrixStorage(jobname.string(), deck.string());
  }
  return std::make_shared<const FeStructure>(std::move(fe));
}

int BeamIndex(const Scene& scene, JsonObjectReader& r, const std::string& key) {
  const std::string name = r.RequiredString(key);
  for (std::size_t i = 0; i < scene.beams.size(); ++i) {
    if (scene.beams[i].name == name) return static_cast<int>(i);
  }
  r.Fail(key, "no beam named \"" + name + "\"");
}

double Height(const Scene& scene, JsonObjectReader& r, int beam) {
  const double h = r.RequiredNumber("height_m");
  if (h < 0 || h > scene.beams[beam].length_m) {
    r.Fail("height_m", "value " + Shown(Json(h)) + " must lie on the beam, in [0, " +
                           Shown(Json(scene.beams[beam].length_m)) + "]");
  }
  return h;
}

// The names given so far, each with where it was given ("given at zones[0].name", "of a zone
// the bundle generates").
using NamesGiven = std::unordered_map<std::string, std::string>;

// A name read at `key`, refused when `names` already holds it (names label CSV columns and
// database rows).
std::string UniqueName(JsonObjectReader& r, const std::string& key, const char* what,
                       NamesGiven& names) {
  std::string name = r.RequiredName(key);
  const auto [given, fresh] = names.try_emplace(name, "given at " + r.PathOf(key));
  if (!fresh) {
    r.Fail(key, std::string(what) + " \"" + name + "\" is already the name " + given->second +
                    "; " + what + " names must be unique");
  }
  return name;
}

// structures[]: each one's files and truncation; names unique among beams and structures.
void ParseStructures(JsonObjectReader& r, const SceneFileAccess& access, Scene& scene,
                     NamesGiven& names) {
  EachItem(r, "structures", [&](JsonObjectReader& s) {
    SceneStructure structure;
    structure.name = UniqueName(s, "name", "structure", names);
    if (s.Has("r_ftrunc") && s.Has("f_trunc_hz"))
      s.Fail("f_trunc_hz", "give r_ftrunc or f_trunc_hz, not both");
    if (s.Has("r_ftrunc")) structure.r_ftrunc = InRange(s, "r_ftrunc", 0.0, 1.0, 1e5);
    if (s.Has("f_trunc_hz")) structure.f_trunc_hz = Positive(s, "f_trunc_hz", 1e7);
    auto fe = ReadStructureFiles(s, access);
    std::const_pointer_cast<FeStructure>(fe)->name = structure.name;
    structure.fe = std::move(fe);
    scene.structures.push_back(std::move(structure));
  });
}

std::optional<int> StructureNamed(const Scene& scene, const std::string& name) {
  for (std::size_t i = 0; i < scene.structures.size(); ++i) {
    if (scene.structures[i].name == name) return static_cast<int>(i);
  }
  return std::nullopt;
}

int StructureIndex(const Scene& scene, JsonObjectReader& r, const std::string& key) {
  const std::string name = r.RequiredString(key);
  if (const auto i = StructureNamed(scene, name)) return *i;
  r.Fail(key, "no structure named \"" + name + "\"");
}

constexpr std::array<DofComponent, 3> kTranslations{DofComponent::kUx, DofComponent::kUy,
                                                    DofComponent::kUz};

// A node of a structure at `key`: in its node table, with a free translational DOF.
int NodeOf(JsonObjectReader& r, const std::string& key, const SceneStructure& s) {
  if (!r.Has(key)) r.Fail(key, "required: a node of structure \"" + s.name + "\"");
  const int node = r.Integer(key, 0);
  if (!s.fe->node_coordinates_m.contains(node)) {
    r.Fail(key, "node " + std::to_string(node) + " is not in the node table of structure \"" +
                    s.name + "\"");
  }
  if (std::ranges::none_of(kTranslations,
                           [&](DofComponent c) { return s.fe->DofIndex(node, c).has_value(); })) {
    r.Fail(key, "node " + std::to_string(node) + " of structure \"" + s.name +
                    "\" has no free translational DOF (ux, uy, uz): its supports hold it");
  }
  return node;
}

// A unit vector [x, y, z] at `key` (required): refused when zero or not of unit length.
std::array<double, 3> UnitVector3(JsonObjectReader& r, const std::string& key) {
  const Json* v = r.Get(key);
  if (v == nullptr) r.Fail(key, "required: a unit vector [x, y, z]");
  if (!v->is_array() || v->size() != 3) r.Fail(key, "expected [x, y, z], got " + Shown(*v));
  std::array<double, 3> n{};
  for (int i = 0; i < 3; ++i)
    n[i] = NumberAt((*v)[i], r.File(), r.PathOf(key) + "[" + std::to_string(i) + "]");
  const double norm = std::hypot(n[0], n[1], n[2]);
  if (norm < 1e-12) r.Fail(key, "a direction must not be zero, got " + Shown(*v));
  if (std::abs(norm - 1.0) > 1e-6) {
    r.Fail(key, Shown(*v) + " has length " + Shown(Json(norm)) +
                    ": give a unit vector (length 1 within 1e-6)");
  }
  return n;
}

// Refused when the direction `n` (at `key`) moves no free DOF of the node.
void CheckFreeAlong(JsonObjectReader& r, const std::string& key, const SceneStructure& s, int node,
                    const std::array<double, 3>& n) {
  double free = 0.0;
  for (int c = 0; c < 3; ++c) {
    if (s.fe->DofIndex(node, kTranslations[c])) free += n[c] * n[c];
  }
  if (free < 1e-12) {
    r.Fail(key, "node " + std::to_string(node) + " of structure \"" + s.name +
                    "\" has no free DOF along this direction: its supports hold it there");
  }
}

void ParseHeader(JsonObjectReader& r, Scene& scene) {
  scene.name = r.RequiredName("name");
  scene.description = r.Text("description", "");
  const std::string planes = r.String("bending", "planar");
  if (planes != "planar" && planes != "both")
    r.Fail("bending", "\"" + planes + "\" must be \"planar\" or \"both\"");
  scene.planes = planes == "both" ? BendingPlanes::kBoth : BendingPlanes::kPlanar;
}

// beams[], then the bundle's beams and zones: every beam name once (`names`: the names of the
// beams and structures so far).
void ParseBeams(JsonObjectReader& r, Scene& scene, NamesGiven& names) {
  EachItem(r, "beams", [&](JsonObjectReader& b) {
    SceneBeam beam = ParseBeamProperties(b);
    beam.name = UniqueName(b, "name", "beam", names);
    std::tie(beam.y_m, beam.z_m) = Vector2(b, "position_m", {0.0, 0.0}, false);
    scene.beams.push_back(beam);
  });
  const std::size_t listed = scene.beams.size();
  if (const Json* bundle = r.Get("bundle")) ExpandBundle(*bundle, r.File(), scene);
  for (std::size_t i = listed; i < scene.beams.size(); ++i) {
    if (names.contains(scene.beams[i].name))
      r.Fail("bundle", "generates a beam named \"" + scene.beams[i].name +
                           "\", as one in \"beams\" is named; beam names must be unique");
  }
  if (scene.beams.size() > static_cast<std::size_t>(kMaxBeams))
    r.Fail("beams", "lists " + std::to_string(scene.beams.size()) +
                        " beams: " + BeamLimit(static_cast<double>(scene.beams.size()), 0.0));
  if (const std::string excess = BasesExcess(scene.beams); !excess.empty())
    r.Fail("beams", "the scene's distinct beams: " + excess);
}

// A zone with a side at a structure's node (docs/scenes.md, "Structures from an FE code"): the
// other side, its unit normal in 3D, the beam sides' height (else the node's x), position and
// laws; friction in any scene (its tangent lies in 3D).
SceneZone ParseNodeZone(JsonObjectReader& z, const Scene& scene, SceneZone zone,
                        const std::string& against) {
  if (against != "stop") {
    if (const auto s = StructureNamed(scene, against)) {
      zone.structure_b = *s;
      zone.node_b = NodeOf(z, "against_node", scene.structures[*s]);
      if (zone.structure_b == zone.structure_a && zone.node_b == zone.node_a)
        z.Fail("against_node", "a node cannot hit itself");
    } else {
      zone.beam_b = -1;
      for (std::size_t i = 0; i < scene.beams.size(); ++i) {
        if (scene.beams[i].name == against) zone.beam_b = static_cast<int>(i);
      }
      if (zone.beam_b < 0)
        z.Fail("against", "no beam or structure named \"" + against + "\" (or use \"stop\")");
    }
  }
  zone.normal_xyz = UnitVector3(z, "normal");
  if (zone.structure_a >= 0)
    CheckFreeAlong(z, "normal", scene.structures[zone.structure_a], zone.node_a, *zone.normal_xyz);
  if (zone.structure_b >= 0)
    CheckFreeAlong(z, "normal", scene.structures[zone.structure_b], zone.node_b, *zone.normal_xyz);
  std::pair<double, double> at{0.0, 0.0};
  if (zone.beam_a >= 0 || zone.beam_b >= 0) {
    const int beam = zone.beam_a >= 0 ? zone.beam_a : zone.beam_b;
    zone.height_m = Height(scene, z, beam);
    at = {scene.beams[beam].y_m, scene.beams[beam].z_m};
  }
  if (zone.structure_a >= 0) {
    const Eigen::Vector3d& node =
        scene.structures[zone.structure_a].fe->node_coordinates_m.at(zone.node_a);
    if (zone.beam_b < 0) zone.height_m = node.x();
    at = {node.y(), node.z()};
  }
  std::tie(zone.y_m, zone.z_m) = Vector2(z, "position_m", at, false);
  zone.gap_m = InRange(z, "gap_m", 0.0, -1.0, 1.0);
  ParseZoneLaws(z, BendingPlanes::kBoth).ApplyTo(zone);
  return zone;
}

SceneZone ParseZone(JsonObjectReader& z, const Scene& scene, NamesGiven& names) {
  SceneZone zone;
  zone.name = UniqueName(z, "name", "zone", names);
  const std::string against = z.String("against", "stop");
  if (z.Has("structure")) {
    if (z.Has("beam")) z.Fail("beam", "give \"beam\" or \"structure\", not both");
    zone.beam_a = -1;
    zone.structure_a = StructureIndex(scene, z, "structure");
    zone.node_a = NodeOf(z, "node", scene.structures[zone.structure_a]);
    return ParseNodeZone(z, scene, zone, against);
  }
  zone.beam_a = BeamIndex(scene, z, "beam");
  if (StructureNamed(scene, against)) return ParseNodeZone(z, scene, zone, against);
  if (against != "stop") {
    zone.beam_b = -1;
    for (std::size_t i = 0; i < scene.beams.size(); ++i) {
      if (scene.beams[i].name == against) zone.beam_b = static_cast<int>(i);
    }
    if (zone.beam_b < 0) z.Fail("against", "no beam named \"" + against + "\" (or use \"stop\")");
    if (zone.beam_b == zone.beam_a) z.Fail("against", "a beam cannot hit itself");
  }
  zone.height_m = Height(scene, z, zone.beam_a);
  if (zone.beam_b >= 0 && zone.height_m > scene.beams[zone.beam_b].length_m) {
    z.Fail("height_m", "lies beyond the end of \"" + against + "\"");
  }
  std::tie(zone.normal_y, zone.normal_z) = Vector2(z, "normal", {1.0, 0.0}, true);
  const SceneBeam& a = scene.beams[zone.beam_a];
  const SceneBeam* b = zone.beam_b >= 0 ? &scene.beams[zone.beam_b] : nullptr;
  std::tie(zone.y_m, zone.z_m) = Vector2(
      z, "position_m",
      b ? std::pair{0.5 * (a.y_m + b->y_m), 0.5 * (a.z_m + b->z_m)} : std::pair{a.y_m, a.z_m},
      false);
  zone.gap_m = InRange(z, "gap_m", 0.0, -1.0, 1.0);
  ParseZoneLaws(z, scene.planes).ApplyTo(zone);
  return zone;
}

// zones[], after the bundle's: every zone name once.
void ParseZones(JsonObjectReader& r, Scene& scene) {
  NamesGiven names;
  for (const SceneZone& z : scene.zones) names.emplace(z.name, "of a zone the bundle generates");
  EachItem(r, "zones",
           [&](JsonObjectReader& z) { scene.zones.push_back(ParseZone(z, scene, names)); });
  if (scene.zones.size() > static_cast<std::size_t>(kMaxZones))
    r.Fail("zones", "more than " + std::to_string(kMaxZones) + " zones");
}

ModalDampingEffect ParseModalDamping(JsonObjectReader& m) {
  ModalDampingEffect d;
  if (const Json* ratios = m.Get("ratios")) {
    if (!ratios->is_array() || ratios->empty())
      m.Fail("ratios", "expected a non-empty list of damping ratios");
    for (std::size_t i = 0; i < ratios->size(); ++i) {
      const std::string at = m.PathOf("ratios") + "[" + std::to_string(i) + "]";
      const double xi = NumberAt((*ratios)[i], m.File(), at);
      if (xi < 0 || xi > 10) FailAt(m.File(), at, "ratio must lie in [0, 10]");
      d.ratios.push_back(xi);
    }
  }
  d.mass_proportional_per_s = InRange(m, "mass_proportional_per_s", 0.0, 0.0, 1e6);
  return d;
}

BaseMotionEffect ParseBaseMotion(JsonObjectReader& b, const SceneFileAccess& access) {
  BaseMotionEffect base;
  std::tie(base.dir_y, base.dir_z) = Vector2(b, "direction", {1.0, 0.0}, true);
  if (const Json* hs = b.Get("half_sine")) {
    JsonObjectReader h(*hs, b.File(), b.PathOf("half_sine"));
    base.amplitude_m_s2 = InRange(h, "amplitude_m_s2", 0.0, -1e7, 1e7);
    base.duration_s = Positive(h, "duration_s", 100.0);
    base.start_s = InRange(h, "start_s", 0.0, 0.0, 1e4);
    h.Finish();
  } else if (b.Has("csv")) {
    LoadAccelerationCsv(b, access, base);
  } else {
    b.Fail("", "give \"half_sine\": {...} or \"csv\": \"file.csv\"");
  }
  return base;
}

StaticForceEffect ParseStaticForce(JsonObjectReader& f, const Scene& scene) {
  StaticForceEffect force;
  force.beam = BeamIndex(scene, f, "beam");
  force.height_m = Height(scene, f, force.beam);
  std::tie(force.dir_y, force.dir_z) = Vector2(f, "direction", {1.0, 0.0}, true);
  force.force_n = InRange(f, "force_n", 0.0, -1e9, 1e9);
  force.start_s = InRange(f, "start_s", 0.0, 0.0, 1e4);
  force.ramp_s = InRange(f, "ramp_s", 0.0, 0.0, 1e4);
  return force;
}

// What a beam's and a structure's initial states both give: the mode and its amplitude, the
// uniform velocity and the static force.
void ReadReleaseAmounts(JsonObjectReader& s, InitialStateEffect& init) {
  init.mode = s.Integer("mode", 1);
  if (init.mode < 1 || init.mode > 1000) s.Fail("mode", "must lie in [1, 1000]");
  init.tip_m = InRange(s, "amplitude_m", 0.0, -1.0, 1.0);
  init.velocity_m_s = InRange(s, "velocity_m_s", 0.0, -1e3, 1e3);
  init.static_force_n = InRange(s, "static_force_n", 0.0, -1e9, 1e9);
}

// A structure's initial state: a mode scaled to an amplitude at a node, a static force at a
// node and a uniform velocity, each along a unit direction.
InitialStateEffect ParseStructureInitialState(JsonObjectReader& s, const Scene& scene) {
  InitialStateEffect init;
  init.beam = -1;
  init.structure = StructureIndex(scene, s, "structure");
  const SceneStructure& structure = scene.structures[init.structure];
  init.direction_xyz = UnitVector3(s, "direction");
  ReadReleaseAmounts(s, init);
  if (init.static_force_n != 0.0 || init.tip_m != 0.0) {
    init.node = NodeOf(s, "node", structure);
    CheckFreeAlong(s, "direction", structure, init.node, init.direction_xyz);
  }
  return init;
}

InitialStateEffect ParseInitialState(JsonObjectReader& s, const Scene& scene) {
  if (s.Has("structure")) return ParseStructureInitialState(s, scene);
  InitialStateEffect init;
  init.beam = BeamIndex(scene, s, "beam");
  init.direction = Direction(s, "direction");
  ReadReleaseAmounts(s, init);
  if (init.static_force_n != 0.0) init.height_m = Height(scene, s, init.beam);
  return init;
}

void ParseEffects(const Json& effects, const std::string& path, const SceneFileAccess& access,
                  Scene& scene) {
  JsonObjectReader e(effects, path, "effects");
  if (const Json* md = e.Get("modal_damping")) {
    JsonObjectReader m(*md, path, e.PathOf("modal_damping"));
    scene.modal_damping = ParseModalDamping(m);
    m.Finish();
  }
  if (const Json* bm = e.Get("base_motion")) {
    JsonObjectReader b(*bm, path, e.PathOf("base_motion"));
    scene.base_motion = ParseBaseMotion(b, access);
    b.Finish();
  }
  EachItem(e, "static_forces",
           [&](JsonObjectReader& f) { scene.static_forces.push_back(ParseStaticForce(f, scene)); });
  EachItem(e, "initial_state", [&](JsonObjectReader& s) {
    scene.initial_state.push_back(ParseInitialState(s, scene));
  });
  e.Finish();
}

void ParseDt(JsonObjectReader& d, TimeStepRequest& dt) {
  if (d.Has("seconds")) {
    dt.dt_s = Positive(d, "seconds", 1.0);
  } else {
    const std::string rule = d.String("rule", "sharp");
    const auto parsed = DtRuleFromString(rule);
    if (!parsed) d.Fail("rule", "\"" + rule + "\" is not a rule: use \"paper\" or \"sharp\"");
    dt.rule = *parsed;
    dt.factor = InRange(d, "factor", dt.factor, 1e-6, 100.0);
  }
}

void ParseSolver(JsonObjectReader& r, Scene& scene) {
  JsonObjectReader s(RequiredObject(r, "solver"), r.File(), "solver");
  SceneSolver& solver = scene.solver;
  if (s.Has("r_ftrunc") && s.Has("f_trunc_hz"))
    s.Fail("f_trunc_hz", "give r_ftrunc or f_trunc_hz, not both");
  solver.r_ftrunc = InRange(s, "r_ftrunc", solver.r_ftrunc, 1.0, 1e5);
  if (s.Has("f_trunc_hz")) solver.f_trunc_hz = Positive(s, "f_trunc_hz", 1e7);
  if (const Json* v = s.Get("static_correction")) {
    if (!v->is_boolean()) s.Fail("static_correction", "expected true or false, got " + Shown(*v));
    solver.static_correction = v->get<bool>();
  }
  solver.end_time_s = Positive(s, "end_time_s", 1e4);
  if (const Json* dt = s.Get("dt")) {
    JsonObjectReader d(*dt, r.File(), s.PathOf("dt"));
    ParseDt(d, solver.dt);
    d.Finish();
  }
  const auto max_steps = TransientOptions{}.max_steps;
  if (solver.dt.dt_s && solver.end_time_s / *solver.dt.dt_s > static_cast<double>(max_steps)) {
    s.Fail("dt", "end_time_s / dt = " + Shown(Json(solver.end_time_s / *solver.dt.dt_s)) +
                     " steps: at most " + std::to_string(max_steps) + " are allowed");
  }
  s.Finish();
}

ObservedPoint ParseDisplacement(JsonObjectReader& d, const Scene& scene, NamesGiven& names) {
  ObservedPoint p;
  p.name = UniqueName(d, "name", "output", names);
  if (d.Has("structure")) {
    p.beam = -1;
    p.structure = StructureIndex(scene, d, "structure");
    p.node = NodeOf(d, "node", scene.structures[p.structure]);
    p.direction_xyz = UnitVector3(d, "direction");
    return p;
  }
  p.beam = BeamIndex(scene, d, "beam");
  p.height_m = Height(scene, d, p.beam);
  p.direction = Direction(d, "direction");
  if (p.direction == 1 && scene.planes == BendingPlanes::kPlanar)
    d.Fail("direction", "a planar scene bends in y only");
  return p;
}

// "no zone named ...", and for a name of a pin and the wrapper that the bundle gives per face
// ("pin_0-wrapper@0.9144", as versions before named every face), the faces' names.
std::string NoZoneNamed(const std::string& name, const Scene& scene) {
  std::string message = "no zone named \"" + name + "\"";
  const auto at = name.rfind('@');
  if (at == std::string::npos) return message;
  const std::string beams = name.substr(0, at) + "_", height = name.substr(at);
  std::vector<std::string> faces;
  for (const SceneZone& z : scene.zones) {
    if (z.name.size() <= beams.size() + height.size() || !z.name.starts_with(beams) ||
        !z.name.ends_with(height))
      continue;
    const std::string face =
        z.name.substr(beams.size(), z.name.size() - beams.size() - height.size());
    if (face.ends_with("deg")) faces.push_back("\"" + z.name + "\"");
  }
  if (faces.empty()) return message;
  return message + ": the pin meets the wrapper on several faces, each named by its direction: " +
         fmt::format("{}", fmt::join(faces, ", "));
}

// A list of zone names at `path` (each zone once) as zone indices.
std::vector<int> ZoneIndices(const Json& list, const std::string& file, const std::string& path,
                             const Scene& scene) {
  if (!list.is_array()) FailAt(file, path, "expected a list of zone names, got " + Shown(list));
  std::vector<int> zones;
  std::unordered_set<std::string> listed;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string at = path + "[" + std::to_string(i) + "]";
    if (!list[i].is_string()) FailAt(file, at, "expected a zone name, got " + Shown(list[i]));
    const std::string name = list[i].get<std::string>();
    const auto zone = std::find_if(scene.zones.begin(), scene.zones.end(),
                                   [&](const SceneZone& z) { return z.name == name; });
    if (zone == scene.zones.end()) FailAt(file, at, NoZoneNamed(name, scene));
    if (!listed.insert(name).second)
      FailAt(file, at, "zone \"" + name + "\" is listed twice; list each zone once");
    zones.push_back(static_cast<int>(zone - scene.zones.begin()));
  }
  return zones;
}

// outputs.impact_statistics (docs/physics.md §6): the counting, its convention and window, and
// the zones whose impacts are listed one by one.
void ParseImpactStatistics(JsonObjectReader& im, Scene& scene) {
  scene.outputs.impact_statistics = true;
  scene.outputs.impact_counting =
      ParseImpactCounting(im, scene.solver.end_time_s, "solver.end_time_s");
  if (const Json* listed = im.Get("impact_table")) {
    scene.outputs.impact_table_zones =
        ZoneIndices(*listed, im.File(), im.PathOf("impact_table"), scene);
  }
}

void ParseOutputs(const Json& outputs, const std::string& path, Scene& scene) {
  JsonObjectReader o(outputs, path, "outputs");
  NamesGiven names;
  EachItem(o, "displacements", [&](JsonObjectReader& d) {
    scene.outputs.displacements.push_back(ParseDisplacement(d, scene, names));
  });
  auto flag = [&](const char* key) {
    const Json* v = o.Get(key);
    if (v != nullptr && !v->is_boolean()) o.Fail(key, "expected true or false, got " + Shown(*v));
    return v != nullptr && v->get<bool>();
  };
  if (const Json* v = o.Get("contact_forces"); v != nullptr && v->is_array()) {
    scene.outputs.contact_forces = true;
    scene.outputs.contact_force_zones =
        ZoneIndices(*v, o.File(), o.PathOf("contact_forces"), scene);
  } else if (v != nullptr && !v->is_boolean()) {
    o.Fail("contact_forces", "expected true, false or a list of zone names, got " + Shown(*v));
  } else {
    scene.outputs.contact_forces = flag("contact_forces");
  }
  scene.outputs.energies = flag("energies");
  scene.outputs.max_contact_force = flag("max_contact_force");
  if (const Json* shocks = o.Get("shocks")) {
    JsonObjectReader sh(*shocks, path, o.PathOf("shocks"));
    scene.outputs.shocks = true;
    scene.outputs.rest_duration_s = Positive(sh, "rest_duration_s", 100.0);
    sh.Finish();
  }
  if (const Json* impacts = o.Get("impact_statistics")) {
    JsonObjectReader im(*impacts, path, o.PathOf("impact_statistics"));
    ParseImpactStatistics(im, scene);
    im.Finish();
  }
  scene.outputs.record_stride = o.Integer("record_stride", 1);
  if (scene.outputs.record_stride < 1 || scene.outputs.record_stride > 1'000'000)
    o.Fail("record_stride", "must lie in [1, 1e6]");
  o.Finish();
}

// wear: Archard's law over a life (docs/physics.md §6.3), for scenes whose zones slide.
void ParseWear(const Json& wear, const std::string& path, Scene& scene) {
  JsonObjectReader w(wear, path, "wear");
  WearLaw law;
  law.coefficient_m2_per_n = Positive(w, "coefficient_m2_per_n", 1.0);
  law.life_s = Positive(w, "life_s", 1e10);
  w.Finish();
  if (scene.planes == BendingPlanes::kPlanar) {
    FailAt(path, "wear",
           "a planar scene has no sliding at its zones: wear needs \"bending\": \"both\"");
  }
  if (!scene.outputs.impact_statistics) {
    FailAt(path, "wear",
           "wear needs outputs.impact_statistics, whose wear work rate it extends over life_s");
  }
  scene.wear = law;
}

}  // namespace

ImpactCounting ParseImpactCounting(JsonObjectReader& im, double end_s,
                                   const std::string& end_name) {
  ImpactCounting c;
  c.rest_duration_s = im.RequiredNumber("rest_duration_s");
  if (c.rest_duration_s < 0.0 || c.rest_duration_s > 100.0) {
    im.Fail("rest_duration_s", "value " + Shown(Json(c.rest_duration_s)) +
                                   " must lie in [0, 100] s (0: every "
                                   "contact is an impact)");
  }
  c.force_threshold_n = InRange(im, "force_threshold_n", 0.0, 0.0, 1e15);
  const std::string convention = im.String("convention", "shockmap");
  if (convention != "shockmap" && convention != "code_aster") {
    im.Fail("convention",
            "\"" + convention + "\" is not a convention: use \"shockmap\" or \"code_aster\"");
  }
  c.convention =
      convention == "code_aster" ? ImpactConvention::kCodeAster : ImpactConvention::kShockmap;
  std::tie(c.window_start_s, c.window_end_s) = Vector2(im, "window_s", {0.0, end_s}, false);
  if (!(c.window_start_s >= 0.0 && c.window_start_s < c.window_end_s && c.window_end_s <= end_s)) {
    im.Fail("window_s", "[" + Shown(Json(c.window_start_s)) + ", " + Shown(Json(c.window_end_s)) +
                            "] s must lie inside the run, 0 <= start < end <= " + end_name + " = " +
                            Shown(Json(end_s)));
  }
  return c;
}

Scene LoadScene(const std::string& path, const SceneFileAccess& access) {
  return ParseScene(ReadJsonFile(path), path, access);
}

Scene ParseScene(const nlohmann::json& json, const std::string& path,
                 const SceneFileAccess& access) {
  Scene scene;
  JsonObjectReader r(json, path, "");
  ParseHeader(r, scene);
  NamesGiven names;
  ParseStructures(r, access, scene, names);
  ParseBeams(r, scene, names);
  if (scene.beams.empty() && scene.structures.empty()) {
    r.Fail("beams",
           "a scene needs at least one beam (\"beams\" or \"bundle\") or one \"structures\"");
  }
  ParseZones(r, scene);
  if (const Json* effects = r.Get("effects")) ParseEffects(*effects, path, access, scene);
  ParseSolver(r, scene);
  if (const Json* outputs = r.Get("outputs")) ParseOutputs(*outputs, path, scene);
  if (const Json* wear = r.Get("wear")) ParseWear(*wear, path, scene);
  r.Finish();
  return scene;
}

}  // namespace shockmap
