#include "editors/text/commenttoggle.h"

namespace iec::editors {

namespace {

bool isWholeLineComment(const QString &line)
{
    const QString trimmed = line.trimmed();
    return trimmed.size() >= 4 && trimmed.startsWith(QLatin1String("(*")) && trimmed.endsWith(QLatin1String("*)"));
}

QString uncomment(const QString &line)
{
    const qsizetype open = line.indexOf(QLatin1String("(*"));
    const qsizetype close = line.lastIndexOf(QLatin1String("*)"));
    qsizetype innerStart = open + 2;
    qsizetype innerEnd = close;
    if (innerStart < innerEnd && line[innerStart] == QLatin1Char(' '))
        ++innerStart;
    if (innerEnd > innerStart && line[innerEnd - 1] == QLatin1Char(' '))
        --innerEnd;
    return line.left(open) + line.mid(innerStart, innerEnd - innerStart) + line.mid(close + 2);
}

QString comment(const QString &line)
{
    qsizetype indent = 0;
    while (indent < line.size() && line[indent].isSpace())
        ++indent;
    qsizetype end = line.size();
    while (end > indent && line[end - 1].isSpace())
        --end;
    return line.left(indent) + QLatin1String("(* ") + line.mid(indent, end - indent) + QLatin1String(" *)");
}

} // namespace

QStringList toggleLineComments(const QStringList &lines)
{
    bool allCommented = true;
    bool anyText = false;
    for (const QString &line : lines) {
        if (line.trimmed().isEmpty())
            continue;
        anyText = true;
        allCommented = allCommented && isWholeLineComment(line);
    }
    if (!anyText)
        return lines;
    QStringList result;
    result.reserve(lines.size());
    for (const QString &line : lines) {
        if (line.trimmed().isEmpty())
            result.append(line);
        else
            result.append(allCommented ? uncomment(line) : comment(line));
    }
    return result;
}

} // namespace iec::editors
