// The report's sections for an ensemble study (declared in views/html_report.h): the sizing
// statistics of `shockmap sizing` (docs/ensembles.md, "Sizing") as sortable tables, the
// settings' agreement, the impact statistics, the wear sizing and the sizing pictures; first,
// for an advice check (`check-advice`), its verdict.

#include <fmt/format.h>

#include <algorithm>
#include <iterator>
#include <nlohmann/json.hpp>
#include <optional>

#include "core/input_error.h"
#include "db/report_queries.h"
#include "db/stored_json.h"
#include "specs/advice_check_study.h"
#include "views/advice_check_text.h"
#include "views/html_report.h"
#include "views/html_text.h"
#include "views/setting_names.h"
#include "views/sizing_plots.h"
#include "views/sizing_tables.h"

namespace shockmap {
namespace {

// `table` with the columns named in `moved` (those it has, in that order) just after its column
// `after`, the others in their order.
Table MovedAfter(const Table& table, const std::string& after,
                 const std::vector<std::string>& moved) {
  std::vector<std::size_t> order;
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    if (std::ranges::count(moved, table.columns[c]) == 0) order.push_back(c);
  }
  auto at = std::ranges::find(order, table.ColumnIndex(after).value_or(table.columns.size()));
  if (at != order.end()) ++at;
  for (const std::string& name : moved) {
    if (const auto c = table.ColumnIndex(name)) at = std::next(order.insert(at, *c));
  }
  Table reordered;
  for (std::size_t c : order) reordered.columns.push_back(table.columns[c]);
  for (const auto& row : table.rows) {
    auto& cells = reordered.rows.emplace_back();
    for (std::size_t c : order) cells.push_back(row[c]);
  }
  return reordered;
}

// A force sizing table (HottestZoneTable, ZoneTable) with what a zone is sized by beside it, on
// the first screen: the sizing quantile with its interval, Wilks' limit, the agreement with the
// refined setting; the other quantiles and statistics after them.
Table SizedByFirst(const Table& table, const EnsembleSizing& s) {
  const std::string q = fmt::format("p{:g}", 100 * s.options.quantile);
  return MovedAfter(table, "family",
                    {q + "_n", q + "_lower_n", q + "_upper_n", "wilks_order", "wilks_limit_n",
                     "wilks_members_needed", "agrees_with_refined"});
}

// A sizing table of the report, its settings named (views/setting_names.h); with one setting,
// the caption names it once instead of a column repeating it on every row.
std::string SettingTable(const Table& sizing_table, const EnsembleSizing& s, const Scene& scene,
                         const std::string& id, const std::string& caption) {
  Table table = WithSettingNames(sizing_table, s, scene);
  const std::optional<std::string> setting = TakeSingleSetting(table);
  return SortableTable(table, id,
                       setting ? caption + ", at the one setting: " + *setting : caption);
}

// What the study is and what the tables count, from the stored study file.
std::string About(const EnsembleSizing& s, const std::string& spec_json) {
  const auto spec = nlohmann::json::parse(spec_json, nullptr, false);
  std::string html;
  if (spec.is_object() && spec.contains("description") && spec["description"].is_string()) {
    html += "<p>" + HtmlEscaped(spec["description"].get<std::string>()) + "</p>\n";
  }
  html += fmt::format(
      "<p>P{0:g} of the members' largest force per zone, with {1:g} % intervals from order "
      "statistics (an empty end: too few members to bound that side), Wilks' upper tolerance "
      "limit and a bootstrap interval as a cross-check: the numbers of <code>shockmap sizing "
      "--quantile {2:g} --confidence {3:g}</code>. The zones come in the families an engineer "
      "sizes: the pin-pin wires, the duct pad, the pins against the wrapper (and any other); the "
      "hottest zone of a family has the family's highest estimate at the state's refined "
      "setting, so that the duct pad does not hide the wires. Its design value is Wilks' limit, "
      "which needs the members given beside it.</p>\n",
      100 * s.options.quantile, 100 * s.options.confidence, s.options.quantile,
      s.options.confidence);
  if (s.pending + s.failed > 0) {
    html +=
        fmt::format("<p>{} members pending, {} not ok: not counted.</p>\n", s.pending, s.failed);
  }
  if (s.superseded > 0) {
    html += fmt::format("<p>{} stored members the study file no longer has: not counted.</p>\n",
                        s.superseded);
  }
  return html;
}

std::string Agreement(const EnsembleSizing& s, const Scene& scene) {
  const std::vector<std::string> lines = AgreementLines(s, scene);
  if (lines.empty()) return "<p>One numerical setting: nothing to compare.</p>\n";
  std::string html = fmt::format(
      "<p>A setting agrees with the refined one at a zone where their {:g} % intervals of the "
      "sizing quantile, each widened by {:g} % of the refined estimate, overlap.</p>\n<ul>\n",
      100 * s.options.confidence, 100 * s.options.tolerance);
  for (const std::string& line : lines) html += "<li>" + HtmlEscaped(line) + "</li>\n";
  return html + "</ul>\n";
}

// The means over members of every zone's impact statistics; no rows when none were streamed.
Table ImpactTable(const EnsembleSizing& s) {
  Table t;
  t.columns = {"state",
               "setting",
               "zone",
               "members",
               "impacts_per_s",
               "rebounds_per_impact",
               "mean_impact_duration_s",
               "contact_time_fraction",
               "mean_force_n",
               "rms_force_n",
               "impulse_n_s",
               "wear_work_rate_w"};
  for (const GroupSizing& g : s.groups) {
    for (const ZoneSizing& z : g.zones) {
      if (!z.impacts) continue;
      const MeanImpacts& m = *z.impacts;
      t.rows.push_back({g.state, g.setting_json + (g.refined ? " (refined)" : ""), z.name,
                        static_cast<std::int64_t>(z.members), m.impacts_per_s,
                        m.rebounds_per_impact, m.mean_impact_duration_s, m.contact_time_fraction,
                        m.mean_force_n, m.rms_force_n, m.impulse_n_s,
                        m.wear_work_rate_w ? TableCell(*m.wear_work_rate_w) : TableCell()});
    }
  }
  return t;
}

std::string Impacts(const EnsembleSizing& s, const Scene& scene) {
  const Table table = ImpactTable(s);
  if (table.rows.empty()) {
    return "<p>No member streamed impact statistics (the study file has no "
           "<code>impact_statistics</code>).</p>\n";
  }
  return "<p>Each zone's impact statistics (docs/physics.md §6), averaged over the members; "
         "the wear work rate where the scene bends in both planes.</p>\n" +
         SettingTable(table, s, scene, "impacts-table",
                      "Mean impact statistics per clearance state, setting and zone");
}

std::string Wear(const EnsembleSizing& s, const Scene& scene) {
  const Table table = WearTable(s);
  if (table.rows.empty()) {
    return "<p>No member has a wear volume (the scene has no <code>wear</code> law, or its "
           "zones do not slide: it bends in one plane, or the study file has no "
           "<code>impact_statistics</code>).</p>\n";
  }
  return fmt::format(
             "<p>Archard's wear volume of each zone over the scene's wear life (docs/physics.md "
             "§6.3): P{0:g} over the members with its {1:g} % order-statistic interval, Wilks' "
             "upper tolerance limit (the design value) and the mean, beside the P{0:g} of the "
             "largest force: the numbers of <code>shockmap sizing --wear</code>.</p>\n",
             100 * s.options.quantile, 100 * s.options.confidence) +
         SettingTable(table, s, scene, "wear-table",
                      "Wear volume per clearance state, setting and zone");
}

std::string Pictures(const ReportContext& ctx, const EnsembleSizing& s,
                     const StoredEnsemble& stored, const Scene& scene) {
  std::string html;
  for (const SizingPicture& p : DrawSizingPictures(s, stored, scene, ctx.dir / "sizing")) {
    html += EmbeddedFigure(p.image, p.caption, PlotFiles(p.image, ctx.dir));
  }
  return html;
}

// The advice's verdict when the study is an advice check (specs/advice_check_study.h): what
// `check-advice` prints, at the quantile and tolerance it judged with; nullopt for any other
// ensemble.
std::optional<ReportSection> AdviceCheckSection(const ReportContext& ctx,
                                                const StoredEnsemble& stored) {
  const StoredCell cell{ctx.database_path, "study " + ctx.study, "spec_json"};
  struct Ladder {
    AdviceCheckRecord record;
    nlohmann::json settings;
  };
  const auto ladder = ReadStoredJson(
      cell, stored.spec_json, [&](const nlohmann::json& spec) -> std::optional<Ladder> {
        if (!spec.contains("advice_check")) return std::nullopt;
        Ladder l;
        l.settings = spec.at("settings");
        if (!l.settings.is_array())
          ThrowCorruptCell(cell, "settings: not a list of the ladder's rungs");
        try {
          l.record = ParseAdviceCheckRecord(spec.at("advice_check"), ctx.database_path,
                                            "advice_check", l.settings.size());
        } catch (const InputError& e) {
          ThrowCorruptCell(cell, e.what());
        }
        return l;
      });
  if (!ladder) return std::nullopt;
  SizingOptions options;
  options.quantile = ladder->record.quantile;
  options.tolerance = ladder->record.tolerance;
  const AdviceCheck check = CheckAdvice(SizeEnsemble(stored, ctx.study, options), ladder->settings,
                                        ladder->record.factors, ladder->record.advised);
  return ReportSection{
      "advice-check", "Does the advice hold?",
      "<p class=\"verdict\">" + HtmlEscaped(AdviceVerdict(check, options.quantile)) + "</p>\n" +
          SortableTable(AdviceCheckTable(check), "advice-check-table",
                        "Every rung's sizing quantile per clearance state and zone family, the "
                        "advised and the converged rung named in their headers")};
}

}  // namespace

