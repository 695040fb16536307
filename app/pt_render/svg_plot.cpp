#include "pt_render/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace pt::cli {

namespace {

constexpr double kWidth = 720, kHeight = 480;
constexpr double kLeft = 80, kRight = 190, kTop = 40, kBottom = 60;  // margins; the legend is on the right
const char* const kColors[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                               "#9467bd", "#8c564b", "#e377c2", "#17becf"};

std::string escapeXml(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '<')
            out += "&lt;";
        else if (c == '>')
            out += "&gt;";
        else if (c == '&')
            out += "&amp;";
        else if (c == '"')
            out += "&quot;";
        else
            out += c;
    }
    return out;
}

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", v);
    return text;
}

// The whole decades [lo, hi] (as exponents) that contain every positive value.
struct DecadeRange {
    int lo = 0, hi = 1;
};

DecadeRange decadesOf(const std::vector<double>& values) {
    double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
    for (double v : values) {
        if (v > 0 && std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
    }
    if (!(hi > 0)) return {};
    DecadeRange r{int(std::floor(std::log10(lo))), int(std::ceil(std::log10(hi)))};
    if (r.hi <= r.lo) r.hi = r.lo + 1;
    return r;
}

// Maps values to pixels along one log axis.
struct LogAxis {
    DecadeRange decades;
    double from, to;  // pixel positions of 10^lo and 10^hi
    double operator()(double v) const {
        const double t = (std::log10(v) - decades.lo) / double(decades.hi - decades.lo);
        return from + t * (to - from);
    }
};

// "10" with the exponent raised, e.g. 10^-3.
std::string decadeLabel(int exponent) {
    if (exponent == 0) return "1";
    if (exponent == 1) return "10";
    return "10<tspan dy=\"-7\" font-size=\"10\">" + std::to_string(exponent) + "</tspan>";
}

std::string axes(const LogAxis& x, const LogAxis& y) {
    std::string svg;
    for (int e = x.decades.lo; e <= x.decades.hi; ++e) {
        const double px = x(std::pow(10.0, e));
        svg += "<line x1=\"" + number(px) + "\" y1=\"" + number(kTop) + "\" x2=\"" + number(px) + "\" y2=\"" +
               number(kHeight - kBottom) + "\" class=\"grid\"/>\n";
        svg += "<text x=\"" + number(px) + "\" y=\"" + number(kHeight - kBottom + 22) +
               "\" text-anchor=\"middle\" class=\"tick\">" + decadeLabel(e) + "</text>\n";
        for (int m = 2; m <= 9 && e < x.decades.hi; ++m) {
            const double mx = x(m * std::pow(10.0, e));
            svg += "<line x1=\"" + number(mx) + "\" y1=\"" + number(kHeight - kBottom) + "\" x2=\"" +
                   number(mx) + "\" y2=\"" + number(kHeight - kBottom - 5) + "\" class=\"axis\"/>\n";
        }
    }
    for (int e = y.decades.lo; e <= y.decades.hi; ++e) {
        const double py = y(std::pow(10.0, e));
        svg += "<line x1=\"" + number(kLeft) + "\" y1=\"" + number(py) + "\" x2=\"" +
               number(kWidth - kRight) + "\" y2=\"" + number(py) + "\" class=\"grid\"/>\n";
        svg += "<text x=\"" + number(kLeft - 8) + "\" y=\"" + number(py + 4) +
               "\" text-anchor=\"end\" class=\"tick\">" + decadeLabel(e) + "</text>\n";
        for (int m = 2; m <= 9 && e < y.decades.hi; ++m) {
            const double my = y(m * std::pow(10.0, e));
            svg += "<line x1=\"" + number(kLeft) + "\" y1=\"" + number(my) + "\" x2=\"" + number(kLeft + 5) +
                   "\" y2=\"" + number(my) + "\" class=\"axis\"/>\n";
        }
    }
    svg += "<rect x=\"" + number(kLeft) + "\" y=\"" + number(kTop) + "\" width=\"" +
           number(kWidth - kLeft - kRight) + "\" height=\"" + number(kHeight - kTop - kBottom) +
           "\" class=\"frame\"/>\n";
    return svg;
}

std::string legendEntry(size_t index, const std::string& name, const std::string& lineClass,
                        const std::string& color) {
    const double y = kTop + 10 + 20.0 * double(index), x = kWidth - kRight + 15;
    return "<line x1=\"" + number(x) + "\" y1=\"" + number(y) + "\" x2=\"" + number(x + 24) + "\" y2=\"" +
           number(y) + "\" class=\"" + lineClass + "\" stroke=\"" + color + "\"/>\n<text x=\"" +
           number(x + 30) + "\" y=\"" + number(y + 4) + "\" class=\"legend\">" + escapeXml(name) +
           "</text>\n";
}

}  // namespace

