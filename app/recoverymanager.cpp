#include "app/recoverymanager.h"

#include "model/plcopen/writer.h"
#include "model/savefile.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>
#include <QUuid>

namespace iec::app {

namespace {

const QString kSourceSuffix = QStringLiteral(".source");

// Two projects with the same file name in different folders must not share a recovery file, so
// the name carries a hash of the full path; the base name keeps it recognisable.
QString recoveryFileName(const QString &projectFile)
{
    if (projectFile.isEmpty()) {
        return QStringLiteral("untitled-%1.xml").arg(QUuid::createUuid().toString(QUuid::WithoutBraces).left(8));
    }
    const QByteArray hash = QCryptographicHash::hash(projectFile.toUtf8(), QCryptographicHash::Sha1).toHex();
    return QStringLiteral("%1-%2.xml")
        .arg(QFileInfo(projectFile).completeBaseName(), QString::fromLatin1(hash.left(8)));
}

QString readSource(const QString &recoveryFile)
{
    QFile source(recoveryFile + kSourceSuffix);
    if (!source.open(QIODevice::ReadOnly))
        return {};
    return QString::fromUtf8(source.readAll());
}

} // namespace

RecoveryManager::RecoveryManager(QObject *parent)
    : QObject(parent)
{
    connect(&m_timer, &QTimer::timeout, this, &RecoveryManager::autosaveDue);
    setProject({});
}

QString RecoveryManager::directory()
{
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + QStringLiteral("/recovery");
}

QList<Recovery> RecoveryManager::pendingRecoveries()
{
    QList<Recovery> pending;
    const QDir recoveryDirectory(directory());
    for (const QFileInfo &file : recoveryDirectory.entryInfoList({QStringLiteral("*.xml")}, QDir::Files, QDir::Time)) {
        const Recovery recovery = describe(file.absoluteFilePath());
        const QFileInfo project(recovery.projectFile);
        // A project saved after the recovery file was written already holds the newer content.
        if (!recovery.projectFile.isEmpty() && project.exists() && project.lastModified() >= recovery.savedAt)
            continue;
        pending.append(recovery);
    }
    return pending;
}

Recovery RecoveryManager::describe(const QString &recoveryFile)
{
    const QFileInfo file(recoveryFile);
    return {file.absoluteFilePath(), readSource(file.absoluteFilePath()), file.lastModified()};
}

void RecoveryManager::discard(const QString &recoveryFile)
{
    QFile::remove(recoveryFile);
    QFile::remove(recoveryFile + kSourceSuffix);
}

void RecoveryManager::setProject(const QString &projectFile)
{
    m_projectFile = projectFile;
    m_recoveryFile = QDir(directory()).filePath(recoveryFileName(projectFile));
}

void RecoveryManager::adopt(const Recovery &recovery)
{
    m_projectFile = recovery.projectFile;
    m_recoveryFile = recovery.recoveryFile;
}

bool RecoveryManager::write(const model::Project &project, QString *error)
{
    if (!QDir().mkpath(directory())) {
        if (error)
            *error = tr("Cannot create the folder %1.").arg(directory());
        return false;
    }
    // The .source first: a recovery file is never there without the name of its project.
    return model::saveFileAtomically(m_recoveryFile + kSourceSuffix, m_projectFile.toUtf8(), error)
        && model::saveFileAtomically(m_recoveryFile, model::plcopen::writeProject(project), error);
}

void RecoveryManager::discardCurrent()
{
    discard(m_recoveryFile);
}

void RecoveryManager::setIntervalMinutes(int minutes)
{
    bool seconds = false;
    const int override = qEnvironmentVariableIntValue("IECSTUDIO_AUTOSAVE_SECONDS", &seconds);
    if (seconds && override > 0) {
        m_timer.start(override * 1000);
        return;
    }
    if (minutes <= 0) {
        m_timer.stop();
        return;
    }
    m_timer.start(minutes * 60 * 1000);
}

} // namespace iec::app
