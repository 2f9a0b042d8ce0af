// iecstudio-cli with hostile input, run as a separate process as users run it: deep programs
// give one located message and exit 1, long ones check clean (the limits of
// interpreter/compiler/limits.h, docs/interpreter.md); never a crash. A conversion that cannot be
// written (a full disk: a file size limit on the process; a read-only folder, written by a user
// who is not root) says why, exits with 3 and leaves the old file as it was.
#include "../interpreter/deepinputs.h"
#include "clirun.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <csignal>
#include <functional>
#include <sys/resource.h>
#include <unistd.h>

class TestCliRobustness : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void deepProgramsGiveOneMessage_data();
    void deepProgramsGiveOneMessage();
    void longSumChecksClean();
    void convertOntoAFullDiskKeepsTheOldFile();
    void convertIntoAReadOnlyFolderKeepsTheOldFile();

private:
    QTemporaryDir m_dir;
};

namespace {

using clirun::cli;
using clirun::Result;
using clirun::writeFile;

} // namespace

void TestCliRobustness::deepProgramsGiveOneMessage_data()
{
    QTest::addColumn<QString>("source");
    QTest::addColumn<QString>("expected");
    for (const deepinputs::Deep &deep : deepinputs::deepPrograms())
        QTest::newRow(deep.name) << deep.source()
                                 << QStringLiteral(":Main:%1:%2: error: %3").arg(deep.line).arg(deep.column).arg(deep.message);
}

// `check` prints FILE:POU:LINE:COLUMN: error: MESSAGE once and exits with 1.
void TestCliRobustness::deepProgramsGiveOneMessage()
{
    QFETCH(QString, source);
    QFETCH(QString, expected);
    const QString path = writeFile(m_dir, QStringLiteral("deep.st"), source);
    const Result result = cli({QStringLiteral("check"), path});
    QCOMPARE(result.exitCode, 1);
    QVERIFY2(result.err.isEmpty(), qPrintable(result.err.left(2000)));
    const QStringList lines = result.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 1);
    QVERIFY2(lines.front().startsWith(path + expected), qPrintable(lines.front()));
}

void TestCliRobustness::longSumChecksClean()
{
    const QString path = writeFile(m_dir, QStringLiteral("sum.st"), deepinputs::sumOfOnes(100'000));
    const Result result = cli({QStringLiteral("check"), path});
    QCOMPARE(result.exitCode, 0);
    QCOMPARE(result.out, QString());
    const Result run = cli({QStringLiteral("run"), path, QStringLiteral("--cycles"), QStringLiteral("1"), QStringLiteral("--watch"),
                            QStringLiteral("Main.x")});
    QCOMPARE(run.exitCode, 0);
    QCOMPARE(run.out.trimmed(), QStringLiteral("Main.x = 100000"));
}

namespace {

QByteArray contents(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray("<missing>");
}

QString example()
{
    return QStringLiteral(IEC_SOURCE_DIR "/resources/examples/first_steps.xml");
}

} // namespace

void TestCliRobustness::convertOntoAFullDiskKeepsTheOldFile()
{
    const QString out = writeFile(m_dir, QStringLiteral("old.xml"), QStringLiteral("<old/>"));
    const Result result = cli({QStringLiteral("convert"), example(), out}, [] {
        // Files may not grow beyond 1 KB; beyond, write fails with EFBIG (no SIGXFSZ).
        std::signal(SIGXFSZ, SIG_IGN);
        rlimit limit {};
        getrlimit(RLIMIT_FSIZE, &limit);
        limit.rlim_cur = 1024;
        setrlimit(RLIMIT_FSIZE, &limit);
    });
    QCOMPARE(result.exitCode, 3);
    QCOMPARE(result.err, QStringLiteral("iecstudio-cli: %1 was not saved: the file would be larger than the system allows. "
                                        "The file on the disk is unchanged.\n")
                             .arg(QDir::toNativeSeparators(out)));
    QCOMPARE(contents(out), QByteArray("<old/>"));
    QCOMPARE(QDir(m_dir.path()).entryList({QStringLiteral("old.xml*")}, QDir::Files | QDir::Hidden), QStringList {QStringLiteral("old.xml")});
}

void TestCliRobustness::convertIntoAReadOnlyFolderKeepsTheOldFile()
{
    QTemporaryDir dir;
    const auto readable = QFile::ReadOwner | QFile::ExeOwner | QFile::ReadGroup | QFile::ExeGroup | QFile::ReadOther | QFile::ExeOther;
    QFile::setPermissions(dir.path(), readable | QFile::WriteOwner);
    const QString folder = dir.filePath(QStringLiteral("readonly"));
    QVERIFY(QDir(dir.path()).mkdir(QStringLiteral("readonly")));
    const QString out = writeFile(dir, QStringLiteral("readonly/old.st"), QStringLiteral("(* old *)"));
    QFile::setPermissions(folder, readable);
    const Result result = cli({QStringLiteral("convert"), example(), out}, [] {
        if (geteuid() == 0) { // root writes anywhere: convert as nobody
            constexpr uid_t kNobody = 65534;
            if (setgid(kNobody) != 0 || setuid(kNobody) != 0)
                _exit(99);
        }
    });
    QFile::setPermissions(folder, readable | QFile::WriteOwner);
    QCOMPARE(result.exitCode, 3);
    QCOMPARE(result.err, QStringLiteral("iecstudio-cli: %1 was not saved: the folder %2 is read-only, or you may not write in it. "
                                        "The file on the disk is unchanged.\n")
                             .arg(QDir::toNativeSeparators(out), QDir::toNativeSeparators(folder)));
    QCOMPARE(contents(out), QByteArray("(* old *)"));
    QCOMPARE(QDir(folder).entryList(QDir::Files | QDir::Hidden), QStringList {QStringLiteral("old.st")});
}

QTEST_GUILESS_MAIN(TestCliRobustness)
#include "tst_cli_robustness.moc"
