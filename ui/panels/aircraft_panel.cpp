#include "ui/panels/aircraft_panel.h"

#include "core/mission/aircraft_naming.h"
#include "core/mission/oblique.h"
#include "core/mission/validation.h"
#include "core/sensor/camera.h"
#include "ui/commands/add_aircraft_command.h"
#include "ui/commands/edit_aircraft_command.h"
#include "ui/commands/remove_aircraft_command.h"
#include "ui/mission_document.h"

#include <QColorDialog>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QPainter>
#include <QPushButton>
#include <QToolButton>
#include <QVBoxLayout>

#include <cmath>

namespace pf::ui {

namespace {

QIcon swatch(const QString& colour) {
    QPixmap pm(14, 14);
    pm.fill(Qt::transparent);
    QPainter p(&pm);
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(QPen(QColor(40, 40, 40), 1));
    p.setBrush(QColor(colour));
    p.drawRoundedRect(QRectF(1, 1, 12, 12), 3, 3);
    return QIcon(pm);
}

QDoubleSpinBox* spin(double min, double max, int decimals, double step, const QString& suffix) {
    auto* s = new QDoubleSpinBox;
    s->setRange(min, max);
    s->setDecimals(decimals);
    s->setSingleStep(step);
    s->setSuffix(suffix);
    s->setKeyboardTracking(false); // one command per finished entry, not per keystroke
    s->setAlignment(Qt::AlignRight);
    return s;
}

// A wrapped label in a form row gets the height of one line unless it is told its height.
void fitHeight(QLabel* label, int fieldWidth) {
    label->setMinimumHeight(label->heightForWidth(std::max(120, fieldWidth)));
}

// A generic 1" 20 MP camera for custom aircraft when the catalog has none.
sensor::Camera genericCamera() {
    sensor::Camera c;
    c.name = "Generic 1-inch 20 MP";
    c.sensorWidthMm = 13.2;
    c.sensorHeightMm = 8.8;
    c.focalLengthMm = 8.8;
    c.imageWidthPx = 5472;
    c.imageHeightPx = 3648;
    return c;
}

// The altitude an aircraft flies at: its own, or the one giving its GSD.
std::optional<double> effectiveAltitude(const mission::AircraftConfig& a) {
    if (a.altitudeM) return a.altitudeM;
    if (a.gsdCm) {
        auto alt = sensor::altitudeForGsd(a.camera, *a.gsdCm);
        if (alt) return *alt;
    }
    return std::nullopt;
}

} // namespace

AircraftPanel::AircraftPanel(MissionDocument* doc, io::Catalog catalog, QWidget* parent)
    : QWidget(parent), m_doc(doc), m_catalog(std::move(catalog)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(6, 6, 6, 6);
    buildList();
    layout->addWidget(m_list);
    layout->addLayout(buildButtons());
    createFields();
    buildForm();
    layout->addWidget(m_form);
    layout->addStretch();

    connectFields();
    connectPlaneFields();
    connect(doc, &MissionDocument::aircraftChanged, this, [this] {
        refreshList();
        refreshForm();
    });
    // Whether a plane is plannable depends on the mission's planner: the footprint line says so.
    connect(doc, &MissionDocument::optionsChanged, this, [this] { refreshForm(true); });
    refreshList();
    refreshForm();
}

// The list of the mission's aircraft.
void AircraftPanel::buildList() {
    m_list = new QListWidget;
    m_list->setMaximumHeight(110);
    m_list->setIconSize(QSize(14, 14));
    // A long camera name is shortened in the middle, never cut by a scroll bar; the tip has it all.
    m_list->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_list->setTextElideMode(Qt::ElideMiddle);
}

// Add aircraft (a menu of the catalog's aircraft and a custom one) and Remove.
QHBoxLayout* AircraftPanel::buildButtons() {
    auto* buttons = new QHBoxLayout;
    m_addButton = new QToolButton;
    m_addButton->setText(tr("Add aircraft"));
    m_addButton->setIcon(QIcon(QStringLiteral(":/icons/aircraft_add.svg")));
    m_addButton->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_addButton->setPopupMode(QToolButton::InstantPopup);
    auto* menu = new QMenu(m_addButton);
    for (const auto& spec : m_catalog.aircraft) {
        const QString name = QString::fromStdString(spec.name);
        menu->addAction(name, this, [this, name] { addFromCatalog(name); });
    }
    if (!m_catalog.aircraft.empty()) menu->addSeparator();
    menu->addAction(tr("Custom aircraft"), this, &AircraftPanel::addCustom);
    m_addButton->setMenu(menu);
    m_removeButton = new QPushButton(QIcon(QStringLiteral(":/icons/remove.svg")), tr("Remove"));
    buttons->addWidget(m_addButton);
    buttons->addStretch();
    buttons->addWidget(m_removeButton);
    return buttons;
}

// The form's fields: wide ranges, so that a value out of the aircraft's limits is refused with the
// reason instead of being clamped.
void AircraftPanel::createFields() {
    m_name = new QLineEdit;
    m_model = new QLabel;
    m_model->setStyleSheet(QStringLiteral("color: palette(mid);"));
    m_camera = new QComboBox;
    for (const auto& cam : m_catalog.cameras) m_camera->addItem(QString::fromStdString(cam.name));
    // Wide ranges: a value out of the aircraft's limits is refused with the reason (below the field)
    // instead of being clamped or reverted without a word.
    m_altitude = spin(0.0, 99999.0, 1, 5.0, tr(" m"));
    m_altitude->setObjectName(QStringLiteral("AltitudeBox"));
    m_gsd = spin(0.0, 9999.0, 2, 0.1, tr(" cm/px"));
    m_gsd->setObjectName(QStringLiteral("GsdBox"));
    m_altitudeError = new QLabel;
    m_altitudeError->setObjectName(QStringLiteral("AltitudeError"));
    m_altitudeError->setWordWrap(true);
    m_altitudeError->setStyleSheet(QStringLiteral("QLabel { color: #b00020; font-weight: bold; }"));
    m_altitudeError->hide();
    m_footprint = new QLabel;
    m_footprint->setObjectName(QStringLiteral("FootprintLabel"));
    m_footprint->setWordWrap(true);
    m_footprint->setMinimumWidth(120);
    m_camera->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_camera->setMinimumContentsLength(12);
    m_front = spin(0.0, 95.0, 0, 5.0, tr(" %"));
    m_side = spin(0.0, 95.0, 0, 5.0, tr(" %"));
    m_front->setObjectName(QStringLiteral("FrontOverlapBox"));
    m_side->setObjectName(QStringLiteral("SideOverlapBox"));
    m_front->setToolTip(
        tr("Front overlap: the share of a photo's ground the next photo on the lane sees again"));
    m_front->setWhatsThis(
        tr("<p><b>Front overlap.</b> Photos along a lane lie the footprint's length "
           "× (1 − front overlap) apart: 70 % takes a photo every 30 % of the "
           "footprint. More overlap, more photos.</p>"));
    m_side->setToolTip(
        tr("Side overlap: the share of a lane's strip the neighbouring lane sees again"));
    m_side->setWhatsThis(tr("<p><b>Side overlap.</b> Lanes lie the footprint's width × (1 − side "
                            "overlap) apart (the track spacing). More overlap, more lanes and a "
                            "longer flight.</p>"));
    m_speed = spin(0.5, 60.0, 1, 0.5, tr(" m/s"));
    m_endurance = spin(1.0, 600.0, 0, 1.0, tr(" min"));
    m_kind = new QComboBox;
    m_kind->setObjectName(QStringLiteral("KindBox"));
    m_kind->addItem(tr("Multirotor"));
    m_kind->addItem(tr("Fixed-wing"));
    m_kind->addItem(tr("VTOL (flies the survey as a plane)"));
    m_kind->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_kind->setMinimumContentsLength(10);
    // Wide ranges: validation names a value a plane cannot fly, as for the altitude.
    m_turnRadius = spin(0.0, 5000.0, 1, 5.0, tr(" m"));
    m_turnRadius->setObjectName(QStringLiteral("TurnRadiusBox"));
    m_turnRadius->setToolTip(
        tr("The plane's tightest turn at its cruise speed; editing it sets the bank it needs"));
    m_bank = spin(1.0, 89.0, 0, 1.0, tr(" °"));
    m_bank->setObjectName(QStringLiteral("BankBox"));
    m_bank->setToolTip(
        tr("The autopilot's bank limit (ArduPlane ROLL_LIMIT_DEG, PX4 FW_R_LIM); editing it sets "
           "the turn radius: V² / (g tan bank)"));
    m_climb = spin(0.1, 30.0, 1, 0.5, tr(" m/s"));
    m_sink = spin(0.1, 30.0, 1, 0.5, tr(" m/s"));
    m_runIn = spin(0.0, 2000.0, 0, 5.0, tr(" m"));
    m_runIn->setToolTip(tr(
        "Straight flight before each lane's first photo: the camera level and the track settled"));
    m_colour = new QPushButton;
}

// The form: the aircraft's fields, and a plane's own figures in a box of their own.
void AircraftPanel::buildForm() {
    m_form = new QWidget;
    auto* form = new QFormLayout(m_form);
    form->setContentsMargins(0, 6, 0, 0);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    form->addRow(tr("Name"), m_name);
    form->addRow(tr("Model"), m_model);
    form->addRow(tr("Camera"), m_camera);
    form->addRow(tr("Altitude"), m_altitude);
    form->addRow(tr("GSD"), m_gsd);
    form->addRow(QString(), m_altitudeError);
    form->addRow(tr("Footprint"), m_footprint);
    form->addRow(tr("Front overlap"), m_front);
    form->addRow(tr("Side overlap"), m_side);
    form->addRow(tr("Kind"), m_kind);
    form->addRow(tr("Speed"), m_speed);
    form->addRow(tr("Endurance"), m_endurance);
    // A plane's own figures in a box of their own, hidden for a multirotor (a form row hidden in Qt
    // 5 still takes its spacing).
    m_planeBox = new QGroupBox(tr("Plane"));
    auto* planeForm = new QFormLayout(m_planeBox);
    planeForm->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    planeForm->addRow(tr("Turn radius"), m_turnRadius);
    planeForm->addRow(tr("Bank limit"), m_bank);
    planeForm->addRow(tr("Climb rate"), m_climb);
    planeForm->addRow(tr("Sink rate"), m_sink);
    planeForm->addRow(tr("Run-in"), m_runIn);
    form->addRow(m_planeBox);
    form->addRow(tr("Colour"), m_colour);
}

// Every field edits the current aircraft (one undo step each).
void AircraftPanel::connectFields() {
    connect(m_list, &QListWidget::currentRowChanged, this, [this] { refreshForm(); });
    connect(m_removeButton, &QPushButton::clicked, this, &AircraftPanel::removeCurrent);
    connect(m_name, &QLineEdit::editingFinished, this, [this] {
        const std::string name = m_name->text().trimmed().toStdString();
        if (!name.empty()) editCurrent(tr("name"), [&](mission::AircraftConfig& a) { a.name = name; });
    });
    connect(m_camera, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this](int i) {
        if (i < 0 || std::size_t(i) >= m_catalog.cameras.size()) return;
        const sensor::Camera cam = m_catalog.cameras[std::size_t(i)];
        editCurrent(tr("camera"), [&](mission::AircraftConfig& a) {
            // Keep the altitude (the flying constraint); the GSD follows from the new camera.
            const auto alt = effectiveAltitude(a);
            a.camera = cam;
            if (alt) {
                a.altitudeM = alt;
                a.gsdCm.reset();
            }
        });
    });
    // Altitude and GSD drive each other: whichever the user edits becomes the one stored.
    connect(m_altitude, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this](double v) {
        if (!acceptAltitude(v, false)) return;
        editCurrent(tr("altitude"), [&](mission::AircraftConfig& a) {
            a.altitudeM = v;
            a.gsdCm.reset();
        });
    });
    connect(m_gsd, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this](double v) {
        if (!acceptAltitude(v, true)) return;
        editCurrent(tr("GSD"), [&](mission::AircraftConfig& a) {
            a.gsdCm = v;
            a.altitudeM.reset();
        });
    });
    connect(m_front, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this](double v) {
        editCurrent(tr("front overlap"), [&](mission::AircraftConfig& a) { a.overlap.front = v / 100.0; });
    });
    connect(m_side, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this](double v) {
        editCurrent(tr("side overlap"), [&](mission::AircraftConfig& a) { a.overlap.side = v / 100.0; });
    });
    connect(m_speed, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this](double v) {
        editCurrent(tr("speed"), [&](mission::AircraftConfig& a) { a.cruiseSpeedMps = v; });
    });
    connect(
        m_endurance, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this](double v) {
            editCurrent(tr("endurance"), [&](mission::AircraftConfig& a) { a.enduranceMin = v; });
        });
    connect(m_colour, &QPushButton::clicked, this, [this] {
        const int i = current();
        if (i < 0)
            return;
        const QColor c = QColorDialog::getColor(QColor(QString::fromStdString(m_doc->mission().aircraft[std::size_t(i)].colour)),
                                                this, tr("Path colour"));
        if (c.isValid())
            setColour(c);
    });
}

