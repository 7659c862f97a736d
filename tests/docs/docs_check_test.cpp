// The documentation check: README.md and docs/*.md against the repository and the programs.
//  - every relative link resolves: the file exists, and a #part names a heading of the target page
//    (GitHub's heading slugs, which pandoc's gfm reader makes too, so the help browser agrees);
//  - a page under docs/ links inside docs/ only to pages of the help build (docs/docs.cmake's
//    PF_DOC_PAGES) or its images (docs/images/*.png); a link to another file of the repository
//    starts with ../ (the help build shows such a link as text) and must resolve in the repository;
//  - every `photoflight-cli COMMAND` the docs write exists in `photoflight-cli --help`, and every
//    --option written after it exists in `photoflight-cli COMMAND --help`; every other --option the
//    docs name exists in some command's --help, in `photoflight --help`, or belongs to one of the
//    developer tools listed below;
//  - every command of `photoflight-cli --help` is documented in docs/cli.md.
// Paths come from the build: PF_SOURCE_DIR, PF_CLI_PATH and PF_GUI_PATH.
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QMap>
#include <QProcess>
#include <QProcessEnvironment>
#include <QRegularExpression>
#include <QSet>
#include <QStringList>

#include <gtest/gtest.h>

namespace {

const QString kSource = QStringLiteral(PF_SOURCE_DIR);

QString readText(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QString::fromUtf8(f.readAll());
}

// README.md and every page of docs/, relative to the source directory.
QStringList docFiles() {
    QStringList files{QStringLiteral("README.md")};
    const QStringList pages = QDir(kSource + QStringLiteral("/docs"))
                                  .entryList({QStringLiteral("*.md")}, QDir::Files, QDir::Name);
    for (const QString& p : pages)
        files << QStringLiteral("docs/") + p;
    return files;
}

// One line of a Markdown file, and whether it lies in a fenced code block.
struct Line {
    QString text;
    bool code = false;
    int number = 0;
};

QVector<Line> lines(const QString& text) {
    QVector<Line> out;
    bool fence = false;
    int n = 0;
    for (const QString& l : text.split(QLatin1Char('\n'))) {
        ++n;
        if (l.startsWith(QLatin1String("```"))) {
            fence = !fence;
            continue;
        }
        out.push_back({l, fence, n});
    }
    return out;
}

// GitHub's anchor for a heading: lower case, markup and punctuation dropped, spaces to hyphens.
QString slug(QString heading) {
    static const QRegularExpression link(QStringLiteral("\\[([^\\]]*)\\]\\([^)]*\\)"));
    heading.replace(link, QStringLiteral("\\1"));
    QString out;
    for (const QChar c : heading.trimmed().toLower()) {
        if (c.isLetterOrNumber() || c.isMark() || c == QLatin1Char('_') || c == QLatin1Char('-'))
            out += c;
        else if (c == QLatin1Char(' '))
            out += QLatin1Char('-');
    }
    return out;
}

// Every anchor of a page, duplicates numbered as GitHub numbers them (name, name-1, ...).
QSet<QString> anchors(const QString& path) {
    QSet<QString> out;
    QMap<QString, int> seen;
    static const QRegularExpression heading(QStringLiteral("^#{1,6} +(.*?) *#*$"));
    for (const Line& l : lines(readText(path))) {
        if (l.code)
            continue;
        const auto m = heading.match(l.text);
        if (!m.hasMatch())
            continue;
        const QString s = slug(m.captured(1));
        const int k = seen.value(s, 0);
        out.insert(k == 0 ? s : s + QLatin1Char('-') + QString::number(k));
        seen[s] = k + 1;
    }
    return out;
}

// Inline code spans of a line outside code blocks, or the whole line inside one.
QStringList codeOf(const Line& l) {
    if (l.code)
        return {l.text};
    QStringList spans;
    static const QRegularExpression span(QStringLiteral("`+([^`]+)`+"));
    for (auto it = span.globalMatch(l.text); it.hasNext();)
        spans << it.next().captured(1);
    return spans;
}

struct Help {
    QStringList commands;                 // from `photoflight-cli --help`
    QMap<QString, QSet<QString>> options; // per command, from `photoflight-cli COMMAND --help`
    QSet<QString> everyOption;            // any command's, the top level's and photoflight's
};

QString run(const QString& program, const QStringList& args) {
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    p.setProcessEnvironment(env);
    p.start(program, args);
    if (!p.waitForFinished(30000))
        return {};
    return QString::fromUtf8(p.readAllStandardOutput() + p.readAllStandardError());
}

QSet<QString> optionsIn(const QString& text) {
    QSet<QString> out;
    static const QRegularExpression option(QStringLiteral("(?<![\\w-])--[a-z][a-z0-9_-]*"));
    for (auto it = option.globalMatch(text); it.hasNext();)
        out.insert(it.next().captured(0));
    return out;
}

const Help& help() {
    static const Help h = [] {
        Help out;
        const QString top = run(QStringLiteral(PF_CLI_PATH), {QStringLiteral("--help")});
        const int at = top.indexOf(QLatin1String("Commands:\n"));
        if (at >= 0) {
            static const QRegularExpression command(QStringLiteral("^  ([a-z]+)\\b"),
                                                    QRegularExpression::MultilineOption);
            const QString listed = top.mid(at + 10);
            for (const QString& line : listed.split(QLatin1Char('\n'))) {
                const auto m = command.match(line);
                if (!m.hasMatch())
                    break;
                out.commands << m.captured(1);
            }
        }
        out.everyOption = optionsIn(top);
        for (const QString& c : out.commands) {
            out.options[c] =
                optionsIn(run(QStringLiteral(PF_CLI_PATH), {c, QStringLiteral("--help")}));
            out.everyOption += out.options[c];
        }
        out.everyOption += optionsIn(run(QStringLiteral(PF_GUI_PATH), {QStringLiteral("--help")}));
        return out;
    }();
    return h;
}

// Options of the developer tools the docs describe (developer.md, mosaic.md), by tool.
const QSet<QString>& toolOptions() {
    static const QSet<QString> tools = {
        // tests/peers/sim_vehicle.mjs, the simulated vehicle
        "--udp", "--udp-out", "--tcp", "--sysid", "--autopilot", "--drop-request", "--nack",
        "--nack-type", "--old-requests", "--silent", "--delay", "--vehicle-timeout", "--report",
        "--seconds",
        // build/tests/pf_simulate_flight, the flight simulator
        "--noise-pos", "--noise-angle",
        // CMake, Google Benchmark, GoogleTest, ctest, npm
        "--build", "--benchmark_filter", "--benchmark_counters_tabular", "--gtest_filter",
        "--output-on-failure", "--prefer-offline"};
    return tools;
}

TEST(DocsCheck, EveryRelativeLinkResolves) {
    const QString pageList = readText(kSource + QStringLiteral("/docs/docs.cmake"));
    static const QRegularExpression pagesBlock(QStringLiteral("set\\(PF_DOC_PAGES([^)]*)\\)"));
    const QStringList helpPages = pagesBlock.match(pageList).captured(1).split(
        QRegularExpression(QStringLiteral("\\s+")), Qt::SkipEmptyParts);
    ASSERT_FALSE(helpPages.isEmpty()) << "no PF_DOC_PAGES in docs/docs.cmake";
    static const QRegularExpression link(
        QStringLiteral("!?\\[(?:[^\\[\\]]|\\[[^\\]]*\\])*\\]\\(([^)\\s]+)\\)"));
    static const QRegularExpression span(QStringLiteral("`+[^`]+`+"));
    int checked = 0;
    for (const QString& file : docFiles()) {
        const QString dir = QFileInfo(kSource + QLatin1Char('/') + file).absolutePath();
        const bool inDocs = file.startsWith(QLatin1String("docs/"));
        if (inDocs) {
            EXPECT_TRUE(helpPages.contains(file.mid(5)))
                << file.toStdString() << " is not in PF_DOC_PAGES (docs/docs.cmake)";
        }
        for (const Line& l : lines(readText(kSource + QLatin1Char('/') + file))) {
            if (l.code)
                continue;
            QString text = l.text;
            text.replace(span, QStringLiteral("code"));
            for (auto it = link.globalMatch(text); it.hasNext();) {
                const QString target = it.next().captured(1);
                if (target.contains(QRegularExpression(QStringLiteral("^[a-z][a-z0-9+.-]*:"))))
                    continue; // a web address
                ++checked;
                const std::string where = (file + QLatin1Char(':') + QString::number(l.number) +
                                           QStringLiteral(": ") + target)
                                              .toStdString();
                const int hash = target.indexOf(QLatin1Char('#'));
                const QString path = hash < 0 ? target : target.left(hash);
                const QString fragment = hash < 0 ? QString() : target.mid(hash + 1);
                const QString resolved = path.isEmpty()
                                             ? kSource + QLatin1Char('/') + file
                                             : QDir::cleanPath(dir + QLatin1Char('/') + path);
                if (!QFileInfo::exists(resolved)) {
                    ADD_FAILURE() << where << ": no such file";
                    continue;
                }
                if (!resolved.startsWith(kSource + QLatin1Char('/')))
                    ADD_FAILURE() << where << ": outside the repository";
                if (inDocs && !path.isEmpty() && !path.startsWith(QLatin1String("../"))) {
                    // Stays in docs/: the help build must hold it.
                    const bool page = helpPages.contains(path);
                    const bool image = path.startsWith(QLatin1String("images/")) &&
                                       path.endsWith(QLatin1String(".png"));
                    EXPECT_TRUE(page || image)
                        << where << ": neither a page of PF_DOC_PAGES nor images/*.png";
                }
                if (!fragment.isEmpty()) {
                    EXPECT_TRUE(resolved.endsWith(QLatin1String(".md")))
                        << where << ": an anchor into a file that is not a page";
                    EXPECT_TRUE(anchors(resolved).contains(fragment))
                        << where << ": no heading with this anchor";
                }
            }
        }
    }
    EXPECT_GT(checked, 50) << "the link pattern found too few links to be checking anything";
}

TEST(DocsCheck, EveryCommandAndOptionTheDocsNameExists) {
    const Help& h = help();
    ASSERT_GE(h.commands.size(), 5) << "photoflight-cli --help lists no commands";
    static const QRegularExpression invocation(QStringLiteral("photoflight-cli +([a-z][a-z-]*)"));
    for (const QString& file : docFiles()) {
        const QVector<Line> all = lines(readText(kSource + QLatin1Char('/') + file));
        QString command; // the command of the code line being continued
        for (const Line& l : all) {
            // In a code block a line that starts with blanks continues the command above it.
            if (!l.code || !l.text.startsWith(QLatin1Char(' ')))
                command.clear();
            for (const QString& code : codeOf(l)) {
                if (!l.code)
                    command.clear(); // each inline code span stands alone
                const std::string where =
                    (file + QLatin1Char(':') + QString::number(l.number) + QStringLiteral(": "))
                        .toStdString();
                const auto m = invocation.match(code);
                const int from = m.hasMatch() ? m.capturedEnd() : 0;
                if (m.hasMatch()) {
                    command = m.captured(1);
                    EXPECT_TRUE(h.commands.contains(command))
                        << where << "photoflight-cli has no command " << command.toStdString();
                }
                const QSet<QString> said = optionsIn(code.mid(from));
                for (const QString& o : said) {
                    if (!command.isEmpty() && h.options.contains(command)) {
                        EXPECT_TRUE(h.options[command].contains(o))
                            << where << o.toStdString() << " is not in photoflight-cli "
                            << command.toStdString() << " --help";
                    } else {
                        EXPECT_TRUE(h.everyOption.contains(o) || toolOptions().contains(o))
                            << where << o.toStdString()
                            << " is in no --help of photoflight-cli or photoflight";
                    }
                }
                // Options before the command in the same span (none expected) are checked as any
                // other.
                for (const QString& o : optionsIn(code.left(from)))
                    EXPECT_TRUE(h.everyOption.contains(o) || toolOptions().contains(o))
                        << where << o.toStdString();
            }
        }
    }
}

TEST(DocsCheck, EveryCommandOfTheHelpIsDocumented) {
    const Help& h = help();
    ASSERT_GE(h.commands.size(), 5);
    const QString cli = readText(kSource + QStringLiteral("/docs/cli.md"));
    for (const QString& c : h.commands)
        EXPECT_TRUE(cli.contains(QStringLiteral("## `") + c + QStringLiteral("`")))
            << "docs/cli.md has no section \"## `" << c.toStdString() << "`\" for photoflight-cli "
            << c.toStdString();
}

} // namespace
