#include "views/sweep_outcome_map.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <optional>
#include <set>

#include "views/html_text.h"
#include "views/map_grid.h"
#include "views/outcome_glyphs.h"

namespace shockmap {
namespace {

std::optional<double> ValueAt(const SceneParameters& parameters, const std::string& path) {
  for (const auto& [p, v] : parameters) {
    if (p == path) return v;
  }
  return std::nullopt;
}

// The swept paths: the one across, the one up ("" when a single parameter is swept), then the
// others, each of which splits the points into maps.
struct Axes {
  std::string x, y;
  std::vector<std::string> facets;
};

Axes AxesOf(const SceneParameters& swept) {
  std::vector<std::string> paths;
  for (const auto& [path, value] : swept) paths.push_back(path);
  Axes a;
  auto take = [&](const std::string& preferred) {
    auto it = std::ranges::find(paths, preferred);
    if (it == paths.end()) it = paths.begin();
    if (it == paths.end()) return std::string();
    std::string path = *it;
    paths.erase(it);
    return path;
  };
  a.x = take("solver.r_ftrunc");
  a.y = take("solver.dt.factor");
  a.facets = paths;
  return a;
}

// Whether the point has a value for every swept path (a stored row may lack one).
bool Sets(const SweepPoint& p, const Axes& axes) {
  auto has = [&](const std::string& path) { return ValueAt(p.parameters, path).has_value(); };
  return has(axes.x) && (axes.y.empty() || has(axes.y)) && std::ranges::all_of(axes.facets, has);
}

std::string Scored(const std::optional<double>& v) {
  return v ? fmt::format("{:.4g}", *v) : "not scored";
}

// A cell's hover text: the point's swept values, scores and status.
std::string Title(const SweepPoint& p, const OutcomeCategory& category) {
  std::string text;
  for (const auto& [path, value] : p.parameters) text += fmt::format("{} = {:g}, ", path, value);
  for (const ScoreDefinition& score : Scores()) {
    text += fmt::format("{} = {}, ", score.label, Scored(p.scored.scores[score.name]));
  }
  return text + fmt::format("status {} ({})", ToString(p.scored.status), category.label);
}

struct CellLayout {
  double left = 120, top = 10, cell_w, cell_h;
  std::vector<double> xs, ys;  // Ascending; ys = {0} when nothing is swept up.

  double X(double v) const {
    return left + cell_w * static_cast<double>(std::ranges::find(xs, v) - xs.begin());
  }
  // Rows grow upwards: the largest value on top.
  double Y(double v) const {
    return top + cell_h * static_cast<double>(ys.end() - std::ranges::find(ys, v) - 1);
  }
  double Width() const { return cell_w * static_cast<double>(xs.size()); }
  double Height() const { return cell_h * static_cast<double>(ys.size()); }
};

std::string Cell(const SweepPoint& p, const Axes& axes, const CellLayout& l,
                 const CriteriaOptions& thresholds) {
  const OutcomeCategory& category = OutcomeCategories()[OutcomeCategoryOf(p.scored, thresholds)];
  const double x = l.X(*ValueAt(p.parameters, axes.x));
  const double y = l.Y(axes.y.empty() ? 0.0 : *ValueAt(p.parameters, axes.y));
  std::string values;
  for (const auto& [path, value] : p.parameters) {
    values += fmt::format("{}{}={:g}", values.empty() ? "" : ";", path, value);
  }
  return fmt::format(
      "<rect class=\"cell\" x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" "
      "fill=\"{}\" data-point-id=\"{}\" data-parameters=\"{}\" data-outcome=\"{}\">"
      "<title>{}</title></rect>{}\n",
      x, y, l.cell_w, l.cell_h, category.colour, p.scored.point_id, HtmlEscaped(values),
      HtmlEscaped(category.label), HtmlEscaped(Title(p, category)),
      MarkerShape(category.marker, x, y, l.cell_w, l.cell_h));
}

std::string AxisLabels(const Axes& axes, const CellLayout& l) {
  std::string svg;
  const double bottom = l.top + l.Height();
  for (double v : l.xs) {
    svg += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{:g}</text>\n",
                       l.X(v) + l.cell_w / 2, bottom + 18, v);
  }
  svg += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{}</text>\n",
                     l.left + l.Width() / 2, bottom + 40, HtmlEscaped(axes.x));
  if (axes.y.empty()) return svg;
  for (double v : l.ys) {
    svg += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"end\">{:g}</text>\n",
                       l.left - 8, l.Y(v) + l.cell_h / 2 + 5, v);
  }
  svg += fmt::format(
      "<text transform=\"translate(20 {:.1f}) rotate(-90)\" text-anchor=\"middle\">{}</text>\n",
      l.top + l.Height() / 2, HtmlEscaped(axes.y));
  return svg;
}

