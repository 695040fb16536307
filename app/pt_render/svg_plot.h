#pragma once
// A log-log line plot as a self-contained SVG document, written by hand (no plotting library):
// decade grid lines with labels, minor ticks, one polyline per series with a legend, and an
// optional guide line of a given slope (e.g. -1, the rate of an unbiased Monte Carlo estimate).
#include <string>
#include <utility>
#include <vector>

namespace pt::cli {

struct PlotSeries {
    std::string name;
    std::vector<std::pair<double, double>> points;  // (x, y); points with x or y <= 0 are left out
};

struct LogLogPlot {
    std::string title, xLabel, yLabel;
    std::vector<PlotSeries> series;
    double guideSlope = 0.0;  // 0: no guide; else drawn through the first point of the first series
    std::string guideLabel;
};

std::string svgLogLogPlot(const LogLogPlot& plot);

}  // namespace pt::cli
