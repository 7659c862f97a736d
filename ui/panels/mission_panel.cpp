#include "ui/panels/mission_panel.h"

#include "core/geo/local_frame.h"
#include "core/geo/polygon_ops.h"
#include "core/mission/corridor.h"
#include "ui/commands/set_corridor_command.h"
#include "ui/map/mission_layer.h"
#include "ui/mission_document.h"
#include "ui/tools/draw_corridor_tool.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
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
    m_width = new QDoubleSpinBox;
    m_width->setObjectName(QStringLiteral("CorridorWidthBox"));
    m_width->setRange(1, mission::kMaxCorridorWidthM);
    m_width->setDecimals(0);
    m_width->setSingleStep(10);
    m_width->setSuffix(QStringLiteral(" m"));
    m_width->setKeyboardTracking(false);
    m_width->setToolTip(
        tr("The corridor's full width: lanes along its line cover this much ground, half on "
           "each side (without a corridor: the width the next one drawn gets)"));
    auto* widthRow = new QFormLayout;
    widthRow->addRow(tr("Corridor width"), m_width);
    connect(m_width, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this](double w) {
        DrawCorridorTool::rememberWidthM(w);
        auto c = m_doc->mission().corridor;
        if (!c || c->widthM == w)
            return;
        c->widthM = w;
        m_doc->undoStack()->push(
            new SetCorridorCommand(m_doc, c, tr("Corridor width %1 m").arg(w, 0, 'f', 0)));
    });
    l->addWidget(m_summary);
    l->addLayout(widthRow);
    l->addWidget(m_shapes, 1);
    l->addWidget(m_problems);
    connect(doc, &MissionDocument::changed, this, &MissionPanel::refresh);
    connect(layer, &MissionLayer::problemsChanged, this, &MissionPanel::refresh);
    connect(m_shapes, &QListWidget::itemClicked, this, [this](QListWidgetItem* item) {
        const int row = item->data(Qt::UserRole).toInt();
        const ShapeRef ref = row == -2 ? ShapeRef::corridor()
                             : row < 0 ? ShapeRef::area()
                                       : ShapeRef::noFly(row);
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
    if (m.corridor)
        s += tr("Corridor %1 km × %2 m, %3 points")
                 .arg(mission::corridorLengthM(*m.corridor) / 1000.0, 0, 'f', 2)
                 .arg(m.corridor->widthM, 0, 'f', 0)
                 .arg(m.corridor->line.size());
    else if (m.area.outer.empty())
        s += tr("No area yet: draw one (or a corridor) or import a file.");
    else
        s += tr("Area %1 ha, %2 vertices").arg(geo::groundAreaM2(m.area) / 10000.0, 0, 'f', 2).arg(m.area.outer.size());
    s += QStringLiteral("<br>") + tr("%n no-fly zone(s)", nullptr, int(m.noFlyZones.size()));
    s += QStringLiteral("<br>") + (m.home ? tr("Home %1°, %2°").arg(m.home->lat, 0, 'f', 6).arg(m.home->lon, 0, 'f', 6)
                                          : tr("No home point"));
    s += QStringLiteral("<br>") + tr("%n aircraft", nullptr, int(m.aircraft.size()));
    m_summary->setText(s);

    {
        const QSignalBlocker block(m_width);
        m_width->setValue(DrawCorridorTool::corridorWidthM(m_doc));
    }
    m_shapes->clear();
    if (m.corridor) {
        auto* item =
            new QListWidgetItem(QIcon(QStringLiteral(":/icons/draw_corridor.svg")), tr("Corridor"));
        item->setData(Qt::UserRole, -2);
        m_shapes->addItem(item);
    } else if (!m.area.outer.empty()) {
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