void AircraftPanel::connectPlaneFields() {
    connect(m_kind, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this](int i) {
        if (i < 0)
            return;
        editCurrent(tr("kind"), [&](mission::AircraftConfig& a) {
            a.kind = static_cast<fleet::AircraftKind>(i);
        });
    });
    // Radius and bank drive each other through the speed: whichever the user edits is stored.
    connect(m_turnRadius, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
            [this](double v) {
                editCurrent(tr("turn radius"),
                            [&](mission::AircraftConfig& a) { a.plane.minTurnRadiusM = v; });
            });
    connect(m_bank, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this](double v) {
        editCurrent(tr("bank limit"), [&](mission::AircraftConfig& a) {
            a.plane.maxBankDeg = v;
            a.plane.minTurnRadiusM.reset();
        });
    });
    connect(m_climb, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this](double v) {
        editCurrent(tr("climb rate"),
                    [&](mission::AircraftConfig& a) { a.plane.climbRateMps = v; });
    });
    connect(m_sink, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this](double v) {
        editCurrent(tr("sink rate"), [&](mission::AircraftConfig& a) { a.plane.sinkRateMps = v; });
    });
    connect(m_runIn, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this](double v) {
        editCurrent(tr("run-in"), [&](mission::AircraftConfig& a) { a.plane.runInM = v; });
    });
}

