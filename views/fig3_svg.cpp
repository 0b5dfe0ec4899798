#include "views/fig3_svg.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "views/html_text.h"

namespace shockmap {
namespace {

constexpr double kLeft = 64.0, kTop = 30.0, kPanelHeight = 160.0, kPanelGap = 46.0;
constexpr double kWidth = kLeft + static_cast<double>(kFig3Columns) + 16.0;
constexpr double kHeight = kTop + 2.0 * kPanelHeight + kPanelGap + 42.0;
constexpr const char* kReferenceColour = "#1f77b4";
constexpr const char* kNumericalColour = "#d62728";

struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void Add(double v) { lo = std::min(lo, v), hi = std::max(hi, v); }
  bool Empty() const { return !(lo <= hi); }
};

struct Box {
  double x, y, w, h;
};

// One panel's quantity: the curves' signals and how their values are shown.
struct Quantity {
  const char* name;  // data-quantity
  const char* label;
  double scale;  // SI value to the axis' unit.
  const UniformSignal* reference;
  const UniformSignal* numerical;  // nullptr when the run recorded nothing.
};

// 1, 2 or 5 times a power of ten, near span / 5.
double TickStep(double span) {
  const double raw = span / 5.0;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double norm = raw / magnitude;
  return magnitude * (norm < 1.5 ? 1.0 : norm < 3.5 ? 2.0 : norm < 7.5 ? 5.0 : 10.0);
}

// `r` widened to whole tick steps; a flat or empty range gets a span of its own.
Range Rounded(Range r) {
  if (r.Empty()) r = {0.0, 1.0};
  if (r.hi - r.lo <= 1e-12 * std::max(std::abs(r.lo), std::abs(r.hi))) {
    const double pad = r.lo == 0.0 ? 1.0 : 0.1 * std::abs(r.lo);
    r = {r.lo - pad, r.hi + pad};
  }
  const double step = TickStep(r.hi - r.lo);
  return {std::floor(r.lo / step) * step, std::ceil(r.hi / step) * step};
}

double Scaled(double v, double lo, double hi, double from, double length) {
  return from + (v - lo) / (hi - lo) * length;
}

std::vector<CurveVertex> Curve(const UniformSignal& s, double window_s, double scale) {
  std::vector<CurveVertex> curve = MinMaxPerColumn(s, 0.0, window_s, kFig3Columns);
  for (CurveVertex& v : curve) v.value *= scale;
  return curve;
}

std::string Polyline(const std::vector<CurveVertex>& curve, const Box& box, const Range& t,
                     const Range& y, const char* cls, const char* colour, const char* dash) {
  std::string points;
  for (const CurveVertex& v : curve) {
    fmt::format_to(std::back_inserter(points), "{}{:.1f},{:.1f}", points.empty() ? "" : " ",
                   Scaled(v.t_s, t.lo, t.hi, box.x, box.w),
                   Scaled(v.value, y.lo, y.hi, box.y + box.h, -box.h));
  }
  return fmt::format(
      "<polyline class=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"{}\"{} points=\"{}\"/>\n",
      cls, colour, dash[0] ? "1.2" : "1.8",
      dash[0] ? fmt::format(" stroke-dasharray=\"{}\"", dash) : "", points);
}

// Tick marks, their labels and a dotted grid line at each multiple of the step in `r`.
std::string Ticks(const Box& box, const Range& r, bool horizontal) {
  const double step = TickStep(r.hi - r.lo);
  std::string out;
  for (double k = std::ceil(r.lo / step - 1e-9); k * step <= r.hi + 1e-9 * step; k += 1.0) {
    const double v = k * step, at_zero = std::abs(v) < 1e-9 * step ? 0.0 : v;
    if (horizontal) {
      const double x = Scaled(v, r.lo, r.hi, box.x, box.w), bottom = box.y + box.h;
      fmt::format_to(std::back_inserter(out),
                     "<line class=\"grid\" x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{0:.1f}\" "
                     "y2=\"{2:.1f}\"/><text x=\"{0:.1f}\" y=\"{3:.1f}\" "
                     "text-anchor=\"middle\">{4:g}</text>\n",
                     x, box.y, bottom, bottom + 14.0, at_zero);
    } else {
      const double y = Scaled(v, r.lo, r.hi, box.y + box.h, -box.h);
      fmt::format_to(std::back_inserter(out),
                     "<line class=\"grid\" x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" "
                     "y2=\"{1:.1f}\"/><text x=\"{3:.1f}\" y=\"{4:.1f}\" "
                     "text-anchor=\"end\">{5:g}</text>\n",
                     box.x, y, box.x + box.w, box.x - 5.0, y + 4.0, at_zero);
    }
  }
  return out;
}

std::string Panel(const Quantity& q, const Box& box, double window_s, bool numerical_in_range) {
  const auto reference = Curve(*q.reference, window_s, q.scale);
  const auto numerical =
      q.numerical ? Curve(*q.numerical, window_s, q.scale) : std::vector<CurveVertex>{};
  Range values;
  for (const CurveVertex& v : reference) values.Add(v.value);
  if (numerical_in_range) {
    for (const CurveVertex& v : numerical) values.Add(v.value);
  }
  const Range y = Rounded(values), t{0.0, window_s};
  const std::string clip = fmt::format("fig3-clip-{}", q.name);
  return fmt::format(
      "<g class=\"panel\" data-quantity=\"{0}\" data-box=\"{1} {2} {3} {4}\" "
      "data-range=\"0 {5} {6} {7}\">\n<clipPath id=\"{8}\"><rect x=\"{1}\" y=\"{2}\" "
      "width=\"{3}\" height=\"{4}\"/></clipPath>\n{9}{10}<rect class=\"frame\" x=\"{1}\" "
      "y=\"{2}\" width=\"{3}\" height=\"{4}\"/>\n<g clip-path=\"url(#{8})\">\n{11}{12}</g>\n"
      "<text class=\"axis\" transform=\"translate({13:.1f} {14:.1f}) rotate(-90)\" "
      "text-anchor=\"middle\">{15}</text>\n</g>\n",
      q.name, box.x, box.y, box.w, box.h, fmt::format("{:.17g}", window_s),
      fmt::format("{:.17g}", y.lo), fmt::format("{:.17g}", y.hi), clip, Ticks(box, t, true),
      Ticks(box, y, false), Polyline(reference, box, t, y, "reference", kReferenceColour, ""),
      Polyline(numerical, box, t, y, "numerical", kNumericalColour, "5 3"), box.x - 46.0,
      box.y + box.h / 2.0, q.label);
}

std::string Legend(double right, double y) {
  return fmt::format(
      "<g class=\"legend\"><line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" "
      "stroke=\"{3}\" stroke-width=\"1.8\"/><text x=\"{4:.1f}\" y=\"{5:.1f}\">reference</text>"
      "<line x1=\"{6:.1f}\" y1=\"{1:.1f}\" x2=\"{7:.1f}\" y2=\"{1:.1f}\" stroke=\"{8}\" "
      "stroke-width=\"1.2\" stroke-dasharray=\"5 3\"/><text x=\"{9:.1f}\" y=\"{5:.1f}\">"
      "numerical</text></g>\n",
      right - 230.0, y, right - 206.0, kReferenceColour, right - 202.0, y + 4.0, right - 110.0,
      right - 86.0, kNumericalColour, right - 82.0);
}

}  // namespace

