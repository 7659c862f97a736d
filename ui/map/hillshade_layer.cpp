#include "ui/map/hillshade_layer.h"

#include "core/mission/terrain_stage.h"
#include "core/terrain/dem.h"
#include "core/terrain/hillshade.h"
#include "ui/geo_adapter.h"
#include "ui/map/web_mercator.h"
#include "ui/mission_document.h"

#include <QAction>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QGraphicsPixmapItem>
#include <QGraphicsScene>
#include <QPixmap>
#include <QSettings>
#include <QTimer>
#include <QtConcurrent>

#include <algorithm>
#include <cmath>

namespace pf::ui {

namespace {

const QString kSetting = QStringLiteral("map/hillshade");
constexpr double kMaxCropM = 40'000.0; // scene metres shown around the area of a larger DEM

QRectF areaRect(const mission::Mission& m) {
    QRectF r;
    for (const auto& p : m.area.outer) {
        const QPointF s = mercator::toScene(p.lon, p.lat);
        r = r.isNull() ? QRectF(s, QSizeF(1e-6, 1e-6)) : r.united(QRectF(s, QSizeF(1e-6, 1e-6)));
    }
    return r;
}

} // namespace

HillshadeLayer::HillshadeLayer(MissionDocument* doc, QGraphicsScene* scene, QObject* parent)
    : QObject(parent), m_doc(doc) {
    setObjectName(QStringLiteral("HillshadeLayer"));
    m_item = new QGraphicsPixmapItem;
    m_item->setZValue(kZ);
    m_item->setOpacity(kOpacity);
    m_item->setTransformationMode(Qt::SmoothTransformation);
    m_item->setAcceptedMouseButtons(Qt::NoButton);
    m_item->setVisible(false);
    scene->addItem(m_item);
    m_action = new QAction(tr("&Hillshade of the terrain model"), this);
    m_action->setObjectName(QStringLiteral("HillshadeAction"));
    m_action->setCheckable(true);
    m_action->setToolTip(
        tr("Shaded relief of the mission's DEM, lit from the north-west, under the plan"));
    m_action->setChecked(QSettings().value(kSetting, true).toBool());
    connect(m_action, &QAction::toggled, this, [this](bool on) {
        QSettings().setValue(kSetting, on);
        m_item->setVisible(on && hasRelief());
        emit reliefChanged();
    });
    connect(&m_watcher, &QFutureWatcher<ShadedRelief>::finished, this, &HillshadeLayer::onFinished);
    connect(m_doc, &MissionDocument::optionsChanged, this, &HillshadeLayer::onMissionChanged);
    connect(m_doc, &MissionDocument::changed, this, &HillshadeLayer::onMissionChanged);
    onMissionChanged();
}

HillshadeLayer::~HillshadeLayer() {
    m_watcher.waitForFinished();
}

void HillshadeLayer::setShown(bool on) {
    m_action->setChecked(on);
}
bool HillshadeLayer::isShown() const {
    return m_action->isChecked();
}

void HillshadeLayer::onMissionChanged() {
    const auto& m = m_doc->mission();
    const QString path = QString::fromStdString(m.terrain.demPath);
    // A new DEM, or a cropped picture that no longer holds the area.
    const bool outside = m_relief.cropped && !m_relief.sceneRect.contains(areaRect(m));
    if (path == m_wanted && !outside)
        return;
    m_wanted = path;
    start();
}

void HillshadeLayer::start() {
    if (m_running) {
        m_pending = true; // started again once the running one ends
        return;
    }
    m_pending = false;
    if (m_wanted.isEmpty()) {
        m_relief = {};
        m_item->setPixmap({});
        m_item->setVisible(false);
        emit reliefChanged();
        return;
    }
    m_running = true;
    m_watcher.setFuture(
        QtConcurrent::run(&HillshadeLayer::compute, m_wanted, areaRect(m_doc->mission())));
}

void HillshadeLayer::onFinished() {
    m_running = false;
    ShadedRelief r = m_watcher.result();
    if (m_pending || r.path != m_wanted) {
        start();
        return;
    }
    m_relief = std::move(r);
    if (m_relief.image.isNull()) {
        m_item->setPixmap({});
        m_item->setVisible(false);
    } else {
        m_item->setPixmap(QPixmap::fromImage(m_relief.image));
        m_item->setPos(m_relief.sceneRect.topLeft());
        m_item->setScale(m_relief.sceneRect.width() / m_relief.image.width());
        m_item->setVisible(isShown());
    }
    emit reliefChanged();
}

bool HillshadeLayer::waitUntilReady(int timeoutMs) {
    QElapsedTimer timer;
    timer.start();
    while (isComputing()) {
        if (timer.elapsed() > timeoutMs)
            return false;
        QEventLoop loop;
        QTimer::singleShot(10, &loop, &QEventLoop::quit);
        loop.exec();
    }
    return true;
}

ShadedRelief HillshadeLayer::compute(const QString& demPath, const QRectF& area) {
    ShadedRelief out;
    out.path = demPath;
    auto dem = terrain::Dem::open(mission::locateDem(demPath.toStdString()));
    if (!dem) {
        out.error = QString::fromStdString(dem.error().message);
        return out;
    }
    const auto& info = dem->info();
    const QPointF nw = mercator::toScene(info.southWest.lon, info.northEast.lat);
    const QPointF se = mercator::toScene(info.northEast.lon, info.southWest.lat);
    const QRectF whole = QRectF(nw, se).normalized();
    QRectF rect = whole;
    // A DEM much larger than the mission: the part around the area (or the DEM's centre).
    const QPointF centre = area.isNull() ? whole.center() : area.center();
    const double half = std::max({kMaxCropM / 2, area.width(), area.height()});
    const QRectF crop(centre - QPointF(half, half), centre + QPointF(half, half));
    if (whole.width() > crop.width() || whole.height() > crop.height()) {
        rect = whole.intersected(crop);
        out.cropped = true;
    }
    if (rect.isEmpty())
        rect = whole;
    const double lat = mercator::toLonLat(rect.center()).y();
    const double ground = mercator::groundScale(lat); // ground metres per scene metre
    double spacing =
        std::max(info.pixelSizeM / ground, std::max(rect.width(), rect.height()) / kMaxSidePx);
    const int cols = std::max(2, static_cast<int>(std::ceil(rect.width() / spacing)));
    const int rows = std::max(2, static_cast<int>(std::ceil(rect.height() / spacing)));
    // Node (0, 0) at the centre of the top-left pixel; EPSG:3857 northing = -scene y.
    const double x0 = rect.left() + spacing / 2, y0 = -(rect.top() + spacing / 2);
    auto grid = dem->resample("EPSG:3857", x0, y0, spacing, cols, rows);
    if (!grid) {
        out.error = QString::fromStdString(grid.error().message);
        return out;
    }
    terrain::HillshadeOptions o;
    o.groundMetresPerUnit = ground;
    const std::vector<std::uint8_t> shade = terrain::hillshade(*grid, o);
    QImage img(cols, rows, QImage::Format_ARGB32_Premultiplied);
    for (int r = 0; r < rows; ++r) {
        auto* line = reinterpret_cast<QRgb*>(img.scanLine(r));
        for (int c = 0; c < cols; ++c) {
            const int v = shade[static_cast<std::size_t>(r) * cols + c];
            line[c] = v ? qRgba(v, v, v, 255) : qRgba(0, 0, 0, 0);
        }
    }
    out.image = std::move(img);
    out.sceneRect = QRectF(rect.left(), rect.top(), cols * spacing, rows * spacing);
    return out;
}

} // namespace pf::ui
