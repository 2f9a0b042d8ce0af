// The monkey (monkey.h) on every editor the example projects open: seeded random gestures from
// the editor's own actions and the window's menus, under AddressSanitizer. Every few gestures the
// project is saved: the file must validate against the PLCopen XSD and read back to the model the
// window holds. At the end everything is undone, which must give the project as it was opened.
// IEC_MONKEY_GESTURES=N sets the gestures per editor (default 150, what ctest runs),
// IEC_MONKEY_SEED=S the seed (default 1); a failure prints both and the last gestures.
#include "monkey.h"

#include "../model/roundtrip.h"

#include "app/documentarea.h"
#include "app/mainwindow.h"
#include "app/online/debugcontroller.h"
#include "editors/cfc/cfcstorage.h"
#include "editors/common/editorlanguage.h"
#include "interpreter/frontend/iecreader.h"
#include "model/plcopen/reader.h"
#include "model/plcopen/writer.h"
#include "model/projectmodel.h"

#include <QFile>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

using namespace iec;

class TestMonkey : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void editorsSurviveRandomGestures_data();
    void editorsSurviveRandomGestures();

private:
    QTemporaryDir m_configHome;
    QTemporaryDir m_files;
};

namespace {

constexpr int kSaveEvery = 25;

int gestureCount()
{
    bool ok = false;
    const int n = qEnvironmentVariableIntValue("IEC_MONKEY_GESTURES", &ok);
    return ok && n > 0 ? n : 150;
}

quint32 seed()
{
    bool ok = false;
    const int s = qEnvironmentVariableIntValue("IEC_MONKEY_SEED", &ok);
    return ok ? quint32(s) : 1u;
}

model::Project withoutIds(model::Project project)
{
    for (model::Pou &pou : project.types.pous)
        pou.id = {};
    return project;
}

QString lastGestures(const monkey::Monkey &m)
{
    return m.log().mid(std::max<qsizetype>(0, m.log().size() - 15)).join(QStringLiteral(" | "));
}

} // namespace

void TestMonkey::initTestCase()
{
    qputenv("XDG_CONFIG_HOME", m_configHome.path().toLocal8Bit());
    QCoreApplication::setOrganizationName(QStringLiteral("IEC Studio Tests"));
    QCoreApplication::setApplicationName(QStringLiteral("tst_monkey"));
    QStandardPaths::setTestModeEnabled(true);
    QSettings().clear();
    // An IL body for the IL editor: no example has one.
    interp::frontend::TextReadResult il = interp::frontend::readIecText(
        QStringLiteral("PROGRAM Main\nVAR a, b : BOOL; n : INT; t : TON; END_VAR\nLD a\nANDN b\nST b\nCAL t(IN := a, PT := T#1s)\n"
                       "LD n\nADD 1\nST n\nEND_PROGRAM\n"),
        QStringLiteral("il"));
    QVERIFY(!il.diagnostics.hasErrors());
    il.project.fileHeader.creationDateTime = QStringLiteral("2026-01-01T00:00:00"); // IEC text has no header
    QFile file(m_files.filePath(QStringLiteral("il.xml")));
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(model::plcopen::writeProject(il.project));

    // CFC bodies for the CFC editor: staggered_fans' diagram as IEC Studio's CFC (its FBD body
    // marked), and in CODESYS's form (an empty ST body with the chart in addData).
    model::plcopen::ReadResult fans = model::plcopen::readProjectFile(QStringLiteral(IEC_SOURCE_DIR "/resources/examples/staggered_fans.xml"));
    QVERIFY(fans.ok);
    model::Pou &main = *std::ranges::find_if(fans.project.types.pous, [](const model::Pou &p) { return p.name == QLatin1String("Main"); });
    model::Body &diagram = main.bodies.front();
    QVERIFY(diagram.elements() && !diagram.elements()->empty());
    diagram.addData.push_back({QString::fromLatin1(editors::kIecStudioCfcAddDataName), QStringLiteral("implementation"), QStringLiteral("<cfc/>")});
    const auto write = [this](const QString &name, const model::Project &project) {
        QFile out(m_files.filePath(name));
        return out.open(QIODevice::WriteOnly) && out.write(model::plcopen::writeProject(project)) > 0;
    };
    QVERIFY(write(QStringLiteral("cfc.xml"), fans.project));
    model::Body codesys = model::Body::withLanguage(model::BodyLanguage::ST);
    codesys.addData.push_back({QStringLiteral("http://www.3s-software.com/plcopenxml/cfc"), QStringLiteral("implementation"),
        editors::cfc::writeCodesysCfc(*diagram.elements())});
    main.bodies = {codesys};
    QVERIFY(write(QStringLiteral("codesys_cfc.xml"), fans.project));
}

