#include "interpreter/frontend/duration.h"

#include "interpreter/compiler/literals.h"

#include <QRegularExpression>


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
    // Said again as an IEC duration (1d2h3m4.5s), which is read exactly and refused when it does
    // not fit in 64 bits (a double overflowed here; found by fuzz_values).
    constexpr const char *kUnits[] = {"d", "h", "m", "s"};
    QString iec = match.capturedView(1).toString();
    for (int part = 0; part < 4; ++part) {
        if (!match.capturedView(part + 2).isEmpty())
            iec += match.capturedView(part + 2) + QLatin1String(kUnits[part]);
    }
    return decodeDuration(iec);
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
