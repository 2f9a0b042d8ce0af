#include "app/cli/runoptions.h"

#include "interpreter/frontend/duration.h"

#include <QRegularExpression>

namespace iec::cli {

namespace {

// NAME=VALUE or NAME=VALUE@CYCLE. A value may itself contain '=' or '@' ('a=b@c'), so the cycle
// is only what follows the last '@' when that is a number.
std::optional<ScheduledWrite> parseWrite(const QString &text, QString &error)
{
    const qsizetype equals = text.indexOf(QLatin1Char('='));
    if (equals <= 0) {
        error = QStringLiteral("--set needs NAME=VALUE or NAME=VALUE@CYCLE, not '%1'.").arg(text);
        return std::nullopt;
    }
    ScheduledWrite write {text.left(equals).trimmed(), text.mid(equals + 1).trimmed(), 1};
    static const QRegularExpression cycleSuffix(QStringLiteral("@(\\d+)$"));
    const QRegularExpressionMatch match = cycleSuffix.match(write.value);
    if (match.hasMatch()) {
        write.cycle = match.captured(1).toInt();
        write.value.chop(match.capturedLength(0));
        if (write.cycle < 1) {
            error = QStringLiteral("--set %1: cycles are counted from 1.").arg(text);
            return std::nullopt;
        }
    }
    return write;
}

bool isTraceFile(const QString &path)
{
    return path.endsWith(QLatin1String(".csv"), Qt::CaseInsensitive)
        || path.endsWith(QLatin1String(".vcd"), Qt::CaseInsensitive);
}

// Applies one option with its value; false (and `error`) when the value is wrong.
bool applyOption(RunOptions &options, const QString &option, const QString &value, QString &error)
{
    if (option == QLatin1String("--program")) {
        options.program = value;
    } else if (option == QLatin1String("--cycles")) {
        bool ok = false;
        options.cycles = value.toInt(&ok);
        if (!ok || options.cycles < 0)
            error = QStringLiteral("--cycles needs a whole number of cycles, not '%1'.").arg(value);
    } else if (option == QLatin1String("--cycle-time")) {
        options.cycleNs = interp::frontend::parseDuration(value);
        if (!options.cycleNs || *options.cycleNs <= 0)
            error
                = QStringLiteral("--cycle-time needs a duration above zero such as 10ms, T#10ms or PT0.01S, not '%1'.")
                      .arg(value);
    } else if (option == QLatin1String("--set")) {
        if (const auto write = parseWrite(value, error))
            options.writes.push_back(*write);
    } else if (option == QLatin1String("--watch")) {
        options.watches << value;
    } else if (option == QLatin1String("--trace")) {
        options.trace = value;
        if (!isTraceFile(value))
            error = QStringLiteral("--trace writes a .csv or a .vcd file, not '%1'.").arg(value);
    } else {
        error = QStringLiteral("Unknown option '%1'.").arg(option);
    }
    return error.isEmpty();
}

} // namespace

std::optional<RunOptions> parseRunOptions(const QStringList &arguments, QString &error)
{
    RunOptions options;
    for (qsizetype i = 0; i < arguments.size(); ++i) {
        const QString &argument = arguments.at(i);
        if (!argument.startsWith(QLatin1String("--"))) {
            if (!options.file.isEmpty()) {
                error = QStringLiteral("run takes one FILE; '%1' is one too many.").arg(argument);
                return std::nullopt;
            }
            options.file = argument;
            continue;
        }
        if (i + 1 >= arguments.size()) {
            error = QStringLiteral("%1 needs a value.").arg(argument);
            return std::nullopt;
        }
        if (!applyOption(options, argument, arguments.at(++i), error))
            return std::nullopt;
    }
    if (options.file.isEmpty()) {
        error = QStringLiteral("run needs a FILE (.xml, .st or .exp).");
        return std::nullopt;
    }
    return options;
}

} // namespace iec::cli
