// MosaicPanel: the Mosaic dock: which mosaic is shown, its opacity, gaps and seams on or off, the
// figures of its report, zoom to it or remove it.
#pragma once

#include <QDockWidget>

class QCheckBox;
class QLabel;
class QPushButton;
class QSlider;

namespace pf::ui {

class MosaicLayer;

class MosaicPanel : public QDockWidget {
    Q_OBJECT
public:
    explicit MosaicPanel(MosaicLayer* layer, QWidget* parent = nullptr);

    // Refreshes the texts from the layer's report.
    void refresh();
    QSlider* opacitySlider() const { return m_opacity; }
    QCheckBox* gapsBox() const { return m_gaps; }
    QCheckBox* seamsBox() const { return m_seams; }
    QString summaryText() const;

signals:
    void zoomRequested();
    void removeRequested();
    void reportRequested();

private:
    MosaicLayer* m_layer;
    QLabel* m_file;
    QLabel* m_summary;
    QSlider* m_opacity;
    QLabel* m_opacityValue;
    QCheckBox* m_gaps;
    QCheckBox* m_seams;
};

} // namespace pf::ui
