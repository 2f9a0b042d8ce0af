#include "app/mainwindow.h"
#include "app/uitranslator.h"

#include <QDockWidget>
#include <QMenu>
#include <QMenuBar>
#include <QTest>
#include <QTreeWidget>

using namespace iec::app;

class TestMainWindow : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void opensWithMenusAndDocks();
    void translationSwitchRetitlesMenus_data();
    void translationSwitchRetitlesMenus();
};

namespace {

QStringList menuTitles(const MainWindow &window)
{
    QStringList titles;
    for (QAction *action : window.menuBar()->actions())
        titles << action->text();
    return titles;
}

} // namespace

void TestMainWindow::opensWithMenusAndDocks()
{
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));

    QCOMPARE(menuTitles(window), (QStringList{QStringLiteral("&File"), QStringLiteral("&Edit"),
                                              QStringLiteral("&View"), QStringLiteral("&Project"),
                                              QStringLiteral("&Online"), QStringLiteral("&Help")}));
    auto *projectDock = window.findChild<QDockWidget *>(QStringLiteral("projectDock"));
    QVERIFY(projectDock);
    QVERIFY(projectDock->isVisible());
    QCOMPARE(window.findChild<QTreeWidget *>(QStringLiteral("projectTree"))->topLevelItemCount(), 0);
    QVERIFY(window.findChild<QDockWidget *>(QStringLiteral("messagesDock"))->isVisible());
    QVERIFY(window.close());
}

void TestMainWindow::translationSwitchRetitlesMenus_data()
{
    QTest::addColumn<QString>("locale");
    QTest::addColumn<QString>("fileMenu");
    QTest::addColumn<QString>("helpMenu");
    QTest::newRow("de") << QStringLiteral("de_DE") << QStringLiteral("&Datei") << QStringLiteral("&Hilfe");
    QTest::newRow("zh_CN") << QStringLiteral("zh_CN") << QStringLiteral("文件(&F)") << QStringLiteral("帮助(&H)");
}

void TestMainWindow::translationSwitchRetitlesMenus()
{
    QFETCH(QString, locale);
    QFETCH(QString, fileMenu);
    QFETCH(QString, helpMenu);
    MainWindow window;
    UiTranslator translator;

    QVERIFY(translator.apply(QLocale(locale)));
    // Qt posts LanguageChange to every widget; the event loop would deliver it.
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);

    const QStringList titles = menuTitles(window);
    QCOMPARE(titles.first(), fileMenu);
    QCOMPARE(titles.last(), helpMenu);
}

QTEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"
