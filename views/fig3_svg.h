#pragma once
// The paper's Fig. 3 for one point as inline SVG: two panels over the scored window, the tip
// displacement and the contact force of the numerical run against the reference's, with axes,
// ticks, labels and a legend. Curves are decimated to the extreme samples of each of
// kFig3Columns columns, in time order, so that every peak survives: at most 2 kFig3Columns
// vertices a curve.

#include <cstddef>
#include <string>
#include <vector>

#include "compare/comparison.h"
#include "core/uniform_signal.h"

namespace shockmap {

inline constexpr std::size_t kFig3Columns = 400;  // The plot's width in SVG units.

// A vertex of a decimated curve: time (s) and value.
struct CurveVertex {
  double t_s = 0.0, value = 0.0;
};

// The samples of `signal` in [t0_s, t1_s] up to its first non-finite value (where a diverged
// run stopped), reduced to the smallest and the largest of each of `columns` equal time columns,
// in time order (one vertex where they coincide).
std::vector<CurveVertex> MinMaxPerColumn(const UniformSignal& signal, double t0_s, double t1_s,
                                         std::size_t columns);

// The <svg class="fig3"> of `result` (histories recorded, reference attached) over
// [0, window_s]. Each panel is a <g class="panel" data-quantity="tip|force"> whose
// data-box="x y width height" and data-range="t0 t1 y0 y1" map its polylines' points
// (class "reference" and "numerical", SVG units) back to seconds and to mm or kN. A run that
// stopped early is drawn up to its last finite sample; a diverged one within the reference's
// range.
std::string Fig3Svg(const ComparisonResult& result, double window_s);

// A sentence for a run that did not reach the end of the window, or recorded nothing: where it
// stopped and what the figure draws of it (HTML, escaped); empty for a run that ran to the end.
std::string Fig3Note(const ComparisonResult& result, double window_s);

}  // namespace shockmap
