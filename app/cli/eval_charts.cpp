#include "app/cli/eval_charts.h"

#include "core/mission/planner_kinds.h"

#ifdef PF_CLI_HAS_QT
#include <QColor>
#include <QByteArray>
#include <QGuiApplication>
#include <QImage>
#include <QPainter>
#include <QString>
#endif

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <string>

#ifdef PF_CLI_HAS_QT
#include <sys/stat.h>
#include <unistd.h>
#endif

namespace pf::cli {

std::string chartFileName(const std::string& s) {
    std::string out;
    for (char c : s)
        out += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') ? c : '_';
    return out;
}

#ifndef PF_CLI_HAS_QT

int writeEvalCharts(const std::vector<plan::EvalRun>&, const std::vector<plan::EvalSummary>&, const std::string&,
                    std::string*) {
    return 0;
}

#else

namespace {

QColor plannerColour(plan::PlannerKind k) {
    switch (k) {
    case plan::PlannerKind::Stride:
        return QColor(31, 119, 180);
    case plan::PlannerKind::Raster:
        return QColor(214, 39, 40);
    case plan::PlannerKind::Wavefront:
        return QColor(44, 160, 44);
    }
    return Qt::black;
}

// A "nice" axis maximum and tick step for values up to v.
void niceAxis(double v, double* top, double* step) {
    if (v <= 0)
        v = 1;
    const double mag = std::pow(10.0, std::floor(std::log10(v)));
    double s = mag;
    for (double f : {0.1, 0.2, 0.5, 1.0, 2.0, 5.0})
        if (v / (f * mag) <= 8) {
            s = f * mag;
            break;
        }
    *step = s;
    *top = std::ceil(v / s) * s;
}

struct Plot {
    QRectF area; // the plotting rectangle in pixels
    double xMax = 1, yMax = 1;
    QPointF map(double x, double y) const {
        return {area.left() + x / xMax * area.width(), area.bottom() - y / yMax * area.height()};
    }
};

Plot drawAxes(QPainter& p, const QRectF& r, double xMax, double yMaxRaw, const QString& title, const QString& xLabel,
              const QString& yLabel, bool xTicks) {
    Plot plot;
    plot.area = r;
    double yStep;
    niceAxis(yMaxRaw, &plot.yMax, &yStep);
    plot.xMax = std::max(1.0, xMax);
    p.setPen(QPen(Qt::black, 1));
    p.drawRect(r);
    QFont f = p.font();
    f.setPixelSize(12);
    p.setFont(f);
    for (double y = 0; y <= plot.yMax + 1e-9; y += yStep) {
        const QPointF a = plot.map(0, y);
        p.setPen(QPen(QColor(220, 220, 220), 1));
        p.drawLine(a, QPointF(r.right(), a.y()));
        p.setPen(Qt::black);
        p.drawText(QRectF(r.left() - 58, a.y() - 8, 52, 16), Qt::AlignRight | Qt::AlignVCenter,
                   QString::number(y, 'g', 6));
    }
    if (xTicks) {
        double top, step;
        niceAxis(xMax, &top, &step);
        for (double x = 0; x <= xMax + 1e-9; x += step) {
            const QPointF a = plot.map(x, 0);
            p.drawLine(a, a + QPointF(0, 4));
            p.drawText(QRectF(a.x() - 30, a.y() + 5, 60, 16), Qt::AlignHCenter | Qt::AlignTop, QString::number(x));
        }
    }
    f.setPixelSize(14);
    f.setBold(true);
    p.setFont(f);
    p.drawText(QRectF(r.left(), r.top() - 30, r.width(), 24), Qt::AlignHCenter | Qt::AlignVCenter, title);
    f.setPixelSize(12);
    f.setBold(false);
    p.setFont(f);
    p.drawText(QRectF(r.left(), r.bottom() + 22, r.width(), 18), Qt::AlignHCenter, xLabel);
    p.save();
    p.translate(r.left() - 66, r.center().y());
    p.rotate(-90);
    p.drawText(QRectF(-r.height() / 2, -16, r.height(), 16), Qt::AlignHCenter, yLabel);
    p.restore();
    return plot;
}

void drawLegend(QPainter& p, const QPointF& at, const std::vector<plan::PlannerKind>& kinds) {
    double y = at.y();
    for (auto k : kinds) {
        p.fillRect(QRectF(at.x(), y + 3, 18, 10), plannerColour(k));
        p.setPen(Qt::black);
        p.drawText(QRectF(at.x() + 24, y, 120, 16), Qt::AlignLeft | Qt::AlignVCenter, mission::plannerKindInfo(k).id);
        y += 18;
    }
}

} // namespace

void ensureHeadlessGui() {
    if (QGuiApplication::instance())
        return;
    if (!std::getenv("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    if (!std::getenv("XDG_RUNTIME_DIR")) {
        // The platform asks for the runtime directory and warns on the output when the variable is
        // unset (a root shell, CI): the directory Qt would fall back to, made private, given it.
        const std::string dir = "/tmp/runtime-" + std::to_string(static_cast<unsigned long>(::getuid()));
        ::mkdir(dir.c_str(), 0700);
        struct stat st {};
        if (::stat(dir.c_str(), &st) == 0 && st.st_uid == ::getuid() && (st.st_mode & 0777) == 0700)
            qputenv("XDG_RUNTIME_DIR", QByteArray::fromStdString(dir));
    }
    static int argc = 1;
    static char arg0[] = "photoflight-cli";
    static char* argv[] = {arg0, nullptr};
    // Never deleted: destroying it among the static destructors at exit, after Qt's own, crashes.
    new QGuiApplication(argc, argv);
}

int writeEvalCharts(const std::vector<plan::EvalRun>& runs, const std::vector<plan::EvalSummary>& summary,
                    const std::string& dir, std::string* error) {
    ensureHeadlessGui();
    int written = 0;
    std::vector<std::string> areas;
    std::vector<plan::PlannerKind> kinds;
    for (const auto& s : summary) {
        if (std::find(areas.begin(), areas.end(), s.area) == areas.end())
            areas.push_back(s.area);
        if (std::find(kinds.begin(), kinds.end(), s.planner) == kinds.end())
            kinds.push_back(s.planner);
    }
    auto save = [&](const QImage& img, const std::string& name) {
        const std::string path = dir + "/" + name;
        if (!img.save(QString::fromStdString(path), "PNG")) {
            *error = "cannot write the chart " + path;
            return false;
        }
        ++written;
        return true;
    };

    // Figures 4 and 5: turns for each start cell.
    for (const auto& area : areas) {
        std::map<plan::PlannerKind, std::vector<int>> turns;
        double yMax = 1;
        for (const auto& r : runs)
            if (r.area == area) {
                turns[r.planner].push_back(r.metrics.turns);
                yMax = std::max<double>(yMax, r.metrics.turns);
            }
        std::size_t n = 0;
        for (const auto& [k, v] : turns)
            n = std::max(n, v.size());
        QImage img(1000, 420, QImage::Format_ARGB32);
        img.fill(Qt::white);
        QPainter p(&img);
        p.setRenderHint(QPainter::Antialiasing);
        const Plot plot = drawAxes(p, QRectF(80, 40, 780, 320), n > 1 ? n - 1 : 1, yMax * 1.05,
                                   QString::fromStdString("Turns per start cell: " + area), "start cell (contour order)",
                                   "turns", true);
        for (const auto& [k, v] : turns) {
            p.setPen(QPen(plannerColour(k), 1.5));
            for (std::size_t i = 1; i < v.size(); ++i)
                p.drawLine(plot.map(i - 1, v[i - 1]), plot.map(i, v[i]));
            if (v.size() == 1)
                p.drawEllipse(plot.map(0, v[0]), 2, 2);
        }
        drawLegend(p, QPointF(875, 50), kinds);
        p.end();
        if (!save(img, "turns_" + chartFileName(area) + ".png"))
            return -1;
    }

    // Figure 6: average distance (top) and average jumps (bottom) per area.
    {
        QImage img(1000, 760, QImage::Format_ARGB32);
        img.fill(Qt::white);
        QPainter p(&img);
        p.setRenderHint(QPainter::Antialiasing);
        double dMax = 1, jMax = 1;
        for (const auto& s : summary) {
            dMax = std::max(dMax, s.avgDistanceM);
            jMax = std::max(jMax, s.avgJumps);
        }
        const double groups = std::max<std::size_t>(1, areas.size());
        for (int panel = 0; panel < 2; ++panel) {
            const QRectF r(80, 40 + panel * 370, 780, 290);
            const Plot plot = drawAxes(p, r, groups, (panel == 0 ? dMax : jMax) * 1.05,
                                       panel == 0 ? "Average travelled distance" : "Average number of jumps", "area",
                                       panel == 0 ? "distance (m)" : "jumps", false);
            const double gw = r.width() / groups, bw = gw * 0.8 / std::max<std::size_t>(1, kinds.size());
            for (std::size_t a = 0; a < areas.size(); ++a) {
                p.setPen(Qt::black);
                p.drawText(QRectF(r.left() + a * gw, r.bottom() + 4, gw, 16), Qt::AlignHCenter,
                           QString::fromStdString(areas[a]));
                for (std::size_t k = 0; k < kinds.size(); ++k) {
                    for (const auto& s : summary) {
                        if (s.area != areas[a] || s.planner != kinds[k])
                            continue;
                        const double v = panel == 0 ? s.avgDistanceM : s.avgJumps;
                        const QPointF top = plot.map(0, v);
                        const double x = r.left() + a * gw + gw * 0.1 + k * bw;
                        p.fillRect(QRectF(x, top.y(), bw - 2, r.bottom() - top.y()), plannerColour(kinds[k]));
                    }
                }
            }
        }
        drawLegend(p, QPointF(875, 50), kinds);
        p.end();
        if (!save(img, "averages.png"))
            return -1;
    }
    return written;
}

#endif

} // namespace pf::cli
