// AbstractTool: base of the map tools; a tool turns mouse and key input into undo commands.
#pragma once

#include <QCursor>
#include <QIcon>
#include <QKeySequence>
#include <QObject>
#include <QPointF>

class QKeyEvent;
class QMouseEvent;

namespace pf::ui {

class MapView;
class MissionDocument;
class MissionLayer;

// Tools only PUSH commands on the document's undo stack; they never change the mission directly.
// A drag previews with temporary scene items and pushes one command on release.
class AbstractTool : public QObject {
    Q_OBJECT
public:
    AbstractTool(const QString& name, const QIcon& icon, const QKeySequence& shortcut, MissionDocument* doc,
                 MissionLayer* layer, QObject* parent = nullptr);

    QString name() const { return m_name; }
    QIcon icon() const { return m_icon; }
    QKeySequence shortcut() const { return m_shortcut; }
    // One line telling the user how to use the tool (shown in the status bar when activated).
    virtual QString hint() const = 0;
    virtual QCursor cursor() const { return Qt::ArrowCursor; }
    // The pan tool lets the left button drag the map.
    virtual bool pansWithLeftButton() const { return false; }

    virtual void activate(MapView* view);
    virtual void deactivate(MapView* view);

    virtual void mousePressed(QMouseEvent*, const QPointF&) {}
    virtual void mouseMoved(QMouseEvent*, const QPointF&) {}
    virtual void mouseReleased(QMouseEvent*, const QPointF&) {}
    virtual void mouseDoubleClicked(QMouseEvent*, const QPointF&) {}
    // Returns true when the key was used.
    virtual bool keyPressed(QKeyEvent*) { return false; }

signals:
    void statusMessage(const QString& text);

protected:
    // Scene distance covered by `px` screen pixels in the active view.
    double pixelsToScene(double px) const;

    MissionDocument* m_doc;
    MissionLayer* m_layer;
    MapView* m_view = nullptr;

private:
    QString m_name;
    QIcon m_icon;
    QKeySequence m_shortcut;
};

} // namespace pf::ui