void AircraftPanel::showPlaneRows(bool plane) {
    m_planeBox->setVisible(plane);
}

int AircraftPanel::current() const { return m_list->currentRow(); }

QString AircraftPanel::altitudeError() const { return m_altitudeError->isHidden() ? QString() : m_altitudeError->text(); }

bool AircraftPanel::acceptAltitude(double value, bool isGsd) {
    if (m_updating) return false;
    const int i = current();
    if (i < 0 || std::size_t(i) >= m_doc->mission().aircraft.size()) return false;
    const mission::AircraftConfig& a = m_doc->mission().aircraft[std::size_t(i)];
    QStringList why;
    double alt = value;
    if (isGsd) {
        if (!(value > 0)) {
            why << tr("the ground sample distance must be greater than 0 cm/px");
        } else if (auto fromGsd = sensor::altitudeForGsd(a.camera, value); !fromGsd) {
            why << QString::fromStdString(fromGsd.error().message);
        } else {
            alt = *fromGsd;
        }
    }
    if (why.isEmpty()) {
        // The dock shows one aircraft: its name in front of each reason would only repeat the form.
        const QString who =
            QString::fromStdString(mission::aircraftLabel(a.name)) + QStringLiteral(": ");
        for (const auto& e : mission::altitudeErrors(m_doc->mission(), a, alt)) {
            QString line = QString::fromStdString(e);
            if (line.startsWith(who)) line = line.mid(who.size());
            why << line;
        }
    }
    if (why.isEmpty()) {
        m_altitudeError->hide();
        return true;
    }
    // Refused: the stored value comes back into the box, the reason stays in view.
    m_altitudeError->setText(
        (isGsd ? tr("%1 cm/px not applied: %2").arg(value, 0, 'f', 2) : tr("%1 m not applied: %2").arg(value, 0, 'f', 1))
            .arg(why.join(QStringLiteral("; "))));
    m_altitudeError->show();
    fitHeight(m_altitudeError, m_altitude->width());
    refreshForm(/*keepError=*/true);
    return false;
}