std::vector<ReportSection> EnsembleSections(const ReportContext& ctx, const StoredEnsemble& stored,
                                            const Scene& scene) {
  const EnsembleSizing sizing = SizeEnsemble(stored, ctx.study, SizingOptions{});
  const ReportTables tables = LoadReportTables(ctx.database_path, ctx.study);
  std::vector<ReportSection> sections;
  if (auto advice = AdviceCheckSection(ctx, stored)) sections.push_back(std::move(*advice));
  std::vector<ReportSection> sizing_sections = {
      {"sizing-hottest", "Sizing force of the hottest zone of each family",
       About(sizing, stored.spec_json) +
           SettingTable(SizedByFirst(HottestZoneTable(sizing, false), sizing), sizing, scene,
                        "sizing-hottest-table",
                        "The hottest zone of each family per clearance state and setting")},
      {"sizing-zones", "Sizing statistics per zone",
       SettingTable(SizedByFirst(ZoneTable(sizing), sizing), sizing, scene, "sizing-zones-table",
                    "Every zone per clearance state and setting")},
      {"settings-agreement", "Settings against the refined one", Agreement(sizing, scene)},
      {"impacts", "Impact statistics", Impacts(sizing, scene)},
      {"wear-sizing", "Wear sizing", Wear(sizing, scene)},
      {"sizing-pictures", "Sizing pictures", Pictures(ctx, sizing, stored, scene)},
      {"provenance", "Provenance",
       SortableTable(tables.provenance, "provenance-table", "Runs of the study")},
      {"study-file", "Study file", Preformatted(tables.spec_json)},
  };
  std::ranges::move(sizing_sections, std::back_inserter(sections));
  return sections;
}

}  // namespace shockmap