std::vector<CurveVertex> MinMaxPerColumn(const UniformSignal& signal, double t0_s, double t1_s,
                                         std::size_t columns) {
  std::vector<CurveVertex> out;
  std::size_t column = columns, low = 0, high = 0;  // The column being reduced, its extremes.
  auto flush = [&] {
    if (column == columns) return;
    for (std::size_t i : {std::min(low, high), std::max(low, high)}) {
      if (out.empty() || out.back().t_s != signal.TimeAt(i)) {
        out.push_back({signal.TimeAt(i), signal.values[i]});
      }
    }
  };
  for (std::size_t i = 0; i < signal.values.size(); ++i) {
    const double t = signal.TimeAt(i), v = signal.values[i];
    if (!std::isfinite(v)) break;
    if (t < t0_s || t > t1_s) continue;
    const auto c = std::min(columns - 1, static_cast<std::size_t>((t - t0_s) / (t1_s - t0_s) *
                                                                  static_cast<double>(columns)));
    if (c != column) {
      flush();
      column = c, low = high = i;
    }
    if (v < signal.values[low]) low = i;
    if (v > signal.values[high]) high = i;
  }
  flush();
  return out;
}

std::string Fig3Svg(const ComparisonResult& result, double window_s) {
  const TransientResult& h = result.histories;
  const bool recorded = !h.displacement_m.empty() && !h.contact_force_n.empty();
  const bool in_range = result.status != RunStatus::kDiverged;
  const Quantity tip{"tip", "tip displacement (mm)", 1e3, &result.reference->tip_m,
                     recorded ? &h.displacement_m[0] : nullptr};
  const Quantity force{"force", "contact force (kN)", 1e-3, &result.reference->force_n,
                       recorded ? &h.contact_force_n[0] : nullptr};
  const double plot_width = static_cast<double>(kFig3Columns);
  const Box top{kLeft, kTop, plot_width, kPanelHeight};
  const Box bottom{kLeft, kTop + kPanelHeight + kPanelGap, plot_width, kPanelHeight};
  return fmt::format(
      "<svg class=\"fig3\" xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 {0} {1}\" "
      "role=\"img\" aria-label=\"Fig. 3: tip displacement and contact force, numerical against "
      "reference\">\n{2}{3}{4}<text class=\"axis\" x=\"{5:.1f}\" y=\"{6:.1f}\" "
      "text-anchor=\"middle\">time (s)</text>\n</svg>\n",
      kWidth, kHeight, Legend(kLeft + plot_width, kTop - 14.0), Panel(tip, top, window_s, in_range),
      Panel(force, bottom, window_s, in_range), kLeft + plot_width / 2.0, kHeight - 6.0);
}

std::string Fig3Note(const ComparisonResult& result, double window_s) {
  const std::string status =
      ToString(result.status) + (result.message.empty() ? "" : ": " + HtmlEscaped(result.message));
  const std::vector<double> none;
  const TransientResult& h = result.histories;
  const std::vector<double>& tip = h.displacement_m.empty() ? none : h.displacement_m[0].values;
  const auto finite =
      std::find_if(tip.begin(), tip.end(), [](double v) { return !std::isfinite(v); });
  if (finite == tip.begin()) {
    return fmt::format("The run ({}) recorded no finite sample: only the reference is drawn.",
                       status);
  }
  if (result.status == RunStatus::kOk) return "";
  if (result.status != RunStatus::kDiverged && result.status != RunStatus::kFailed) {
    return fmt::format("The run reached the end of the window ({}).", status);
  }
  const auto last = static_cast<std::size_t>(finite - tip.begin()) - 1;
  return fmt::format(
      "The run stopped ({}) at t = {:.4g} s of the {:.4g} s window: drawn up to its last finite "
      "sample{}.",
      status, h.displacement_m[0].TimeAt(last), window_s,
      result.status == RunStatus::kDiverged ? ", within the reference's range" : "");
}

}  // namespace shockmap
