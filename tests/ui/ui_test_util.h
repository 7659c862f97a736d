// Helpers shared by the UI tests: a ready main window and mouse input on the map's viewport.
#pragma once

#include "core/geo/types.h"
#include "ui/geo_adapter.h"
#include "ui/main_window.h"
#include "ui/map/map_view.h"

#include <QAbstractButton>
#include <QApplication>
#include <QMessageBox>
#include <QMouseEvent>
#include <QTest>
#include <QTimer>

#include <cmath>
#include <memory>

namespace pf::ui::test {

// A non-interactive main window (no dialogs), shown offscreen at a fixed size, on the demo map,
// with an empty mission, looking at the demo site.
inline std::unique_ptr<MainWindow> makeWindow() {
    auto w = std::make_unique<MainWindow>(nullptr, false);
    w->resize(1400, 900);
    w->setBaseMap(QStringLiteral("demo"));
    w->show();
    w->newMission();
    w->mapView()->fitSceneRect(QRectF(toScene({8.3262, 49.0138}), toScene({8.3335, 49.0102})));
    QApplication::processEvents();
    return w;
}

inline QPoint viewPos(MapView* view, const geo::LonLat& p) { return view->mapFromScene(toScene(p)); }

inline void click(MapView* view, const geo::LonLat& p, Qt::MouseButton b = Qt::LeftButton) {
    QTest::mouseClick(view->viewport(), b, Qt::NoModifier, viewPos(view, p));
}

// QTest::mouseMove moves the system cursor, which the offscreen platform ignores: send the event.
inline void moveWithButton(MapView* view, const QPoint& pos, Qt::MouseButtons buttons) {
    QMouseEvent e(QEvent::MouseMove, pos, view->viewport()->mapToGlobal(pos), Qt::NoButton, buttons, Qt::NoModifier);
    QApplication::sendEvent(view->viewport(), &e);
}

inline void drag(MapView* view, const geo::LonLat& from, const geo::LonLat& to) {
    const QPoint a = viewPos(view, from), b = viewPos(view, to);
    QTest::mousePress(view->viewport(), Qt::LeftButton, Qt::NoModifier, a);
    for (int i = 1; i <= 5; ++i) moveWithButton(view, a + (b - a) * i / 5, Qt::LeftButton);
    QTest::mouseRelease(view->viewport(), Qt::LeftButton, Qt::NoModifier, b);
}

// Metres between two points (small distances; enough for click-accuracy checks).
inline double metresBetween(const geo::LonLat& a, const geo::LonLat& b) {
    const double k = 111319.49;
    return std::hypot((a.lon - b.lon) * k * std::cos(a.lat * 3.14159265358979 / 180.0), (a.lat - b.lat) * k);
}

// What a message box said, once answered.
struct DialogAnswer {
    QString text;
    QString informative;
    bool answered = false;
};

// Answers the next modal message box by clicking the button labelled `button` (mnemonics ignored),
// as a user would; call it before the action that opens the box.
inline std::shared_ptr<DialogAnswer> answerNextMessageBox(const QString& button) {
    auto out = std::make_shared<DialogAnswer>();
    auto* timer = new QTimer;
    timer->setInterval(20);
    QObject::connect(timer, &QTimer::timeout, [timer, out, button] {
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        if (!box) return;
        for (auto* b : box->buttons()) {
            if (b->text().remove(QLatin1Char('&')) != button) continue;
            out->text = box->text();
            out->informative = box->informativeText();
            out->answered = true;
            timer->stop();
            timer->deleteLater();
            b->click();
            return;
        }
    });
    timer->start();
    return out;
}

} // namespace pf::ui::test