std::string svgLogLogPlot(const LogLogPlot& plot) {
    std::vector<double> xs, ys;
    for (const PlotSeries& s : plot.series) {
        for (const auto& [x, y] : s.points) xs.push_back(x), ys.push_back(y);
    }
    const LogAxis x{decadesOf(xs), kLeft, kWidth - kRight};
    const LogAxis y{decadesOf(ys), kHeight - kBottom, kTop};
    std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + number(kWidth) + "\" height=\"" +
                      number(kHeight) + "\" viewBox=\"0 0 " + number(kWidth) + " " + number(kHeight) +
                      "\">\n";
    svg +=
        "<style>text{font-family:sans-serif;font-size:13px} .tick{font-size:12px} .grid{stroke:#ddd} "
        ".axis{stroke:#444} .frame{fill:none;stroke:#444} .series{fill:none;stroke-width:2} "
        ".guide{stroke-dasharray:6 4;stroke-width:1.5} .legend{font-size:12px}</style>\n";
    svg += "<clipPath id=\"plot-area\"><rect x=\"" + number(kLeft) + "\" y=\"" + number(kTop) +
           "\" width=\"" + number(kWidth - kLeft - kRight) + "\" height=\"" +
           number(kHeight - kTop - kBottom) + "\"/></clipPath>\n";
    svg += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    svg += "<text x=\"" + number((kLeft + kWidth - kRight) / 2) + "\" y=\"24\" text-anchor=\"middle\">" +
           escapeXml(plot.title) + "</text>\n";
    svg += axes(x, y);
    svg += "<text x=\"" + number((kLeft + kWidth - kRight) / 2) + "\" y=\"" + number(kHeight - 14) +
           "\" text-anchor=\"middle\">" + escapeXml(plot.xLabel) + "</text>\n";
    svg += "<text transform=\"translate(22 " + number((kTop + kHeight - kBottom) / 2) +
           ") rotate(-90)\" text-anchor=\"middle\">" + escapeXml(plot.yLabel) + "</text>\n";
    size_t legendRow = 0;
    for (size_t i = 0; i < plot.series.size(); ++i) {
        const std::string color = kColors[i % (sizeof kColors / sizeof kColors[0])];
        std::string points;
        for (const auto& [px, py] : plot.series[i].points) {
            if (px > 0 && py > 0) points += number(x(px)) + "," + number(y(py)) + " ";
        }
        svg += "<polyline class=\"series\" stroke=\"" + color + "\" clip-path=\"url(#plot-area)\" points=\"" +
               points + "\"/>\n";
        svg += legendEntry(legendRow++, plot.series[i].name, "series", color);
    }
    if (plot.guideSlope != 0.0 && !plot.series.empty() && !plot.series[0].points.empty()) {
        // y = y0 (x / x0)^slope from the left edge of the plot to the right one.
        const auto [x0, y0] = plot.series[0].points.front();
        const double xa = std::pow(10.0, x.decades.lo), xb = std::pow(10.0, x.decades.hi);
        const double ya = y0 * std::pow(xa / x0, plot.guideSlope),
                     yb = y0 * std::pow(xb / x0, plot.guideSlope);
        svg += "<line class=\"guide\" stroke=\"#666\" clip-path=\"url(#plot-area)\" x1=\"" + number(x(xa)) +
               "\" y1=\"" + number(y(ya)) + "\" x2=\"" + number(x(xb)) + "\" y2=\"" + number(y(yb)) +
               "\"/>\n";
        svg += legendEntry(legendRow++, plot.guideLabel, "guide", "#666");
    }
    svg += "</svg>\n";
    return svg;
}

}  // namespace pt::cli
