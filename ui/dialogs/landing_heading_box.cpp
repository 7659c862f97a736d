#include "ui/dialogs/landing_heading_box.h"

#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QString>

namespace pf::ui {

QDoubleSpinBox* makeLandingHeadingBox(const QString& objectName) {
    const auto tr = [](const char* s) { return QCoreApplication::translate("LandingHeading", s); };
    auto* box = new QDoubleSpinBox;
    box->setObjectName(objectName);
    box->setRange(-1, 359);
    box->setDecimals(0);
    box->setSuffix(tr("°"));
    box->setSpecialValueText(tr("along the first lane"));
    box->setValue(-1);
    box->setToolTip(tr("The direction a fixed-wing or VTOL aircraft lands towards, degrees from "
                       "north: into the wind, towards where it blows from. Along the first lane: "
                       "turned in 15° steps until the 400 m approach keeps the no-fly margins."));
    return box;
}

QLabel* makePlaneOptionsNote() {
    auto* note = new QLabel(QCoreApplication::translate(
        "LandingHeading",
        "Planes (fixed-wing, VTOL): photos by distance along each lane, and their own landing."));
    note->setToolTip(QCoreApplication::translate(
        "LandingHeading", "A plane cannot stop for a photo or hover home: its mission triggers the "
                          "camera by distance on each lane and ends with its landing sequence, "
                          "whatever the photo and end options above say."));
    note->setObjectName(QStringLiteral("PlaneOptionsNote"));
    note->setEnabled(false); // greyed: a remark, not a setting
    return note;
}

std::optional<double> landingHeadingOf(const QDoubleSpinBox* box) {
    if (box->value() > box->minimum())
        return box->value();
    return std::nullopt;
}

} // namespace pf::ui