void AircraftPanel::setCurrent(int index) { m_list->setCurrentRow(index); }

void AircraftPanel::setColour(const QColor& colour) {
    const std::string c = colour.name().toStdString();
    editCurrent(tr("colour"), [&](mission::AircraftConfig& a) { a.colour = c; });
}

QString AircraftPanel::nextName(const QString& base) const {
    std::vector<std::string> taken;
    for (const auto& a : m_doc->mission().aircraft) taken.push_back(a.name);
    return QString::fromStdString(mission::numberedAircraftName(base.toStdString(), taken));
}

QString AircraftPanel::nextColour() const {
    return QString::fromStdString(mission::aircraftColour(m_doc->mission().aircraft.size()));
}

void AircraftPanel::addFromCatalog(const QString& aircraftName) {
    const fleet::AircraftSpec* spec = m_catalog.findAircraft(aircraftName.toStdString());
    if (!spec) return;
    const sensor::Camera* cam = m_catalog.findCamera(spec->defaultCamera);
    mission::AircraftConfig a = mission::aircraftFromCatalog(*spec, cam);
    if (!cam) a.camera = m_catalog.cameras.empty() ? genericCamera() : m_catalog.cameras.front();
    a.name = nextName(aircraftName).toStdString();
    a.altitudeM = std::min(60.0, spec->maxAltitudeM);
    a.colour = nextColour().toStdString();
    m_doc->undoStack()->push(new AddAircraftCommand(m_doc, a));
    setCurrent(int(m_doc->mission().aircraft.size()) - 1);
}

