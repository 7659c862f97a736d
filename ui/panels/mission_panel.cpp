#include "ui/panels/mission_panel.h"

#include "core/geo/local_frame.h"
#include "core/geo/polygon_ops.h"
#include "ui/map/mission_layer.h"
#include "ui/mission_document.h"

#include <QLabel>
#include <QListWidget>
#include <QVBoxLayout>

namespace pf::ui {

MissionPanel::MissionPanel(MissionDocument* doc, MissionLayer* layer, QWidget* parent)
    : QWidget(parent), m_doc(doc), m_layer(layer) {
    auto* l = new QVBoxLayout(this);
    l->setContentsMargins(6, 6, 6, 6);
    m_summary = new QLabel;
    m_summary->setWordWrap(true);
    m_summary->setTextFormat(Qt::RichText);
    m_shapes = new QListWidget;
    m_problems = new QLabel;
    m_problems->setWordWrap(true);
    m_problems->setStyleSheet(QStringLiteral("color: #b35900;"));
    l->addWidget(m_summary);
    l->addWidget(m_shapes, 1);
    l->addWidget(m_problems);
    connect(doc, &MissionDocument::changed, this, &MissionPanel::refresh);
    connect(layer, &MissionLayer::problemsChanged, this, &MissionPanel::refresh);
    connect(m_shapes, &QListWidget::itemClicked, this, [this](QListWidgetItem* item) {
        const int row = item->data(Qt::UserRole).toInt();
        const ShapeRef ref = row < 0 ? ShapeRef::area() : ShapeRef::noFly(row);
        m_layer->select(ref);
        QRectF r;
        for (const auto& ring : m_layer->sceneRings(ref)) r = r.united(ring.boundingRect());
        if (!r.isEmpty()) emit shapeActivated(r);
    });
    refresh();
}

void MissionPanel::refresh() {
    const auto& m = m_doc->mission();
    QString s = QStringLiteral("<b>%1</b><br>").arg(m_doc->displayName().toHtmlEscaped());
    if (m.area.outer.empty())
        s += tr("No area yet: draw one or import a file.");
    else
        s += tr("Area %1 ha, %2 vertices").arg(geo::groundAreaM2(m.area) / 10000.0, 0, 'f', 2).arg(m.area.outer.size());
    s += QStringLiteral("<br>") + tr("%n no-fly zone(s)", nullptr, int(m.noFlyZones.size()));
    s += QStringLiteral("<br>") + (m.home ? tr("Home %1°, %2°").arg(m.home->lat, 0, 'f', 6).arg(m.home->lon, 0, 'f', 6)
                                          : tr("No home point"));
    s += QStringLiteral("<br>") + tr("%n aircraft", nullptr, int(m.aircraft.size()));
    m_summary->setText(s);

    m_shapes->clear();
    if (!m.area.outer.empty()) {
        auto* item = new QListWidgetItem(QIcon(QStringLiteral(":/icons/draw_area.svg")), tr("Area"));
        item->setData(Qt::UserRole, -1);
        m_shapes->addItem(item);
    }
    for (std::size_t i = 0; i < m.noFlyZones.size(); ++i) {
        auto* item = new QListWidgetItem(QIcon(QStringLiteral(":/icons/draw_nofly.svg")),
                                         tr("%1 (%2 m²)")
                                             .arg(QString::fromStdString(m.noFlyZones[i].name))
                                             .arg(geo::groundAreaM2(m.noFlyZones[i].polygon), 0, 'f', 0));
        item->setData(Qt::UserRole, int(i));
        m_shapes->addItem(item);
    }
    const QStringList problems = m_layer->problems();
    m_problems->setText(problems.join(QLatin1Char('\n')));
    m_problems->setVisible(!problems.isEmpty());
}

} // namespace pf::ui
