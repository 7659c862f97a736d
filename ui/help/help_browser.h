// Help > User guide: the documentation pages (docs/*.md, rendered at build time) in a browser
// window that works offline, with back, forward, contents and find in page.
#pragma once

#include <QDialog>
#include <QUrl>

class QLineEdit;
class QTextBrowser;
class QLabel;

namespace pf::ui {

class HelpBrowser : public QDialog {
    Q_OBJECT
public:
    // The contents page of the bundled guide (the guide's resources, :/help/, are registered by the
    // first call).
    static QUrl contentsUrl();
    explicit HelpBrowser(QWidget* parent = nullptr);
    // Shows `page` ("index.html", "user-guide.html#export"; relative to the guide).
    void showPage(const QString& page);
    QTextBrowser* browser() const { return m_browser; }

private:
    void openLink(const QUrl& url);
    void findNext(bool backward);

    QTextBrowser* m_browser = nullptr;
    QLineEdit* m_find = nullptr;
    QLabel* m_status = nullptr;
};

} // namespace pf::ui
