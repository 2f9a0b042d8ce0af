#pragma once

// Runs an example through `iecstudio-cli run ... --trace out.csv` as a user would, and returns
// the trace as one map per cycle (watched name -> value text), for the examples' acceptance tests.

#include <QFile>
#include <QMap>
#include <QProcess>
#include <QStringList>
#include <QTemporaryDir>

#include <vector>

namespace iec::testing {

struct CliTrace {
    QString error;                        // empty when the run succeeded
    std::vector<QMap<QString, QString>> cycles; // cycles[0] is cycle 1
};

inline CliTrace runExample(const QString &example, int cycles, const QStringList &sets, const QStringList &watches)
{
    CliTrace result;
    QTemporaryDir dir;
    const QString csv = dir.filePath(QStringLiteral("trace.csv"));
    QStringList arguments {QStringLiteral("run"), QStringLiteral(IEC_SOURCE_DIR "/resources/examples/") + example,
        QStringLiteral("--cycles"), QString::number(cycles), QStringLiteral("--cycle-time"), QStringLiteral("10ms")};
    for (const QString &set : sets)
        arguments << QStringLiteral("--set") << set;
    for (const QString &watch : watches)
        arguments << QStringLiteral("--watch") << watch;
    arguments << QStringLiteral("--trace") << csv;
    QProcess process;
    process.start(QStringLiteral(IECSTUDIO_CLI), arguments);
    if (!process.waitForFinished(120'000) || process.exitStatus() != QProcess::NormalExit || process.exitCode() != 0) {
        result.error = QStringLiteral("iecstudio-cli failed: ") + QString::fromUtf8(process.readAllStandardError());
        return result;
    }
    QFile file(csv);
    if (!file.open(QIODevice::ReadOnly)) {
        result.error = QStringLiteral("no trace written");
        return result;
    }
    const QStringList lines = QString::fromUtf8(file.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    const QStringList header = lines.value(0).split(QLatin1Char(','));
    for (qsizetype i = 1; i < lines.size(); ++i) {
        const QStringList fields = lines[i].split(QLatin1Char(','));
        QMap<QString, QString> row;
        for (qsizetype f = 0; f < header.size() && f < fields.size(); ++f)
            row.insert(header[f], fields[f]);
        result.cycles.push_back(row);
    }
    if (int(result.cycles.size()) != cycles)
        result.error = QStringLiteral("%1 cycles traced, expected %2").arg(result.cycles.size()).arg(cycles);
    return result;
}

// "TRUE"/"FALSE" for a boolean expectation.
inline QString boolText(bool value)
{
    return value ? QStringLiteral("TRUE") : QStringLiteral("FALSE");
}

} // namespace iec::testing
