#pragma once

#include <QDateTime>
#include <QList>
#include <QObject>
#include <QTimer>

namespace iec::model {
struct Project;
}

namespace iec::app {

// A recovery file left behind by a session that did not end cleanly.
struct Recovery {
    QString recoveryFile;
    QString projectFile; // the project it belongs to; empty for a project that was never saved
    QDateTime savedAt;

    bool operator==(const Recovery &) const = default;
};

// Autosave and crash recovery. While a project has unsaved changes, the window writes it every N
// minutes (PLCopen XML, atomically through QSaveFile) to a recovery file in
// QStandardPaths::AppDataLocation/recovery, named after the project; a clean save or close deletes
// it. A file that is still there at the next start, and newer than its project, is offered back.
// Beside each recovery file "<name>.source" holds the project's path (nothing for untitled ones).
class RecoveryManager : public QObject
{
    Q_OBJECT

public:
    explicit RecoveryManager(QObject *parent = nullptr);

    [[nodiscard]] static QString directory();
    // Recovery files newer than their project (or whose project is untitled or gone), newest first.
    [[nodiscard]] static QList<Recovery> pendingRecoveries();
    // What is known about one recovery file (its project, when it was written).
    [[nodiscard]] static Recovery describe(const QString &recoveryFile);
    // Deletes a recovery file and its .source companion.
    static void discard(const QString &recoveryFile);

    // The project now shown is `projectFile` (empty: untitled): later writes go to its file.
    void setProject(const QString &projectFile);
    // Continue writing to a recovered file (so a clean save removes it).
    void adopt(const Recovery &recovery);
    [[nodiscard]] QString recoveryFile() const { return m_recoveryFile; }

    bool write(const model::Project &project, QString *error = nullptr);
    // The project was saved or closed cleanly: its recovery file is not needed any more.
    void discardCurrent();

    // 0 turns autosave off. IECSTUDIO_AUTOSAVE_SECONDS=N in the environment writes every N
    // seconds instead, whatever the settings say (the recovery test waits for an autosave).
    void setIntervalMinutes(int minutes);
    [[nodiscard]] const QTimer &timer() const { return m_timer; }

Q_SIGNALS:
    // Time to write the recovery file (if there is anything unsaved).
    void autosaveDue();

private:
    QString m_projectFile;
    QString m_recoveryFile;
    QTimer m_timer;
};

} // namespace iec::app
