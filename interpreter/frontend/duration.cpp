#include "interpreter/frontend/duration.h"

#include "interpreter/compiler/literals.h"

#include <QRegularExpression>

#include <cmath>

namespace iec::interp::frontend {

namespace {

// PnDTnHnMn.nS (XML Schema's xsd:duration without years and months, which have no fixed length).
std::optional<std::int64_t> parseIsoDuration(QStringView text)
{
    static const QRegularExpression pattern(QStringLiteral("^(-)?P(?:(\\d+(?:\\.\\d+)?)D)?(?:T(?:(\\d+(?:\\.\\d+)?)H)?("
                                                           "?:(\\d+(?:\\.\\d+)?)M)?(?:(\\d+(?:\\.\\d+)?)S)?)?$"),
        QRegularExpression::CaseInsensitiveOption);
    const QRegularExpressionMatch match = pattern.match(text.toString());
    if (!match.hasMatch() || text.size() < 3 || text.endsWith(u'T') || text.endsWith(u't'))
        return std::nullopt;
    constexpr double kUnits[] = {86'400e9, 3'600e9, 60e9, 1e9};
    double ns = 0;
    for (int part = 0; part < 4; ++part)
        ns += match.capturedView(part + 2).toDouble() * kUnits[part];
    const auto rounded = static_cast<std::int64_t>(std::llround(ns));
    return match.capturedView(1).isEmpty() ? rounded : -rounded;
}

} // namespace

std::optional<std::int64_t> parseDuration(QStringView text)
{
    text = text.trimmed();
    if (text.startsWith(u'P', Qt::CaseInsensitive) || text.startsWith(QLatin1String("-P"), Qt::CaseInsensitive))
        return parseIsoDuration(text);
    const LiteralParts parts = splitTypedLiteral(text);
    const bool timeLiteral = parts.typePrefix.isEmpty()
        || parts.typePrefix.compare(QLatin1String("T"), Qt::CaseInsensitive) == 0
        || parts.typePrefix.compare(QLatin1String("TIME"), Qt::CaseInsensitive) == 0
        || parts.typePrefix.compare(QLatin1String("LT"), Qt::CaseInsensitive) == 0
        || parts.typePrefix.compare(QLatin1String("LTIME"), Qt::CaseInsensitive) == 0;
    if (!timeLiteral || parts.body.isEmpty())
        return std::nullopt;
    return decodeDuration(parts.body);
}

} // namespace iec::interp::frontend
