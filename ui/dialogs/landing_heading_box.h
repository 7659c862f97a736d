// The "Plane landing heading" field of the Export and the Connect and Upload dialogs: one box, one
// meaning (io::ExportOptions::landingHeadingDeg), so both write the same landing.
#pragma once

#include <optional>

class QDoubleSpinBox;
class QLabel;
class QString;

namespace pf::ui {

// A box of 0 to 359 degrees whose lowest value reads "along the first lane" (no heading given),
// starting there.
QDoubleSpinBox* makeLandingHeadingBox(const QString& objectName);

// The line under it: what a plane's mission does whatever the multirotor options above say.
QLabel* makePlaneOptionsNote();

// The heading the box gives, or nothing at "along the first lane".
std::optional<double> landingHeadingOf(const QDoubleSpinBox* box);

} // namespace pf::ui
