#include "formats/scene_outputs.h"

#include <algorithm>
#include <tuple>

#include "formats/comparison_json.h"
#include "formats/output_file.h"
#include "formats/output_values.h"

namespace shockmap {
namespace {

using Json = nlohmann::json;

Json ZoneJson(const Scene& scene, const SceneRun& run, std::size_t i) {
  const SceneZone& z = scene.zones[i];
  Json zone = {{"name", z.name},
               {"beam", scene.SideName(z, false)},
               {"against", scene.SideName(z, true)},
               {"height_m", z.height_m},
               {"position_m", {z.y_m, z.z_m}}};
  if (!run.max_contact_force_n.empty()) zone["max_force_n"] = run.max_contact_force_n[i];
  const auto recorded =
      std::find(run.recorded_zones.begin(), run.recorded_zones.end(), static_cast<int>(i));
  if (!run.shocks.empty() && recorded != run.recorded_zones.end()) {
    const auto& shocks =
        run.shocks[static_cast<std::size_t>(recorded - run.recorded_zones.begin())];
    double impulse = 0.0, peak = 0.0;
    int rebounds = 0;
    for (const Shock& s : shocks) {
      impulse += s.impulse_n_s;
      peak = std::max(peak, s.peak_force_n);
      rebounds += s.Rebounds();
    }
    zone["shocks"] = {{"count", shocks.size()},
                      {"rebounds", rebounds},
                      {"largest_peak_n", peak},
                      {"total_impulse_n_s", impulse},
                      {"first", shocks.empty() ? Json(nullptr) : ShockToJson(shocks.front())}};
  }
  if (!run.impact_statistics.empty()) {
    zone["impact_statistics"] = ImpactStatisticsToJson({run.impact_statistics[i], scene.wear});
  }
  return zone;
}

template <typename Row>
void WriteCsv(const std::filesystem::path& file, const std::string& header, std::size_t rows,
              Row row, std::vector<std::filesystem::path>& written) {
  AtomicFile out(file);
  out.Stream() << header << '\n';
  for (std::size_t i = 0; i < rows; ++i) row(out.Stream(), i);
  out.Commit();
  written.push_back(file);
}

}  // namespace

Json ImpactStatisticsToJson(const ZoneImpactStatistics& zone) {
  // The columns of impact_statistics.csv, but the window as one pair and the wear volume only
  // where the scene has a wear law; whether a wear work rate was measured and how many impacts
  // the run lists.
  const ImpactStatistics& s = zone.statistics;
  Json json = JsonObjectOf(zone, kImpactStatisticsColumns);
  json.erase("window_start_s");
  json.erase("window_end_s");
  if (!zone.wear) json.erase("wear_volume_m3");
  json["window_s"] = {s.window_start_s, s.window_end_s};
  json["wear_available"] = s.wear_available;
  json["impacts_listed"] = s.records.size();
  return json;
}

Json SceneRunToJson(const Scene& scene, const SceneRun& run) {
  Json json = JsonObjectOf(SceneRunOutput{scene, run}, kSceneRunColumns);
  if (!scene.structures.empty()) json["structures"] = scene.structures.size();
  if (scene.wear) {
    json["wear"] = {{"coefficient_m2_per_n", scene.wear->coefficient_m2_per_n},
                    {"life_s", scene.wear->life_s}};
  }
  if (run.reached_bound) {
    const ReachedBound& b = *run.reached_bound;
    const bool closed = b.deepest_zone >= 0;
    json["power_law_bound"] = {
        {"exceeded", b.exceeded},
        {"dt_sharp_at_reached_penetrations_s", b.dt_sharp_reached_s},
        {"deepest_zone", closed ? Json(scene.zones[b.deepest_zone].name) : Json(nullptr)},
        {"largest_penetration_m", closed ? Json(b.largest_penetration_m) : Json(nullptr)},
        {"bound_penetration_m", closed ? Json(b.bound_penetration_m) : Json(nullptr)}};
  }
  if (!run.max_contact_force_n.empty()) {
    const auto largest =
        std::max_element(run.max_contact_force_n.begin(), run.max_contact_force_n.end());
    const std::size_t at = static_cast<std::size_t>(largest - run.max_contact_force_n.begin());
    json["largest_contact_force"] = {{"zone", scene.zones[at].name}, {"force_n", *largest}};
  }
  if (!run.max_contact_force_n.empty() || !run.shocks.empty() || !run.impact_statistics.empty()) {
    Json zones = Json::array();
    for (std::size_t i = 0; i < scene.zones.size(); ++i) zones.push_back(ZoneJson(scene, run, i));
    json["zone_results"] = std::move(zones);
  }
  return json;
}

namespace {

// displacements.csv: the time, then each displacement output's displacement and velocity.
void WriteDisplacements(const Scene& scene, const TransientResult& r,
                        const std::filesystem::path& dir,
                        std::vector<std::filesystem::path>& written) {
  std::string header = "t_s";
  for (const auto& p : scene.outputs.displacements) {
    header += "," + CsvField(p.name + "_m") + "," + CsvField(p.name + "_velocity_m_s");
  }
  WriteCsv(
      dir / "displacements.csv", header, r.displacement_m[0].values.size(),
      [&](std::ostream& out, std::size_t i) {
        out << r.displacement_m[0].TimeAt(i);
        for (std::size_t p = 0; p < r.displacement_m.size(); ++p)
          out << ',' << r.displacement_m[p].values[i] << ',' << r.velocity_m_s[p].values[i];
        out << '\n';
      },
      written);
}

// contact_forces.csv: the time, then each recorded zone's force.
void WriteContactForces(const Scene& scene, const SceneRun& run, const std::filesystem::path& dir,
                        std::vector<std::filesystem::path>& written) {
  const TransientResult& r = run.result;
  std::string header = "t_s";
  for (int z : run.recorded_zones) header += "," + CsvField(scene.zones[z].name + "_n");
  WriteCsv(
      dir / "contact_forces.csv", header, r.contact_force_n[0].values.size(),
      [&](std::ostream& out, std::size_t i) {
        out << r.contact_force_n[0].TimeAt(i);
        for (const auto& f : r.contact_force_n) out << ',' << f.values[i];
        out << '\n';
      },
      written);
}

// A CSV of `rows` rows whose columns are `columns`, row i those of value(i).
template <typename Columns, typename Value>
void WriteColumnsCsv(const std::filesystem::path& file, const Columns& columns, std::size_t rows,
                     Value value, std::vector<std::filesystem::path>& written) {
  WriteCsv(
      file, CsvHeaderOf(columns), rows,
      [&](std::ostream& out, std::size_t i) {
        WriteCsvFields(out, OutputValuesOf(value(i), columns));
        out << '\n';
      },
      written);
}

// shocks.csv: one row per shock of every recorded zone, the zone's name first.
void WriteShocks(const Scene& scene, const SceneRun& run, const std::filesystem::path& dir,
                 std::vector<std::filesystem::path>& written) {
  std::vector<std::pair<std::size_t, const Shock*>> rows;
  for (std::size_t i = 0; i < run.shocks.size(); ++i) {
    for (const Shock& s : run.shocks[i]) rows.emplace_back(run.recorded_zones[i], &s);
  }
  WriteCsv(
      dir / "shocks.csv", "zone," + CsvHeaderOf(kShockColumns), rows.size(),
      [&](std::ostream& out, std::size_t i) {
        out << CsvField(scene.zones[rows[i].first].name) << ',';
        WriteCsvFields(out, OutputValuesOf(*rows[i].second, kShockColumns));
        out << '\n';
      },
      written);
}

// impact_statistics.csv: one row per zone, its name first.
void WriteImpactStatistics(const Scene& scene, const SceneRun& run,
                           const std::filesystem::path& dir,
                           std::vector<std::filesystem::path>& written) {
  WriteCsv(
      dir / "impact_statistics.csv", "zone," + CsvHeaderOf(kImpactStatisticsColumns),
      scene.zones.size(),
      [&](std::ostream& out, std::size_t i) {
        out << CsvField(scene.zones[i].name) << ',';
        WriteCsvFields(out,
                       OutputValuesOf(ZoneImpactStatistics{run.impact_statistics[i], scene.wear},
                                      kImpactStatisticsColumns));
        out << '\n';
      },
      written);
}

// impacts.csv: one row per impact of the zones the scene lists, the zone's name and the
// impact's number (from 1) first.
void WriteImpactTable(const Scene& scene, const SceneRun& run, const std::filesystem::path& dir,
                      std::vector<std::filesystem::path>& written) {
  std::vector<std::tuple<int, int, const ImpactRecord*>> rows;
  for (int z : scene.outputs.impact_table_zones) {
    const auto& records = run.impact_statistics[static_cast<std::size_t>(z)].records;
    for (std::size_t k = 0; k < records.size(); ++k)
      rows.emplace_back(z, static_cast<int>(k) + 1, &records[k]);
  }
  WriteCsv(
      dir / "impacts.csv", "zone,impact," + CsvHeaderOf(kImpactRecordColumns), rows.size(),
      [&](std::ostream& out, std::size_t i) {
        const auto& [zone, number, record] = rows[i];
        out << CsvField(scene.zones[static_cast<std::size_t>(zone)].name) << ',' << number << ',';
        WriteCsvFields(out, OutputValuesOf(*record, kImpactRecordColumns));
        out << '\n';
      },
      written);
}

}  // namespace

std::vector<std::filesystem::path> WriteSceneOutputs(const Scene& scene, const SceneRun& run,
                                                     const std::filesystem::path& dir) {
  CreateOutputDirectory(dir);
  std::vector<std::filesystem::path> written;
  const TransientResult& r = run.result;
  if (!r.displacement_m.empty()) WriteDisplacements(scene, r, dir, written);
  if (!r.contact_force_n.empty()) WriteContactForces(scene, run, dir, written);
  if (!r.energy.kinetic_j.values.empty()) {
    WriteColumnsCsv(
        dir / "energies.csv", kEnergyColumns, r.energy.kinetic_j.values.size(),
        [&](std::size_t i) {
          return EnergySample{r.energy, i};
        },
        written);
  }
  if (!run.max_contact_force_n.empty()) {
    WriteColumnsCsv(
        dir / "max_contact_force.csv", kLargestForceColumns, scene.zones.size(),
        [&](std::size_t i) {
          return ZoneLargestForce{scene, scene.zones[i], run.max_contact_force_n[i]};
        },
        written);
  }
  if (!run.shocks.empty()) WriteShocks(scene, run, dir, written);
  if (!run.impact_statistics.empty()) WriteImpactStatistics(scene, run, dir, written);
  if (!run.impact_statistics.empty() && !scene.outputs.impact_table_zones.empty()) {
    WriteImpactTable(scene, run, dir, written);
  }
  const auto summary = dir / "summary.json";
  WriteFileAtomically(summary, SceneRunToJson(scene, run).dump(2) + '\n');
  written.push_back(summary);
  return written;
}

}  // namespace shockmap
