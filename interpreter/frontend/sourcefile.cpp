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
    useLfLineEnds(text);
    if (!text.contains(QLatin1String("(* @")))
        return;
    static const QRegularExpression marker(QStringLiteral(R"(^[ \t]*\(\* @[A-Z_]+ := '[^'\n]*' \*\)[ \t]*$)"),
        QRegularExpression::MultilineOption);
    text.replace(marker, QString());
}

// CoDeSys 2.3 exports an LD, FBD, CFC or SFC body as its own graphical form (_LD_BODY, _NETWORKS : 2,
// _LD_CONTACT, ...), which is not IEC text. Each such body is turned into a comment, line by line so
// that the file keeps its line numbers and the POU keeps the content, headed by an {error} pragma:
// the parser reports it at the body, under the POU's name, and the rest of the file is still checked.
void commentOutGraphicalBodies(QString &text)
{
    if (!text.contains(QLatin1String("_BODY")))
        return;
    static const QRegularExpression start(QStringLiteral(R"(^[ \t]*_([A-Z]+)_BODY[ \t]*$)"));
    static const QRegularExpression end(
        QStringLiteral(R"(^[ \t]*END_(PROGRAM|FUNCTION_BLOCK|FUNCTION|ACTION|TRANSITION|METHOD|PROPERTY)[ \t;]*$)"));
    // Where the next POU starts, should the body's end be missing: it is not swallowed too.
    static const QRegularExpression next(
        QStringLiteral(R"(^[ \t]*((PROGRAM|FUNCTION_BLOCK|FUNCTION|TYPE|CONFIGURATION)[ \t]+\S|VAR_GLOBAL\b))"));
    QStringList lines = text.split(QLatin1Char('\n'));
    bool inside = false;
    for (QString &line : lines) {
        if (inside && (end.match(line).hasMatch() || next.match(line).hasMatch())) {
            inside = false;
        } else if (inside) {
            line.prepend(QLatin1String("// "));
        } else if (const QRegularExpressionMatch match = start.match(line); match.hasMatch()) {
            inside = true;
            QString message = QCoreApplication::translate("iec::interp::Compiler",
                "CoDeSys 2.3 exported this %1 body in its own graphical form, which IEC Studio does not read; it is kept "
                "below as a comment. Export the POU from CoDeSys as PLCopen XML to open it as a diagram.")
                                  .arg(match.captured(1));
            message.replace(QLatin1Char('}'), QLatin1Char(')')).remove(QLatin1Char('\''));
            line = QStringLiteral("{error '%1'} // %2").arg(message, line.trimmed());
        }
    }
    text = lines.join(QLatin1Char('\n'));
}

} // namespace

void useLfLineEnds(QString &text)
{
    text.replace(QLatin1String("\r\n"), QLatin1String("\n"));
    text.replace(QLatin1Char('\r'), QLatin1Char('\n'));
}

SourceText decodeSourceFile(const QByteArray &bytes)
{
    SourceText source;
    // A byte order mark of UTF-16 or UTF-32 (Windows editors save so): that encoding.
    if (const std::optional<QStringConverter::Encoding> marked = QStringConverter::encodingForData(bytes);
        marked && *marked != QStringConverter::Utf8) {
        QStringDecoder wide(*marked);
        source.text = wide.decode(bytes);
        tidyLines(source.text);
        commentOutGraphicalBodies(source.text);
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
    commentOutGraphicalBodies(source.text);
    return source;
}

QString windows1252Note()
{
    return QCoreApplication::translate("iec::interp::Compiler",
        "The file is not UTF-8: it was read as Windows-1252, the code page CoDeSys 2.3 writes, so that its umlauts "
        "and other special characters are kept.");
}

} // namespace iec::interp::frontend
