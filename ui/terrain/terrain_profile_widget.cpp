#include "ui/terrain/terrain_profile_widget.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pf::ui {

double TerrainProfile::lowestClearanceM(double* atM) const {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < distanceM.size(); ++i) {
        if (std::isnan(groundM[i]) || aircraftM[i] - groundM[i] >= best)
            continue;
        best = aircraftM[i] - groundM[i];
        if (atM)
            *atM = distanceM[i];
    }
    return best;
}

TerrainProfileWidget::TerrainProfileWidget(QWidget* parent) : QWidget(parent) {
    setMinimumHeight(120);
    setAutoFillBackground(true);
}

void TerrainProfileWidget::setProfile(TerrainProfile profile) {
    m_profile = std::move(profile);
    update();
}

void TerrainProfileWidget::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QRectF area = QRectF(rect()).adjusted(52, 10, -12, -24);
    if (m_profile.empty()) {
        p.setPen(palette().color(QPalette::Disabled, QPalette::Text));
        p.drawText(QRectF(rect()).adjusted(8, 4, -8, -4), Qt::AlignCenter | Qt::TextWordWrap,
                   tr("No terrain profile: choose a terrain model (File ▸ Terrain model) and plan"));
        return;
    }
    const auto& d = m_profile.distanceM;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t i = 0; i < d.size(); ++i) {
        if (!std::isnan(m_profile.groundM[i]))
            lo = std::min(lo, m_profile.groundM[i]);
        lo = std::min(lo, m_profile.aircraftM[i]);
        hi = std::max(hi, m_profile.aircraftM[i]);
    }
    const double pad = std::max(2.0, 0.08 * (hi - lo));
    lo -= pad;
    hi += pad;
    const double len = std::max(d.back(), 1.0);
    auto X = [&](double s) { return area.left() + area.width() * s / len; };
    auto Y = [&](double h) { return area.bottom() - area.height() * (h - lo) / (hi - lo); };

    // Axes: heights above sea level on the left, distance along the flight below.
    p.setPen(palette().color(QPalette::Mid));
    p.drawRect(area);
    p.setPen(palette().color(QPalette::Text));
    const QFontMetrics fm(font());
    for (int k = 0; k <= 4; ++k) {
        const double h = lo + (hi - lo) * k / 4.0;
        p.drawText(QRectF(0, Y(h) - fm.height() / 2.0, 48, fm.height()), Qt::AlignRight | Qt::AlignVCenter,
                   QStringLiteral("%1 m").arg(h, 0, 'f', 0));
    }
    p.drawText(QRectF(area.left(), area.bottom() + 4, area.width(), fm.height()), Qt::AlignLeft,
               tr("home"));
    p.drawText(QRectF(area.left(), area.bottom() + 4, area.width(), fm.height()), Qt::AlignRight,
               QStringLiteral("%1 m").arg(len, 0, 'f', 0));

    // The ground, filled; the clearance line above it; the aircraft.
    QPainterPath ground, clearance, aircraft;
    bool open = false, openC = false;
    for (std::size_t i = 0; i < d.size(); ++i) {
        const double g = m_profile.groundM[i];
        if (std::isnan(g)) {
            open = openC = false;
            continue;
        }
        const QPointF pg(X(d[i]), Y(g)), pc(X(d[i]), Y(g + m_profile.minClearanceM));
        open ? ground.lineTo(pg) : ground.moveTo(pg);
        openC ? clearance.lineTo(pc) : clearance.moveTo(pc);
        open = openC = true;
    }
    for (std::size_t i = 0; i < d.size(); ++i) {
        const QPointF pa(X(d[i]), Y(m_profile.aircraftM[i]));
        i == 0 ? aircraft.moveTo(pa) : aircraft.lineTo(pa);
    }
    QPainterPath fill = ground;
    fill.lineTo(X(d.back()), area.bottom());
    fill.lineTo(X(d.front()), area.bottom());
    fill.closeSubpath();
    p.fillPath(fill, QColor(160, 120, 70, 120));
    p.setPen(QPen(QColor(110, 75, 35), 1.5));
    p.drawPath(ground);
    p.setPen(QPen(QColor(200, 120, 0), 1.0, Qt::DashLine));
    p.drawPath(clearance);
    p.setPen(QPen(m_profile.colour, 2.0));
    p.drawPath(aircraft);
    p.setPen(QPen(m_profile.colour, 1.0));
    for (double s : m_profile.waypointsM)
        p.drawLine(QPointF(X(s), area.top()), QPointF(X(s), area.top() + 4));

    // Where the aircraft comes closer to the ground than the clearance: red.
    p.setPen(QPen(QColor(220, 0, 0), 3.0));
    for (std::size_t i = 0; i < d.size(); ++i)
        if (!std::isnan(m_profile.groundM[i]) &&
            m_profile.aircraftM[i] - m_profile.groundM[i] < m_profile.minClearanceM - 0.05)
            p.drawPoint(QPointF(X(d[i]), Y(m_profile.aircraftM[i])));
}

} // namespace pf::ui
