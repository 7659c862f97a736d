#include "ui/dialogs/gimbal_box.h"

#include "core/io/export_context.h"

#include <QComboBox>
#include <QCoreApplication>

namespace pf::ui {

namespace {

QString tr(const char* text) { return QCoreApplication::translate("GimbalBox", text); }

} // namespace

QComboBox* makeGimbalBox(const QString& objectName, double tiltDeg) {
    auto* box = new QComboBox;
    box->setObjectName(objectName);
    const QString look = tiltDeg > 0 ? tr("Camera tilted %1° forward (pitch %2°)")
                                           .arg(tiltDeg, 0, 'f', 0)
                                           .arg(tiltDeg - 90.0, 0, 'f', 0)
                                     : tr("Camera straight down");
    box->addItem(look + QStringLiteral(": DO_MOUNT_CONTROL"), int(io::GimbalCommand::MountControl));
    box->addItem(look + QStringLiteral(": DO_GIMBAL_MANAGER_PITCHYAW"),
                 int(io::GimbalCommand::GimbalManagerPitchYaw));
    box->addItem(tr("No gimbal command"), int(io::GimbalCommand::None));
    return box;
}

} // namespace pf::ui
