#include "app/cli/survey_charts.h"

#include "app/cli/eval_charts.h"

#include "core/mission/planner_kinds.h"

#ifdef PF_CLI_HAS_QT
#include <QColor>
#include <QFont>
#include <QImage>
#include <QPainter>
#include <QPainterPath>
#include <QPolygonF>
#include <QString>
#endif

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pf::cli {

#ifndef PF_CLI_HAS_QT

int writeSurveyCharts(const std::vector<mission::SurveyComparison>&, const std::string&, std::string*) { return 0; }

#else

namespace {

constexpr int kPanel = 620;    // drawing square per plan, pixels
constexpr int kTitle = 58;     // text lines above it
constexpr int kPad = 14;

// Local metres -> panel pixels, north up, the same scale for x and y.
struct View {
    geo::Box box;
    double scale = 1;
    QPointF origin;
    QPointF map(const geo::Vec2& p) const {
        return {origin.x() + (p.x() - box.min.x()) * scale, origin.y() + (box.max.y() - p.y()) * scale};
    }
};

void grow(geo::Box& b, const geo::Vec2& p) {
    b.min = b.min.cwiseMin(p);
    b.max = b.max.cwiseMax(p);
}

QPainterPath pathOf(const View& v, const geo::MultiPolygon& mp) {
    QPainterPath path;
    path.setFillRule(Qt::OddEvenFill);
    auto ring = [&](const geo::Ring& r) {
        QPolygonF q;
        for (const auto& p : r)
            q << v.map(p);
        if (!q.isEmpty())
            q << q.front();
        path.addPolygon(q);
    };
    for (const auto& poly : mp) {
        ring(poly.outer);
        for (const auto& h : poly.holes)
            ring(h);
    }
    return path;
}

std::string num(const char* f, double v) {
    if (!std::isfinite(v))
        return "-";
    char b[64];
    std::snprintf(b, sizeof b, f, v);
    return b;
}

// A scale bar of a round length, about a fifth of the panel.
void drawScale(QPainter& p, const View& v, const QRectF& panel) {
    const double target = panel.width() / 5 / v.scale;
    const double mag = std::pow(10.0, std::floor(std::log10(target)));
    double len = mag;
    for (double f : {1.0, 2.0, 5.0})
        if (f * mag <= target)
            len = f * mag;
    const QPointF a(panel.left() + 12, panel.bottom() - 14), b(a.x() + len * v.scale, a.y());
    p.setPen(QPen(Qt::black, 2));
    p.drawLine(a, b);
    p.drawLine(a + QPointF(0, -4), a + QPointF(0, 4));
    p.drawLine(b + QPointF(0, -4), b + QPointF(0, 4));
    p.drawText(QRectF(a.x(), a.y() - 20, 200, 16), Qt::AlignLeft, QString::fromStdString(num("%.0f m", len)));
}

void drawPlan(QPainter& p, const mission::SurveyComparison& c, const View& v, const QRectF& panel,
              const mission::SurveyMeasures& m, const QColor& colour, const std::string& l1, const std::string& l2) {
    p.save();
    p.setClipRect(panel.adjusted(-2, -2, 2, 2));
    p.fillPath(pathOf(v, c.localArea), QColor(232, 245, 233));
    p.setPen(QPen(QColor(46, 125, 50), 1.5));
    p.drawPath(pathOf(v, c.localArea));
    if (!c.margins.empty()) {
        p.fillPath(pathOf(v, c.margins), QColor(255, 204, 128, 150));
        geo::MultiPolygon zones(c.localZones.begin(), c.localZones.end());
        p.fillPath(pathOf(v, zones), QColor(229, 57, 53, 200));
        p.setPen(QPen(QColor(183, 28, 28), 1));
        p.drawPath(pathOf(v, zones));
    }
    if (m.ok) {
        QPolygonF line;
        for (const auto& q : m.path)
            line << v.map(q);
        p.setPen(QPen(colour, 1.3));
        p.drawPolyline(line);
        p.setPen(Qt::NoPen);
        p.setBrush(QColor(30, 30, 30));
        for (const auto& q : m.photoPoints)
            p.drawEllipse(v.map(q), 1.6, 1.6);
    }
    // Home: a black square.
    p.setPen(QPen(Qt::white, 1));
    p.setBrush(Qt::black);
    p.drawRect(QRectF(v.map(c.home) - QPointF(5, 5), QSizeF(10, 10)));
    p.restore();
    drawScale(p, v, panel);
    p.setPen(Qt::black);
    QFont f = p.font();
    f.setPixelSize(14);
    f.setBold(true);
    p.setFont(f);
    p.drawText(QRectF(panel.left(), panel.top() - kTitle + 4, panel.width(), 18), Qt::AlignLeft,
               QString::fromStdString(l1));
    f.setBold(false);
    f.setPixelSize(12);
    p.setFont(f);
    p.drawText(QRectF(panel.left(), panel.top() - kTitle + 24, panel.width(), 32), Qt::AlignLeft | Qt::TextWordWrap,
               QString::fromStdString(l2));
}

QColor plannerColour(std::size_t i) {
    static const QColor colours[] = {QColor(31, 119, 180), QColor(214, 39, 40), QColor(44, 160, 44),
                                     QColor(148, 103, 189), QColor(140, 86, 75), QColor(23, 190, 207)};
    return colours[i % (sizeof colours / sizeof colours[0])];
}

} // namespace

int writeSurveyCharts(const std::vector<mission::SurveyComparison>& areas, const std::string& dir, std::string* error) {
    ensureHeadlessGui();
    int written = 0;
    for (const auto& c : areas) {
        geo::Box box = geo::bounds(c.localArea);
        grow(box, c.home);
        for (const auto& q : c.lawnmower.path)
            grow(box, q);
        for (const auto& r : c.planners)
            for (const auto& q : r.m.path)
                grow(box, q);
        const double side = std::max({box.max.x() - box.min.x(), box.max.y() - box.min.y(), 1.0});
        const std::size_t panels = c.planners.size() + 1;
        const int cols = panels <= 2 ? static_cast<int>(panels) : 2;
        const int rows = static_cast<int>((panels + cols - 1) / cols);
        QImage img(cols * (kPanel + 2 * kPad), rows * (kPanel + kTitle + 2 * kPad) + 24, QImage::Format_ARGB32);
        img.fill(Qt::white);
        QPainter p(&img);
        p.setRenderHint(QPainter::Antialiasing);
        QFont f = p.font();
        f.setPixelSize(13);
        p.setFont(f);
        p.drawText(QRectF(kPad, 4, img.width() - 2 * kPad, 18), Qt::AlignLeft,
                   QString::fromStdString(c.area + ": " + num("%.0f", c.areaM2) + " m2, " + std::to_string(c.zones) +
                                          " no-fly zones (red, " + num("%.0f", c.marginM) +
                                          " m margin orange), home black; x = planner / lawnmower"));
        for (std::size_t k = 0; k < panels; ++k) {
            const int col = static_cast<int>(k) % cols, row = static_cast<int>(k) / cols;
            const QRectF panel(col * (kPanel + 2 * kPad) + kPad, 24 + row * (kPanel + kTitle + 2 * kPad) + kPad + kTitle,
                               kPanel, kPanel);
            View v;
            v.box = box;
            v.scale = kPanel / side;
            v.origin = QPointF(panel.left() + (kPanel - (box.max.x() - box.min.x()) * v.scale) / 2,
                               panel.top() + (kPanel - (box.max.y() - box.min.y()) * v.scale) / 2);
            const bool lawnmower = k == c.planners.size();
            if (lawnmower) {
                const auto& L = c.lawnmower;
                const std::string l1 = "lawnmower (Survey) at " + num("%.1f", L.angleDeg) + " deg: " +
                                       num("%.0f", L.timeS) + " s, " + std::to_string(L.photos) + " photos";
                std::string l2 = num("%.0f", L.pathM) + " m, " + std::to_string(L.turns) + " turns, coverage " +
                                 num("%.4f", L.coverage);
                if (c.zones > 0)
                    l2 += "; ignores the zones: " + std::to_string(c.crossings.photosInZones) + " photos in zones, " +
                          std::to_string(c.crossings.legsCrossing) + " legs crossing a zone or margin, " +
                          std::to_string(c.crossings.photosOutsideZones) + " photos outside";
                drawPlan(p, c, v, panel, L, QColor(90, 90, 90), l1, l2);
            } else {
                const auto& r = c.planners[k];
                const char* name = mission::plannerKindInfo(r.kind).id;
                if (!r.m.ok) {
                    drawPlan(p, c, v, panel, r.m, plannerColour(k), std::string(name) + ": no plan", r.m.error);
                    continue;
                }
                const auto q = mission::ratiosTo(r.m, c);
                const std::string l1 = std::string(name) + " at " + num("%.1f", r.m.angleDeg) + " deg: " +
                                       num("%.0f", r.m.timeS) + " s (x" + num("%.2f", q.time) + "), " +
                                       std::to_string(r.m.photos) + " photos (x" + num("%.2f", q.photos) + ")";
                std::string l2 = num("%.0f", r.m.pathM) + " m (x" + num("%.2f", q.path) + "), " +
                                 std::to_string(r.m.turns) + " turns (x" + num("%.1f", q.turns) + "), coverage " +
                                 num("%.4f", r.m.coverage) + ", " + std::to_string(r.m.violations) + " no-fly violations";
                if (c.zones > 0)
                    l2 += ", photos x" + num("%.2f", q.photosOutside) + " the lawnmower's outside the zones";
                drawPlan(p, c, v, panel, r.m, plannerColour(k), l1, l2);
            }
        }
        p.end();
        const std::string path = dir + "/survey_" + chartFileName(c.area) + ".png";
        if (!img.save(QString::fromStdString(path), "PNG")) {
            *error = "cannot write the picture " + path;
            return -1;
        }
        ++written;
    }
    return written;
}

#endif

} // namespace pf::cli