void AircraftPanel::addCustom() {
    mission::AircraftConfig a;
    a.name = nextName(tr("Custom")).toStdString();
    a.model = "custom";
    a.camera = m_catalog.cameras.empty() ? genericCamera() : m_catalog.cameras.front();
    a.altitudeM = 60.0;
    a.colour = nextColour().toStdString();
    m_doc->undoStack()->push(new AddAircraftCommand(m_doc, a));
    setCurrent(int(m_doc->mission().aircraft.size()) - 1);
}

void AircraftPanel::removeCurrent() {
    const int i = current();
    if (i < 0) return;
    m_doc->undoStack()->push(new RemoveAircraftCommand(m_doc, i));
}

void AircraftPanel::editCurrent(const QString& field, const std::function<void(mission::AircraftConfig&)>& change) {
    if (m_updating) return;
    const int i = current();
    if (i < 0 || std::size_t(i) >= m_doc->mission().aircraft.size()) return;
    mission::AircraftConfig a = m_doc->mission().aircraft[std::size_t(i)];
    const mission::AircraftConfig before = a;
    change(a);
    if (a == before) return;
    m_doc->undoStack()->push(new EditAircraftCommand(m_doc, i, a, field));
}

void AircraftPanel::refreshList() {
    const bool was = m_updating;
    m_updating = true;
    const int keep = m_list->currentRow();
    m_list->blockSignals(true);
    m_list->clear();
    for (const auto& a : m_doc->mission().aircraft) {
        auto* item = new QListWidgetItem(swatch(QString::fromStdString(a.colour)),
                                         QStringLiteral("%1  —  %2").arg(QString::fromStdString(a.name),
                                                                         QString::fromStdString(a.camera.name)));
        item->setToolTip(item->text());
        m_list->addItem(item);
    }
    const int n = m_list->count();
    m_list->setCurrentRow(n == 0 ? -1 : std::clamp(keep < 0 ? 0 : keep, 0, n - 1));
    m_list->blockSignals(false);
    m_updating = was;
}