void TestMonkey::editorsSurviveRandomGestures_data()
{
    QTest::addColumn<QString>("project");
    QTest::addColumn<QString>("pou");
    QTest::addColumn<QString>("action"); // a POU action to edit instead of the POU's body
    const QString examples = QStringLiteral(IEC_SOURCE_DIR "/resources/examples/");
    QTest::newRow("ST first_steps") << examples + QStringLiteral("first_steps.xml") << "Main" << "";
    QTest::newRow("SFC mixing_tank") << examples + QStringLiteral("mixing_tank.xml") << "Main" << "";
    QTest::newRow("ST action of mixing_tank") << examples + QStringLiteral("mixing_tank.xml") << "Main" << "Watch";
    QTest::newRow("LD motor_start_stop") << examples + QStringLiteral("motor_start_stop.xml") << "Main" << "";
    QTest::newRow("LD star_delta") << examples + QStringLiteral("star_delta.xml") << "Main" << "";
    QTest::newRow("FBD staggered_fans") << examples + QStringLiteral("staggered_fans.xml") << "Main" << "";
    QTest::newRow("IL") << m_files.filePath(QStringLiteral("il.xml")) << "Main" << "";
    QTest::newRow("CFC") << m_files.filePath(QStringLiteral("cfc.xml")) << "Main" << "";
    QTest::newRow("CODESYS CFC") << m_files.filePath(QStringLiteral("codesys_cfc.xml")) << "Main" << "";
}

void TestMonkey::editorsSurviveRandomGestures()
{
    QFETCH(QString, project);
    QFETCH(QString, pou);
    QFETCH(QString, action);
    const QString path = m_files.filePath(QStringLiteral("monkey.xml"));
    QFile::remove(path);
    QVERIFY(QFile::copy(project, path));
    QFile::setPermissions(path, QFile::ReadOwner | QFile::WriteOwner);

    app::MainWindow window;
    window.show();
    QString error;
    QVERIFY2(window.openProject(path, &error), qPrintable(error));
    const model::Pou *target = window.projectModel().project().findPou(pou);
    QVERIFY(target);
    const model::BodyRef body {target->id, action.isEmpty() ? model::BodyRef::Part::Pou : model::BodyRef::Part::Action, action};
    QVERIFY(window.documents().openBody(body));
    const model::Project start = withoutIds(window.projectModel().project());

    const quint32 rowSeed = seed() + quint32(qHash(QString::fromLatin1(QTest::currentDataTag())));
    monkey::Monkey monkey(window, rowSeed);
    const auto context = [&] {
        return QStringLiteral("seed %1 (IEC_MONKEY_SEED=%2), gesture %3: %4").arg(rowSeed).arg(seed()).arg(monkey.log().size()).arg(lastGestures(monkey));
    };
    const int gestures = gestureCount();
    for (int i = 1; i <= gestures; ++i) {
        monkey.gesture();
        if (i % kSaveEvery != 0 && i != gestures)
            continue;
        QVERIFY2(window.saveProject(path, &error), qPrintable(error + QLatin1Char('\n') + context()));
        QFile saved(path);
        QVERIFY(saved.open(QIODevice::ReadOnly));
        const QString schema = test::schemaErrors(saved.readAll());
        QVERIFY2(schema.isEmpty(), qPrintable(context() + QLatin1Char('\n') + schema.left(300)));
        const model::plcopen::ReadResult reloaded = model::plcopen::readProjectFile(path);
        QVERIFY2(reloaded.ok, qPrintable(test::diagnosticsText(reloaded.diagnostics) + QLatin1Char('\n') + context()));
        // What the window saves: the model, with the breakpoints beside it in our addData.
        const model::Project held = withoutIds(window.debugger().projectToSave());
        QVERIFY2(withoutIds(reloaded.project) == held,
            qPrintable(test::firstDifference(withoutIds(reloaded.project), held) + QLatin1Char('\n') + context()));
    }
    monkey.logout();
    QString problem;
    QVERIFY2(monkey.undoAll(&problem), qPrintable(problem + QLatin1Char('\n') + context()));
    const model::Project end = withoutIds(window.projectModel().project());
    QVERIFY2(end == start, qPrintable(test::firstDifference(end, start) + QLatin1Char('\n') + context()));
    qInfo("%s: %d gestures: %s; typing lost with its tab: %d steps", QTest::currentDataTag(), gestures,
        qPrintable(monkey.statistics()), monkey.lostTyping());
}

QTEST_MAIN(TestMonkey)
#include "tst_monkey.moc"
