#pragma once

// Runs iecstudio-cli as users run it, for the command-line tests (tst_cli, tst_cli_robustness).
#include <QFile>
#include <QProcess>
#include <QString>
#include <QStringList>
#include <QTemporaryDir>

#include <functional>

namespace clirun {

struct Result {
    int exitCode = -1; // -2: it crashed; -1: it did not finish
    QString out;
    QString err;
};

// `inChild` runs in the child between fork and exec (limits, rights).
inline Result cli(const QStringList &arguments, const std::function<void()> &inChild = {})
{
    QProcess process;
    if (inChild)
        process.setChildProcessModifier(inChild);
    process.start(QStringLiteral(IECSTUDIO_CLI), arguments);
    if (!process.waitForFinished(300'000))
        return {};
    return {process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -2,
        QString::fromUtf8(process.readAllStandardOutput()), QString::fromUtf8(process.readAllStandardError())};
}

// Writes `text` into `dir` as `name` and returns its path.
inline QString writeFile(const QTemporaryDir &dir, const QString &name, const QString &text)
{
    const QString path = dir.filePath(name);
    QFile file(path);
    if (file.open(QIODevice::WriteOnly))
        file.write(text.toUtf8());
    return path;
}

} // namespace clirun