void AircraftPanel::refreshForm(bool keepError) {
    const int i = current();
    const bool has = i >= 0 && std::size_t(i) < m_doc->mission().aircraft.size();
    m_form->setEnabled(has);
    m_removeButton->setEnabled(has);
    if (!keepError) m_altitudeError->hide();
    if (!has) {
        // No aircraft: the greyed form shows nothing of one that is gone.
        const QList<QDoubleSpinBox*> boxes{m_altitude, m_gsd,       m_front,      m_side,
                                           m_speed,    m_endurance, m_turnRadius, m_bank,
                                           m_climb,    m_sink,      m_runIn};
        for (auto* b : boxes) {
            const QSignalBlocker block(b);
            b->clear();
        }
        showPlaneRows(false);
        const QSignalBlocker blockKind(m_kind);
        m_kind->setCurrentIndex(-1);
        const QSignalBlocker block(m_camera);
        m_name->clear();
        m_model->clear();
        m_camera->setCurrentIndex(-1);
        m_colour->setText(QString());
        m_colour->setIcon(QIcon());
        m_footprint->setText(tr("Add an aircraft to choose its camera and altitude."));
        return;
    }
    const mission::AircraftConfig& a = m_doc->mission().aircraft[std::size_t(i)];
    m_updating = true;
    const QList<QWidget*> boxes{m_altitude,  m_gsd,    m_front, m_side, m_speed,
                                m_endurance, m_camera, m_name,  m_kind, m_turnRadius,
                                m_bank,      m_climb,  m_sink,  m_runIn};
    for (auto* w : boxes) w->blockSignals(true);
    m_name->setText(QString::fromStdString(a.name));
    m_model->setText(a.model == "custom" ? tr("custom aircraft") : QString::fromStdString(a.model));
    int camIndex = m_camera->findText(QString::fromStdString(a.camera.name));
    if (camIndex < 0) {
        // A camera that is not in the catalog (from a mission file): show it, selected.
        m_camera->addItem(QString::fromStdString(a.camera.name));
        camIndex = m_camera->count() - 1;
    }
    m_camera->setCurrentIndex(camIndex);
    m_camera->setToolTip(m_camera->currentText());

    const auto alt = effectiveAltitude(a);
    std::optional<double> gsd = a.gsdCm;
    if (!gsd && alt) {
        auto g = sensor::gsdCmAt(a.camera, *alt);
        if (g) gsd = *g;
    }
    if (alt) m_altitude->setValue(*alt);
    if (gsd) m_gsd->setValue(*gsd);
    m_altitude->setToolTip(tr("Flight altitude above take-off: %1 to %2 m for this aircraft, photos at least %3 m "
                              "on the ground")
                               .arg(mission::kMinSafeAltitudeM, 0, 'f', 0)
                               .arg(a.maxAltitudeM, 0, 'f', 0)
                               .arg(mission::kMinFootprintM, 0, 'f', 0));
    m_front->setValue(a.overlap.front * 100.0);
    m_side->setValue(a.overlap.side * 100.0);
    m_speed->setValue(a.cruiseSpeedMps);
    m_endurance->setValue(a.enduranceMin);
    m_kind->setCurrentIndex(static_cast<int>(a.kind));
    m_turnRadius->setValue(fleet::minTurnRadiusM(a.plane, a.cruiseSpeedMps));
    m_bank->setValue(fleet::bankAngleDeg(a.plane, a.cruiseSpeedMps));
    m_climb->setValue(a.plane.climbRateMps);
    m_sink->setValue(a.plane.sinkRateMps);
    m_runIn->setValue(a.plane.runInM);
    showPlaneRows(fleet::fliesAsPlane(a.kind));
    for (auto* w : boxes) w->blockSignals(false);
    m_colour->setIcon(swatch(QString::fromStdString(a.colour)));
    m_colour->setText(QString::fromStdString(a.colour));

    m_footprint->setText(footprintText(a, alt));
    fitHeight(m_footprint, m_altitude->width());
    m_updating = false;
}

