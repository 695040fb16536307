#pragma once
// A log-log plot of relMSE against render time for the Stats panel: the measured curve, a
// slope -1 guide through its first point (where an unbiased estimator's error goes), and the
// reference's own noise, below which no curve can fall.
#include <vector>

#include "render/util/error_curve.h"

namespace pt::editor {

void drawErrorPlot(const std::vector<ErrorPoint>& curve, double referenceNoiseRelMse, float height);

}  // namespace pt::editor
