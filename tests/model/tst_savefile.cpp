// saveFileAtomically, the one path every save takes: the file is the old one or the new one,
// never a part, and a failure says why in a sentence. A full disk is a file size limit
// (RLIMIT_FSIZE: writes beyond it fail with EFBIG, as they fail with ENOSPC on a full disk); a
// read-only folder is a folder without write permission, written by a user who is not root (a
// forked child gives up root's rights first).
#include "model/savefile.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <csignal>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace iec::model;

namespace {

QByteArray contents(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray("<missing>");
}

void writePlain(const QString &path, const QByteArray &bytes)
{
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    QCOMPARE(file.write(bytes), bytes.size());
}

QStringList entries(const QString &folder)
{
    return QDir(folder).entryList(QDir::Files | QDir::Hidden | QDir::NoDotAndDotDot);
}

// While it lives, files this process writes may not grow beyond `bytes`, and going beyond gives
// an error (EFBIG) instead of the signal that would end the process.
class FileSizeLimit
{
public:
    explicit FileSizeLimit(rlim_t bytes)
    {
        getrlimit(RLIMIT_FSIZE, &m_before);
        m_handler = std::signal(SIGXFSZ, SIG_IGN);
        rlimit limited = m_before;
        limited.rlim_cur = bytes;
        setrlimit(RLIMIT_FSIZE, &limited);
    }
    ~FileSizeLimit()
    {
        setrlimit(RLIMIT_FSIZE, &m_before);
        std::signal(SIGXFSZ, m_handler);
    }
    FileSizeLimit(const FileSizeLimit &) = delete;
    FileSizeLimit &operator=(const FileSizeLimit &) = delete;

private:
    rlimit m_before {};
    void (*m_handler)(int) = nullptr;
};

// Saves as a user without root's rights (root writes into read-only folders): in a forked child
// that gives them up, when this process is root. Returns the error text, or "saved".
QString saveUnprivileged(const QString &path, const QByteArray &bytes)
{
    const auto save = [&] {
        QString error;
        return saveFileAtomically(path, bytes, &error) ? QStringLiteral("saved") : error;
    };
    if (geteuid() != 0)
        return save();
    int channel[2];
    if (pipe(channel) != 0)
        return QStringLiteral("<no pipe>");
    const pid_t child = fork();
    if (child == 0) {
        close(channel[0]);
        constexpr uid_t kNobody = 65534;
        const QByteArray answer = (setgid(kNobody) == 0 && setuid(kNobody) == 0) ? save().toUtf8() : QByteArray("<still root>");
        const ssize_t written = write(channel[1], answer.constData(), size_t(answer.size()));
        _exit(written == answer.size() ? 0 : 1);
    }
    close(channel[1]);
    QByteArray answer;
    char buffer[4096];
    for (ssize_t n; (n = read(channel[0], buffer, sizeof buffer)) > 0;)
        answer.append(buffer, n);
    close(channel[0]);
    int status = 0;
    waitpid(child, &status, 0);
    return QString::fromUtf8(answer);
}

} // namespace

class TestSaveFile : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void replacesTheFile();
    void missingFolderIsNamed();
    void folderInTheWay();
    void fullDiskLeavesTheOldFile_data();
    void fullDiskLeavesTheOldFile();
    void readOnlyFolderLeavesTheOldFile();
};

void TestSaveFile::replacesTheFile()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("p.xml"));
    writePlain(path, "old");
    QString error;
    QVERIFY(saveFileAtomically(path, "new contents", &error));
    QCOMPARE(contents(path), QByteArray("new contents"));
    QCOMPARE(entries(dir.path()), QStringList {QStringLiteral("p.xml")});
    QVERIFY(error.isEmpty());
}

void TestSaveFile::missingFolderIsNamed()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("missing/p.xml"));
    QString error;
    QVERIFY(!saveFileAtomically(path, "x", &error));
    QCOMPARE(error, QStringLiteral("%1 was not saved: the folder %2 does not exist. The file on the disk is unchanged.")
                        .arg(QDir::toNativeSeparators(path), QDir::toNativeSeparators(dir.filePath(QStringLiteral("missing")))));
}

void TestSaveFile::folderInTheWay()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("p.xml"));
    QVERIFY(QDir(dir.path()).mkdir(QStringLiteral("p.xml")));
    QString error;
    QVERIFY(!saveFileAtomically(path, "x", &error));
    QCOMPARE(error, QStringLiteral("%1 was not saved: a folder of that name is in the way. The file on the disk is unchanged.")
                        .arg(QDir::toNativeSeparators(path)));
}

void TestSaveFile::fullDiskLeavesTheOldFile_data()
{
    QTest::addColumn<int>("limit");
    QTest::addColumn<int>("size");
    QTest::newRow("1 MB beyond 64 KB") << 64 * 1024 << 1024 * 1024;
    // Below Qt's write buffer: the bytes reach the disk only when QSaveFile commits.
    QTest::newRow("1851 bytes beyond 1 KB") << 1024 << 1851;
}

void TestSaveFile::fullDiskLeavesTheOldFile()
{
    QFETCH(int, limit);
    QFETCH(int, size);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("p.xml"));
    const QByteArray old(100, 'o');
    writePlain(path, old);
    QString error;
    bool saved = true;
    {
        const FileSizeLimit limited {rlim_t(limit)};
        saved = saveFileAtomically(path, QByteArray(size, 'n'), &error);
    }
    QVERIFY(!saved);
    QCOMPARE(error, QStringLiteral("%1 was not saved: the file would be larger than the system allows. The file on the disk is unchanged.")
                        .arg(QDir::toNativeSeparators(path)));
    QCOMPARE(contents(path), old);
    QCOMPARE(entries(dir.path()), QStringList {QStringLiteral("p.xml")}); // no half-written temporary file
}

void TestSaveFile::readOnlyFolderLeavesTheOldFile()
{
    QTemporaryDir dir;
    QFile::setPermissions(dir.path(), QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner | QFile::ReadOther | QFile::ExeOther
                                          | QFile::ReadGroup | QFile::ExeGroup);
    const QString folder = dir.filePath(QStringLiteral("readonly"));
    QVERIFY(QDir(dir.path()).mkdir(QStringLiteral("readonly")));
    const QString path = folder + QStringLiteral("/p.xml");
    writePlain(path, "old");
    QFile::setPermissions(path, QFile::ReadOwner | QFile::WriteOwner | QFile::ReadOther | QFile::WriteOther);
    QFile::setPermissions(folder, QFile::ReadOwner | QFile::ExeOwner | QFile::ReadOther | QFile::ExeOther | QFile::ReadGroup | QFile::ExeGroup);
    const QString answer = saveUnprivileged(path, "new");
    QFile::setPermissions(folder, QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
    QCOMPARE(answer, QStringLiteral("%1 was not saved: the folder %2 is read-only, or you may not write in it. The file on the disk is unchanged.")
                         .arg(QDir::toNativeSeparators(path), QDir::toNativeSeparators(folder)));
    QCOMPARE(contents(path), QByteArray("old"));
    QCOMPARE(entries(folder), QStringList {QStringLiteral("p.xml")});
}

QTEST_GUILESS_MAIN(TestSaveFile)
#include "tst_savefile.moc"
