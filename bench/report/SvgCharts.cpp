#include "SvgCharts.h"

#include "Html.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace pb::bench {

namespace {

const char* kPalette[] = {"#4e79a7", "#f28e2b", "#e15759", "#76b7b2", "#59a14f",
                          "#edc948", "#b07aa1", "#ff9da7", "#9c755f", "#bab0ac"};

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f", v);
    return buf;
}

std::string tickText(double v) {
    char buf[32];
    double a = std::fabs(v);
    // Three significant digits tell neighbouring ticks (0.01, 0.015) apart at any scale.
    std::snprintf(buf, sizeof buf, a == 0 ? "0" : a >= 1000 ? "%.0f" : "%.3g", v);
    return buf;
}

// About five round ticks covering [lo, hi].
std::vector<double> ticks(double lo, double hi) {
    double span = hi - lo;
    if (!(span > 0)) return {lo};
    double step = std::pow(10.0, std::floor(std::log10(span / 5)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (span / (step * m) <= 6) {
            step *= m;
            break;
        }
    std::vector<double> out;
    for (double t = std::ceil(lo / step) * step; t <= hi + step * 1e-9; t += step)
        out.push_back(std::fabs(t) < step * 1e-9 ? 0.0 : t);
    return out;
}

} // namespace

std::vector<size_t> paretoFront(const std::vector<ParetoPoint>& p) {
    std::vector<size_t> order(p.size());
    for (size_t i = 0; i < p.size(); ++i)
        order[i] = i;
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        return p[a].deltaMs != p[b].deltaMs ? p[a].deltaMs < p[b].deltaMs : p[a].flip < p[b].flip;
    });
    std::vector<size_t> front;
    double best = INFINITY;
    for (size_t i : order)
        if (p[i].flip < best) {
            front.push_back(i);
            best = p[i].flip;
        }
    return front;
}

std::string paretoSvg(const std::vector<ParetoPoint>& pts, const std::string& ciLabel) {
    const double W = 720, H = 420, L = 70, R = 30, T = 20, B = 50;
    double x0 = 0, x1 = 0, y1 = 0;
    for (const auto& p : pts) {
        x0 = std::min({x0, p.deltaMs, p.ciLow});
        x1 = std::max({x1, p.deltaMs, p.ciHigh});
        y1 = std::max(y1, p.flip);
    }
    double pad = (x1 - x0) * 0.08 + 1e-6;
    x0 -= pad;
    x1 += pad;
    y1 = y1 > 0 ? y1 * 1.12 : 0.01;
    auto X = [&](double v) { return L + (v - x0) / (x1 - x0) * (W - L - R); };
    auto Y = [&](double v) { return H - B - v / y1 * (H - T - B); };
    std::ostringstream s;
    s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
      << "\" viewBox=\"0 0 " << W << " " << H << "\" role=\"img\" aria-label=\"Pareto chart\" "
      << "font-family=\"sans-serif\" font-size=\"11\">\n";
    s << "<rect x=\"" << L << "\" y=\"" << T << "\" width=\"" << W - L - R << "\" height=\""
      << H - T - B << "\" fill=\"#fafafa\" stroke=\"#999\"/>\n";
    for (double t : ticks(x0, x1))
        s << "<line x1=\"" << num(X(t)) << "\" y1=\"" << T << "\" x2=\"" << num(X(t)) << "\" y2=\""
          << H - B << "\" stroke=\"" << (t == 0 ? "#666" : "#e3e3e3") << "\"/><text x=\""
          << num(X(t)) << "\" y=\"" << H - B + 14 << "\" text-anchor=\"middle\">" << tickText(t)
          << "</text>\n";
    for (double t : ticks(0, y1))
        s << "<line x1=\"" << L << "\" y1=\"" << num(Y(t)) << "\" x2=\"" << W - R << "\" y2=\""
          << num(Y(t)) << "\" stroke=\"#e3e3e3\"/><text x=\"" << L - 6 << "\" y=\"" << num(Y(t) + 4)
          << "\" text-anchor=\"end\">" << tickText(t) << "</text>\n";
    s << "<text x=\"" << (L + W - R) / 2 << "\" y=\"" << H - 12
      << "\" text-anchor=\"middle\">Δ frame ms vs reference, " << htmlEscape(ciLabel)
      << " (left = faster)</text>\n"
      << "<text transform=\"translate(16," << (T + H - B) / 2
      << ") rotate(-90)\" text-anchor=\"middle\">LDR-FLIP mean vs reference (up = worse)</text>\n";
    std::vector<size_t> front = paretoFront(pts);
    if (front.size() > 1) {
        s << "<polyline fill=\"none\" stroke=\"#59a14f\" stroke-dasharray=\"5,4\" points=\"";
        for (size_t k = 0; k < front.size(); ++k) {
            const auto& p = pts[front[k]];
            if (k > 0) s << num(X(p.deltaMs)) << "," << num(Y(pts[front[k - 1]].flip)) << " ";
            s << num(X(p.deltaMs)) << "," << num(Y(p.flip)) << " ";
        }
        s << "\"/>\n";
    }
    int profileIndex = 0;
    for (const auto& p : pts) {
        double x = X(p.deltaMs), y = Y(p.flip);
        s << "<line x1=\"" << num(X(p.ciLow)) << "\" y1=\"" << num(y) << "\" x2=\""
          << num(X(p.ciHigh)) << "\" y2=\"" << num(y) << "\" stroke=\""
          << (p.isProfile ? "#4e79a7" : "#aaa") << "\"/>\n";
        if (p.isProfile) {
            // Alternate above/below so profiles at the same spot stay readable.
            double ly = (profileIndex++ % 2) ? y + 16 : y - 7;
            s << "<circle cx=\"" << num(x) << "\" cy=\"" << num(y)
              << "\" r=\"5\" fill=\"#4e79a7\"/><text x=\"" << num(x + 7) << "\" y=\"" << num(ly)
              << "\" font-weight=\"bold\">" << htmlEscape(p.label) << "</text>\n";
        } else {
            s << "<circle cx=\"" << num(x) << "\" cy=\"" << num(y)
              << "\" r=\"4\" fill=\"#fff\" stroke=\"#888\"><title>" << htmlEscape(p.label)
              << "</title></circle><text x=\"" << num(x) << "\" y=\"" << num(y + 3)
              << "\" fill=\"#555\" font-size=\"8\" text-anchor=\"middle\">" << htmlEscape(p.tag)
              << "</text>\n";
        }
    }
    s << "</svg>\n";
    return s.str();
}

