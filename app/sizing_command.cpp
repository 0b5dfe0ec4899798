#include "app/sizing_command.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>

#include "app/flag_checks.h"
#include "core/input_error.h"
#include "db/ensemble_members.h"
#include "db/schema.h"
#include "db/study_database.h"
#include "formats/json_reader.h"
#include "formats/output_file.h"
#include "formats/scene_file.h"
#include "formats/table_output.h"
#include "views/setting_names.h"
#include "views/sizing_plots.h"
#include "views/sizing_tables.h"
#include "workflows/stored_ensemble_scene.h"

namespace shockmap {
namespace {

struct SizingFlags {
  std::string database_path = kDefaultDatabasePath;
  std::string study;
  SizingOptions options;
  std::string out;
  std::string format = "table";
  bool wear = false;  // The wear volume's table instead of the force's.
};

// The study named, or the database's only ensemble study.
std::string ResolveEnsemble(Connection& db, const std::string& study) {
  if (!study.empty()) return study;
  const std::vector<std::string> names = EnsembleStudies(db);
  if (names.size() == 1) return names.front();
  if (names.empty()) throw InputError(db.Path() + " holds no ensemble study");
  std::string listed;
  for (const std::string& n : names) listed += (listed.empty() ? "" : ", ") + n;
  throw InputError("STUDY: " + db.Path() + " holds several ensemble studies; name one of " +
                   listed);
}

// Lines beneath a table fit the terminal as the table does: `text` wrapped at spaces to
// kLineWidth columns, indented by two, its continuations by four.
constexpr std::size_t kLineWidth = 110;

void PrintWrapped(const std::string& text, std::size_t indent = 2) {
  std::string line(indent, ' ');
  std::size_t begin = 0;
  while (begin < text.size()) {
    std::size_t end = text.find(' ', begin);
    if (end == std::string::npos) end = text.size();
    const std::string word = text.substr(begin, end - begin);
    if (line.size() > indent && line.size() + 1 + word.size() > kLineWidth) {
      fmt::print("{}\n", line);
      line = std::string(indent + 2, ' ');
    } else if (line.size() > indent) {
      line += ' ';
    }
    line += word;
    begin = end + 1;
  }
  fmt::print("{}\n", line);
}

// The terminal's table with its settings named; a study of one setting has it said once above
// the table instead of in every row.
Table ForTerminal(Table table, const EnsembleSizing& s, const Scene& scene) {
  std::set<std::string> settings;
  for (const GroupSizing& g : s.groups) settings.insert(g.setting_json);
  if (settings.size() > 1) return WithSettingNames(std::move(table), s, scene);
  fmt::print("  setting: {}\n", SettingName(s.groups.front(), scene, false));
  const auto column = std::ranges::find(table.columns, "setting") - table.columns.begin();
  if (static_cast<std::size_t>(column) == table.columns.size()) return table;
  table.columns.erase(table.columns.begin() + column);
  for (auto& row : table.rows) row.erase(row.begin() + column);
  return table;
}

// The hottest zone of each family per state and setting, then how each setting compares and
// what the members cost.
void PrintTable(const EnsembleSizing& s, const StoredEnsemble& stored, const Scene& scene) {
  PrintWrapped(
      fmt::format("study {}: P{:g} of the largest force per zone, {:g} % intervals (order "
                  "statistics; bootstrap as a cross-check), settings agreeing within {:g} %",
                  s.study, 100 * s.options.quantile, 100 * s.options.confidence,
                  100 * s.options.tolerance),
      0);
  if (s.pending + s.failed > 0) {
    fmt::print("  {} members pending, {} not ok: not counted\n", s.pending, s.failed);
  }
  if (s.superseded > 0) {
    fmt::print("  {} stored members the study file no longer has: not counted\n", s.superseded);
  }
  WriteTable(ForTerminal(HottestZoneTable(s, true), s, scene), TableFormat::kTable, std::cout);
  for (const std::string& line : SizingFootnotes(s, false)) PrintWrapped(line);
  for (const GroupSizing& g : s.groups) {
    const std::vector<double> forces = ZoneForces(stored, g, g.hottest);
    const WidthScaling scaling = MeanWidthScaling(forces, s.options);
    if (scaling.mean_width.empty()) continue;
    PrintWrapped(fmt::format(
        "{} {}: the hottest zone's interval narrows as members^{:.2f} (its mean width "
        "over 400 resamples of {} to {} members; the members in order: ^{:.2f})",
        g.state, SettingName(g, scene, false), scaling.slope, scaling.mean_width.front().first,
        scaling.mean_width.back().first, WidthSlope(SizingConvergence(forces, s.options))));
  }
  for (const std::string& line : AgreementLines(s, scene)) PrintWrapped(line);
}

// The most worn zone of each state and setting, when the members have wear volumes (every
// zone with --format csv|json).
void PrintWearTable(const EnsembleSizing& s, const Scene& scene) {
  const Table table = MostWornZoneTable(s);
  if (table.rows.empty()) {
    fmt::print(
        "study {}: no member has a wear volume (the scene has no wear law, or its zones "
        "do not slide)\n",
        s.study);
    return;
  }
  PrintWrapped(fmt::format("study {}: P{:g} of the wear volume over the scene's wear life, the "
                           "most worn zone of each state and setting, {:g} % intervals; Wilks' "
                           "limit, the design value",
                           s.study, 100 * s.options.quantile, 100 * s.options.confidence),
               0);
  WriteTable(ForTerminal(table, s, scene), TableFormat::kTable, std::cout);
  for (const std::string& line : SizingFootnotes(s, true)) PrintWrapped(line);
}

void Size(const SizingFlags& f) {
  if (!f.out.empty()) CheckPathLength(f.out, "--out");
  Connection db(f.database_path, Connection::Mode::kReadOnly);
  CheckSchema(db);
  const std::string study = ResolveEnsemble(db, f.study);
  const StoredEnsemble stored = CurrentMembers(ReadEnsemble(db, study));
  const EnsembleSizing sizing = SizeEnsemble(stored, study, f.options);
  const Scene scene = StoredEnsembleScene(stored, f.database_path, study);
  if (f.format == "table") {
    f.wear ? PrintWearTable(sizing, scene) : PrintTable(sizing, stored, scene);
  } else {
    WriteTable(f.wear ? WearTable(sizing) : ZoneTable(sizing), *TableFormatFromString(f.format),
               std::cout);
  }
  if (f.out.empty()) return;
  CreateOutputDirectory(f.out);
  for (const auto& [name, table] :
       {std::pair{"sizing_hottest.csv", HottestZoneTable(sizing, false)},
        std::pair{"sizing_zones.csv", ZoneTable(sizing)},
        std::pair{"sizing_wear.csv", WearTable(sizing)}}) {
    AtomicFile file(std::filesystem::path(f.out) / name);
    WriteTable(WithSettingNames(table, sizing, scene), TableFormat::kCsv, file.Stream());
    file.Commit();
  }
  const auto pictures = DrawSizingPictures(sizing, stored, scene, f.out);
  std::ostream& note = f.format == "table" ? std::cout : std::cerr;
  note << "tables written to " << f.out
       << "/sizing_hottest.csv, sizing_zones.csv and sizing_wear.csv\n";
  for (const auto& p : pictures) note << "picture written to " << p.image.string() << '\n';
}

}  // namespace

void AddSizingCommand(CLI::App& app) {
  auto flags = std::make_shared<SizingFlags>();
  CLI::App* sizing = app.add_subcommand(
      "sizing",
      "Sizing statistics of an ensemble study: per zone and for the hottest zone of each family "
      "(pin-pin wire, duct pad, pin-wrapper), per clearance state and setting, P50/P95/P99 of the "
      "largest force with order-statistic intervals, "
      "Wilks' upper tolerance limit, a bootstrap cross-check, impact statistics, and each "
      "setting against the refined one; with --wear, the same of the wear volume");
  sizing->add_option("STUDY", flags->study, "study name (default: the database's only ensemble)");
  AddDatabaseFlag(sizing, flags->database_path);
  sizing->add_option("--quantile", flags->options.quantile, "the sizing quantile, in (0, 1)")
      ->capture_default_str()
      ->check(StrictlyBetween(0.0, 1.0));
  sizing
      ->add_option("--confidence", flags->options.confidence,
                   "confidence of the intervals and of Wilks' limit, in (0, 1)")
      ->capture_default_str()
      ->check(StrictlyBetween(0.0, 1.0));
  sizing
      ->add_option("--tolerance", flags->options.tolerance,
                   "a setting agrees with the refined one where their intervals, widened by "
                   "this fraction of the refined estimate, overlap")
      ->capture_default_str()
      ->check(FiniteIn(0.0, false, 1.0));
  sizing->add_option("--hottest-among", flags->options.hottest_among,
                     "the hottest zone is the highest of the zones whose name holds this text, "
                     "e.g. -pin_ for the wires between pins (default: every zone)");
  sizing->add_option("--out", flags->out, "folder for the CSV tables and the pictures");
  sizing
      ->add_option("--format", flags->format,
                   "standard output: each family's hottest zone as a table, "
                   "or every zone as CSV or JSON")
      ->capture_default_str()
      ->check(CLI::IsMember({"table", "csv", "json"}));
  sizing->add_flag("--wear", flags->wear,
                   "the wear volume's sizing instead of the force's (the quantile of the volume "
                   "over the scene's wear life, its interval, Wilks' limit, the mean): the most "
                   "worn zone per state and setting as a table, every zone as CSV or JSON");
  sizing->callback([flags] { Size(*flags); });
}

}  // namespace shockmap
