#include "interpreter/frontend/sourcefile.h"

#include "interpreter/compiler/literals.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <QStringDecoder>

#include <optional>

namespace iec::interp::frontend {

namespace {

// The first line that is not UTF-8 (1-based), for the note.
int firstLineNotUtf8(const QByteArray &bytes)
{
    int line = 1;
    for (qsizetype start = 0; start <= bytes.size(); ++line) {
        qsizetype end = bytes.indexOf('\n', start);
        if (end < 0)
            end = bytes.size();
        QStringDecoder utf8(QStringDecoder::Utf8, QStringDecoder::Flag::Stateless);
        const QString text = utf8.decode(QByteArrayView(bytes).sliced(start, end - start)); // decodes when converted
        if (utf8.hasError())
            return line;
        start = end + 1;
    }
    return 1;
}

// \r\n and a lone \r become \n; export marker lines become empty.
void tidyLines(QString &text)
{
    text.replace(QLatin1String("\r\n"), QLatin1String("\n"));
    text.replace(QLatin1Char('\r'), QLatin1Char('\n'));
    if (!text.contains(QLatin1String("(* @")))
        return;
    static const QRegularExpression marker(QStringLiteral(R"(^[ \t]*\(\* @[A-Z_]+ := '[^'\n]*' \*\)[ \t]*$)"),
        QRegularExpression::MultilineOption);
    text.replace(marker, QString());
}

} // namespace

SourceText decodeSourceFile(const QByteArray &bytes)
{
    SourceText source;
    // A byte order mark of UTF-16 or UTF-32 (Windows editors save so): that encoding.
    if (const std::optional<QStringConverter::Encoding> marked = QStringConverter::encodingForData(bytes);
        marked && *marked != QStringConverter::Utf8) {
        QStringDecoder wide(*marked);
        source.text = wide.decode(bytes);
        tidyLines(source.text);
        return source;
    }
    QStringDecoder utf8(QStringDecoder::Utf8, QStringDecoder::Flag::Stateless);
    source.text = utf8.decode(bytes);
    if (utf8.hasError()) {
        source.windows1252Line = firstLineNotUtf8(bytes);
        source.text.clear();
        source.text.reserve(bytes.size());
        for (const char byte : bytes)
            source.text.append(windows1252Char(static_cast<std::uint8_t>(byte)));
    } else if (source.text.startsWith(QChar(0xFEFF))) {
        source.text.remove(0, 1);
    }
    tidyLines(source.text);
    return source;
}

QString windows1252Note()
{
    return QCoreApplication::translate("iec::interp::Compiler",
        "The file is not UTF-8: it was read as Windows-1252, the code page CoDeSys 2.3 writes, so that its umlauts "
        "and other special characters are kept.");
}

} // namespace iec::interp::frontend