std::string stackedBarsSvg(const std::vector<StackedBar>& bars) {
    std::vector<std::string> names;
    double maxTotal = 0;
    for (const auto& b : bars) {
        maxTotal = std::max(maxTotal, b.total);
        for (const auto& [n, ms] : b.segments)
            if (std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
    }
    if (!(maxTotal > 0)) maxTotal = 1;
    const double W = 720, L = 120, R = 80, T = 40, row = 30;
    const double H = T + row * double(bars.size()) + 30;
    auto colour = [&](const std::string& n) {
        size_t i = size_t(std::find(names.begin(), names.end(), n) - names.begin());
        return kPalette[i % (sizeof kPalette / sizeof *kPalette)];
    };
    std::ostringstream s;
    s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
      << "\" viewBox=\"0 0 " << W << " " << H << "\" role=\"img\" aria-label=\"per-pass times\" "
      << "font-family=\"sans-serif\" font-size=\"11\">\n";
    double lx = L;
    for (const auto& n : names) {
        s << "<rect x=\"" << num(lx) << "\" y=\"8\" width=\"12\" height=\"12\" fill=\"" << colour(n)
          << "\"/><text x=\"" << num(lx + 16) << "\" y=\"18\">" << htmlEscape(n) << "</text>\n";
        lx += 24 + 7.0 * double(n.size());
    }
    const double scale = (W - L - R) / maxTotal;
    for (size_t i = 0; i < bars.size(); ++i) {
        const auto& b = bars[i];
        double y = T + row * double(i), x = L;
        s << "<text x=\"" << L - 6 << "\" y=\"" << num(y + 17) << "\" text-anchor=\"end\">"
          << htmlEscape(b.label) << "</text>\n";
        for (const auto& [n, ms] : b.segments) {
            s << "<rect x=\"" << num(x) << "\" y=\"" << num(y + 4) << "\" width=\""
              << num(std::max(0.0, ms * scale)) << "\" height=\"" << row - 8 << "\" fill=\""
              << colour(n) << "\"><title>" << htmlEscape(n) << ": " << tickText(ms)
              << " ms</title></rect>\n";
            x += ms * scale;
        }
        s << "<text x=\"" << num(L + b.total * scale + 6) << "\" y=\"" << num(y + 17) << "\">"
          << tickText(b.total) << " ms</text>\n";
    }
    s << "<text x=\"" << L << "\" y=\"" << num(H - 8)
      << "\" fill=\"#666\">median ms per pass (exclusive); bar end = median frame</text>\n";
    s << "</svg>\n";
    return s.str();
}

} // namespace pb::bench
