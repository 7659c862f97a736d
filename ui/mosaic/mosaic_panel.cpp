#include "ui/mosaic/mosaic_panel.h"

#include "ui/mosaic/mosaic_layer.h"

#include <QCheckBox>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QSlider>
#include <QVBoxLayout>

namespace pf::ui {

MosaicPanel::MosaicPanel(MosaicLayer* layer, QWidget* parent)
    : QDockWidget(tr("Mosaic"), parent), m_layer(layer) {
    setObjectName(QStringLiteral("MosaicDock"));
    auto* w = new QWidget;
    auto* v = new QVBoxLayout(w);
    m_file = new QLabel;
    m_file->setWordWrap(true);
    m_file->setTextInteractionFlags(Qt::TextSelectableByMouse);
    v->addWidget(m_file);

    auto* row = new QHBoxLayout;
    row->addWidget(new QLabel(tr("Opacity")));
    m_opacity = new QSlider(Qt::Horizontal);
    m_opacity->setObjectName(QStringLiteral("mosaicOpacity"));
    m_opacity->setRange(0, 100);
    m_opacity->setValue(static_cast<int>(layer->opacity() * 100));
    m_opacityValue = new QLabel;
    m_opacityValue->setMinimumWidth(36);
    row->addWidget(m_opacity, 1);
    row->addWidget(m_opacityValue);
    v->addLayout(row);
    connect(m_opacity, &QSlider::valueChanged, this, [this](int value) {
        m_layer->setOpacity(value / 100.0);
        m_opacityValue->setText(QStringLiteral("%1 %").arg(value));
    });
    m_opacityValue->setText(QStringLiteral("%1 %").arg(m_opacity->value()));

    m_gaps = new QCheckBox(tr("Show gaps in the area"));
    m_gaps->setChecked(layer->gapsVisible());
    m_seams = new QCheckBox(tr("Show seams"));
    m_seams->setChecked(layer->seamsVisible());
    v->addWidget(m_gaps);
    v->addWidget(m_seams);
    connect(m_gaps, &QCheckBox::toggled, m_layer, &MosaicLayer::setGapsVisible);
    connect(m_seams, &QCheckBox::toggled, m_layer, &MosaicLayer::setSeamsVisible);

    m_summary = new QLabel;
    m_summary->setWordWrap(true);
    v->addWidget(m_summary);

    auto* buttons = new QHBoxLayout;
    auto* zoom = new QPushButton(tr("Zoom to mosaic"));
    auto* report = new QPushButton(tr("Report…"));
    auto* remove = new QPushButton(tr("Remove"));
    buttons->addWidget(zoom);
    buttons->addWidget(report);
    buttons->addWidget(remove);
    v->addLayout(buttons);
    v->addStretch();
    // A crowded dock area squeezes the panel: scroll rather than cut the figures off.
    auto* scroll = new QScrollArea;
    scroll->setWidget(w);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    connect(zoom, &QPushButton::clicked, this, &MosaicPanel::zoomRequested);
    connect(report, &QPushButton::clicked, this, &MosaicPanel::reportRequested);
    connect(remove, &QPushButton::clicked, this, &MosaicPanel::removeRequested);
    setWidget(scroll);
    refresh();
}

void MosaicPanel::refresh() {
    if (!m_layer->isShown()) {
        m_file->setText(tr("No mosaic shown. File ▸ Build mosaic from photos…"));
        m_summary->clear();
        return;
    }
    const auto& r = m_layer->report();
    m_file->setText(
        QStringLiteral("<b>%1</b><br>%2, %3 cm/px, %4 × %5 px")
            .arg(QFileInfo(QString::fromStdString(r.outputPath)).fileName().toHtmlEscaped(),
                 QString::fromStdString(r.crsName).toHtmlEscaped())
            .arg(r.gsdM * 100, 0, 'f', 1)
            .arg(r.widthPx)
            .arg(r.heightPx));
    int leftOut = 0;
    for (const auto& f : r.findings)
        leftOut += f.excluded ? 1 : 0;
    QString s = tr("%1 of %2 photos used").arg(r.photosUsed).arg(r.photosGiven);
    if (leftOut)
        s += tr(", %n left out", nullptr, leftOut);
    if (!r.missing.empty())
        s += tr("; %n planned photo(s) missing", nullptr, int(r.missing.size()));
    if (r.areaM2 > 0) {
        s += QStringLiteral(".<br>") +
             tr("Planned area covered: %1 %").arg(r.coveredRatio * 100, 0, 'f', 2);
        if (!r.gaps.empty())
            s += QStringLiteral("<br><span style='color:#c05000'>") +
                 tr("%n gap(s), %1 m² in total (hatched orange)", nullptr, int(r.gaps.size()))
                     .arg(r.gapAreaM2, 0, 'f', 1) +
                 QStringLiteral("</span>");
        else
            s += QStringLiteral(", ") + tr("no gap");
    }
    m_summary->setText(s);
}

QString MosaicPanel::summaryText() const {
    return m_summary->text();
}

} // namespace pf::ui
