#pragma once
// How the report's SVG maps draw an outcome category (views/map_grid.h): the marker over a
// cell whose run did not end well, and the category's sample in a legend. Shared by the study
// maps (views/html_validity_map.h) and the scene sweep's map (views/sweep_outcome_map.h).

#include <string>
#include <vector>

#include "views/map_grid.h"

namespace shockmap {

// The marker centred on the cell (x, y, w, h in SVG units), drawn in black and transparent to
// the pointer so that hovering reaches the cell; "" for CellMarker::kNone.
std::string MarkerShape(CellMarker marker, double x, double y, double w, double h);

// The legend's items, one <span> per category present, in legend order: its marker as a
// character, or a swatch of its fill, and its label;
// `present` is indexed as OutcomeCategories().
std::string OutcomeLegendItems(const std::vector<bool>& present);

}  // namespace shockmap
