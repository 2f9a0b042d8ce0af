// Crash recovery with the real iecstudio executable, offscreen: it opens a copy of first_steps,
// Main's body is edited, the autosave writes its recovery file (every second here:
// IECSTUDIO_AUTOSAVE_SECONDS), and the process is killed with SIGKILL. Started again, it offers
// the recovery; Recover and File → Save must give exactly the edited project, and no recovery file
// is left. recoverydriver.cpp, preloaded into the executable, plays the user.
#include "model/plcopen/reader.h"
#include "model/plcopen/writer.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

using namespace iec;

class TestRecovery : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void killedWhileEditingRecoversTheEdit();
};

namespace {

const QString kMarker = QStringLiteral("(* typed before the crash *)\n");

QByteArray contents(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

// The process environment of a session whose settings and data live in `home`.
QProcessEnvironment sessionEnvironment(const QString &home, const QString &part)
{
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("HOME"), home);
    environment.insert(QStringLiteral("XDG_CONFIG_HOME"), home + QStringLiteral("/config"));
    environment.insert(QStringLiteral("XDG_DATA_HOME"), home + QStringLiteral("/data"));
    environment.insert(QStringLiteral("XDG_CACHE_HOME"), home + QStringLiteral("/cache"));
    environment.insert(QStringLiteral("LANG"), QStringLiteral("C.UTF-8"));
    environment.insert(QStringLiteral("LC_ALL"), QStringLiteral("C.UTF-8"));
    environment.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    environment.insert(QStringLiteral("IECSTUDIO_AUTOSAVE_SECONDS"), QStringLiteral("1"));
    environment.insert(QStringLiteral("LD_PRELOAD"), QStringLiteral(IEC_RECOVERY_DRIVER));
    environment.insert(QStringLiteral("IEC_RECOVERY_DRIVER"), part);
    environment.insert(QStringLiteral("IEC_RECOVERY_MARKER"), kMarker);
    // The driver is loaded before the sanitizer runtime the executable links.
    environment.insert(QStringLiteral("ASAN_OPTIONS"),
        environment.value(QStringLiteral("ASAN_OPTIONS")) + QStringLiteral(":verify_asan_link_order=0"));
    return environment;
}

// The recovery files written so far (QStandardPaths::AppDataLocation of "IEC Studio").
QStringList recoveryFiles(const QString &home)
{
    const QDir folder(home + QStringLiteral("/data/IEC Studio/IEC Studio/recovery"));
    QStringList files;
    for (const QString &name : folder.entryList({QStringLiteral("*.xml")}, QDir::Files))
        files << folder.filePath(name);
    return files;
}

bool recoveryHolds(const QString &home, const QString &text)
{
    const QStringList files = recoveryFiles(home);
    return files.size() == 1 && QString::fromUtf8(contents(files.front())).contains(text.trimmed());
}

} // namespace

void TestRecovery::killedWhileEditingRecoversTheEdit()
{
    QTemporaryDir home;
    const QString project = home.filePath(QStringLiteral("project.xml"));
    QVERIFY(QFile::copy(QStringLiteral(IEC_SOURCE_DIR "/resources/examples/first_steps.xml"), project));
    QFile::setPermissions(project, QFile::ReadOwner | QFile::WriteOwner);
    const QByteArray original = contents(project);

    // What the user will have: Main's body with the marker in front.
    model::Project edited = model::plcopen::readProject(original).project;
    for (model::Pou &pou : edited.types.pous) {
        if (pou.name == QLatin1String("Main"))
            pou.bodies.front().setText(kMarker + pou.bodies.front().text());
    }
    const QByteArray expected = model::plcopen::writeProject(edited);

    QProcess editing;
    editing.setProcessEnvironment(sessionEnvironment(home.path(), QStringLiteral("edit")));
    editing.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    editing.start(QStringLiteral(IECSTUDIO), {project});
    QVERIFY2(editing.waitForStarted(), qPrintable(editing.errorString()));
    QTRY_VERIFY_WITH_TIMEOUT(recoveryHolds(home.path(), kMarker) || editing.state() == QProcess::NotRunning, 90'000);
    QVERIFY2(editing.state() == QProcess::Running, "iecstudio ended before its autosave");
    editing.kill(); // SIGKILL: nothing is cleaned up
    QVERIFY(editing.waitForFinished(30'000));
    QCOMPARE(editing.exitStatus(), QProcess::CrashExit);
    QCOMPARE(contents(project), original); // the crash left the project file alone
    QVERIFY(recoveryHolds(home.path(), kMarker));

    QProcess recovering;
    recovering.setProcessEnvironment(sessionEnvironment(home.path(), QStringLiteral("recover")));
    recovering.start(QStringLiteral(IECSTUDIO), {});
    QVERIFY2(recovering.waitForFinished(120'000), "iecstudio did not recover, save and quit");
    const QString driver = QString::fromUtf8(recovering.readAllStandardError());
    QVERIFY2(recovering.exitStatus() == QProcess::NormalExit && recovering.exitCode() == 0, qPrintable(driver));
    QVERIFY2(driver.contains(QStringLiteral("driver: answered Recover")) && driver.contains(QStringLiteral("driver: saved")),
        qPrintable(driver));

    const model::plcopen::ReadResult saved = model::plcopen::readProjectFile(project);
    QVERIFY(saved.ok);
    QCOMPARE(QString::fromUtf8(model::plcopen::writeProject(saved.project)), QString::fromUtf8(expected));
    QCOMPARE(recoveryFiles(home.path()), QStringList());
}

QTEST_GUILESS_MAIN(TestRecovery)
#include "tst_recovery.moc"