// The Footprint line: the photo's footprint and spacings as the mission points the camera, and in
// red whatever keeps the aircraft from being planned; or what it lacks to have one.
QString AircraftPanel::footprintText(const mission::AircraftConfig& a,
                                     std::optional<double> alt) const {
    if (!alt)
        return tr("Set an altitude or a GSD.");
    QString text;
    // The camera as the mission points it: oblique photos see the ground ahead.
    const double tilt = m_doc->mission().options.cameraTiltDeg;
    auto fp = sensor::effectiveFootprint(mission::pointedCamera(a, m_doc->mission().options),
                                         *alt, a.overlap);
    if (fp) {
        text = tr("%1 × %2 m per photo\ntrack spacing %3 m, photo every %4 m")
                   .arg(fp->real.longSideM, 0, 'f', 1)
                   .arg(fp->real.shortSideM, 0, 'f', 1)
                   .arg(fp->acrossM, 0, 'f', 1)
                   .arg(fp->alongM, 0, 'f', 1);
        if (tilt > 0)
            text += tr("\ncamera tilted %1°: photos centred %2 m ahead")
                        .arg(tilt, 0, 'f', 0)
                        .arg(fp->real.aheadM, 0, 'f', 1);
    } else {
        text = QString::fromStdString(fp.error().message);
    }
    // A value from a mission file can be out of limits too: say so in red, it will not be planned.
    QStringList errors;
    for (const auto& e : mission::altitudeErrors(m_doc->mission(), a, *alt)) errors << QString::fromStdString(e).toHtmlEscaped();
    // A plane's figures, and whether the mission's planner plans for a plane, the same way.
    const std::string who = mission::aircraftLabel(a.name);
    for (const auto& e : mission::planeErrors(a, who))
        errors << QString::fromStdString(e).toHtmlEscaped();
    if (const auto e = mission::planeRoutingError(a, m_doc->mission().options.planner, who);
        !e.empty())
        errors << QString::fromStdString(e).toHtmlEscaped();
    if (const auto e = mission::corridorPlaneError(m_doc->mission(), a, who); !e.empty())
        errors << QString::fromStdString(e).toHtmlEscaped();
    if (const auto e = mission::cameraTiltError(m_doc->mission(), a, who); !e.empty())
        errors << QString::fromStdString(e).toHtmlEscaped();
    text = text.toHtmlEscaped().replace(QLatin1Char('\n'), QStringLiteral("<br>"));
    if (!errors.isEmpty())
        text += QStringLiteral("<br><span style='color:#b00020; font-weight:bold'>%1</span>")
                    .arg(tr("Not plannable: %1").arg(errors.join(QStringLiteral("; "))));
    return text;
}

} // namespace pf::ui
