#include "views/outcome_glyphs.h"

#include <fmt/format.h>

#include <algorithm>

#include "views/html_text.h"

namespace shockmap {

std::string MarkerShape(CellMarker marker, double x, double y, double w, double h) {
  const double cx = x + w / 2, cy = y + h / 2, r = std::min(9.0, 0.3 * std::min(w, h));
  const char* style = "fill=\"none\" stroke=\"#000\" stroke-width=\"2\" pointer-events=\"none\"";
  switch (marker) {
    case CellMarker::kCross:
      return fmt::format(
          "<path class=\"marker\" d=\"M{:.1f} {:.1f}L{:.1f} {:.1f}M{:.1f} {:.1f}L{:.1f} "
          "{:.1f}\" {}/>",
          cx - r, cy - r, cx + r, cy + r, cx - r, cy + r, cx + r, cy - r, style);
    case CellMarker::kSquare:
      return fmt::format(
          "<rect class=\"marker\" x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" "
          "{}/>",
          cx - r, cy - r, 2 * r, 2 * r, style);
    case CellMarker::kCircle:
      return fmt::format("<circle class=\"marker\" cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"{:.1f}\" {}/>",
                         cx, cy, r, style);
    case CellMarker::kDiamond:
      return fmt::format(
          "<path class=\"marker\" d=\"M{:.1f} {:.1f}L{:.1f} {:.1f}L{:.1f} {:.1f}L{:.1f} {:.1f}Z\" "
          "{}/>",
          cx, cy - r, cx + r, cy, cx, cy + r, cx - r, cy, style);
    case CellMarker::kNone:
      break;
  }
  return "";
}

namespace {

// The legend's sample of a category.
std::string LegendSample(const OutcomeCategory& category) {
  switch (category.marker) {
    case CellMarker::kCross:
      return "<b class=\"marker\">&#215;</b>";
    case CellMarker::kSquare:
      return "<b class=\"marker\">&#9633;</b>";
    case CellMarker::kCircle:
      return "<b class=\"marker\">&#9675;</b>";
    case CellMarker::kDiamond:
      return "<b class=\"marker\">&#9671;</b>";
    case CellMarker::kNone:
      break;
  }
  return fmt::format("<i style=\"background:{}\"></i>", category.colour);
}

}  // namespace

std::string OutcomeLegendItems(const std::vector<bool>& present) {
  std::string items;
  for (std::size_t i = 0; i < present.size(); ++i) {
    if (!present[i]) continue;
    items += fmt::format("<span>{}{}</span>", LegendSample(OutcomeCategories()[i]),
                         HtmlEscaped(OutcomeCategories()[i].label));
  }
  return items;
}

}  // namespace shockmap