std::string Map(const std::vector<const SweepPoint*>& points, const Axes& axes,
                const CriteriaOptions& thresholds, const std::string& id) {
  std::set<double> xs, ys;
  for (const SweepPoint* p : points) {
    xs.insert(*ValueAt(p->parameters, axes.x));
    ys.insert(axes.y.empty() ? 0.0 : *ValueAt(p->parameters, axes.y));
  }
  CellLayout l;
  l.xs.assign(xs.begin(), xs.end());
  l.ys.assign(ys.begin(), ys.end());
  l.cell_w = std::min(120.0, 720.0 / static_cast<double>(l.xs.size()));
  l.cell_h = std::min(60.0, 360.0 / static_cast<double>(l.ys.size()));
  std::string cells;
  for (const SweepPoint* p : points) cells += Cell(*p, axes, l, thresholds);
  return fmt::format(
      "<svg class=\"sweep-map\" id=\"{}\" viewBox=\"0 0 {:.0f} {:.0f}\" "
      "xmlns=\"http://www.w3.org/2000/svg\">\n{}{}</svg>\n",
      HtmlEscaped(id), l.left + l.Width() + 20, l.top + l.Height() + 50, cells,
      AxisLabels(axes, l));
}

std::string Legend(const std::vector<SweepPoint>& points, const CriteriaOptions& thresholds) {
  std::vector<bool> present(OutcomeCategories().size(), false);
  for (const SweepPoint& p : points) present[OutcomeCategoryOf(p.scored, thresholds)] = true;
  const std::string items = OutcomeLegendItems(present);
  return "<p class=\"legend\">" + items + "</p>\n";
}

}  // namespace

std::string HtmlSweepOutcomeMaps(const std::vector<SweepPoint>& points,
                                 const CriteriaOptions& thresholds, const std::string& id) {
  if (points.empty()) return "";
  const Axes axes = AxesOf(std::ranges::max_element(points, {}, [](const SweepPoint& p) {
                             return p.parameters.size();
                           })->parameters);
  std::map<std::vector<double>, std::vector<const SweepPoint*>> maps;  // By the facets' values.
  std::size_t incomplete = 0;
  for (const SweepPoint& p : points) {
    if (!Sets(p, axes)) {
      ++incomplete;
      continue;
    }
    std::vector<double> key;
    for (const std::string& path : axes.facets) key.push_back(*ValueAt(p.parameters, path));
    maps[key].push_back(&p);
  }
  std::string html;
  if (incomplete > 0) {
    html +=
        fmt::format("<p>{} stored points lack a swept value and are not drawn.</p>\n", incomplete);
  }
  int k = 0;
  for (const auto& [key, members] : maps) {
    std::string heading;
    for (std::size_t i = 0; i < key.size(); ++i) {
      heading += fmt::format("{}{} = {:g}", i ? ", " : "", axes.facets[i], key[i]);
    }
    if (!heading.empty()) html += "<h3>" + HtmlEscaped(heading) + "</h3>\n";
    html += Map(members, axes, thresholds, fmt::format("{}-{}", id, k++));
  }
  return html + Legend(points, thresholds);
}

}  // namespace shockmap
