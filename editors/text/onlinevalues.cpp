#include "editors/text/onlinevalues.h"

#include "interpreter/compiler/lexer.h"

#include <QFontMetrics>
#include <QPainter>
#include <QRectF>

namespace iec::editors {

namespace {

constexpr int kMaxValueLength = 24;
constexpr qreal kChipGap = 6;
constexpr qreal kChipPadding = 4;

using interp::Token;
using interp::TokenKind;

bool isOperator(QStringView line, const Token &token, QStringView op)
{
    return token.kind == TokenKind::Operator && line.mid(token.offset, token.length) == op;
}

// Reads one path starting at tokens[i] (an identifier) and leaves `i` on its last token. A
// computed index gives an empty path with `i` before the "[", so the index itself is read next.
QString readPath(QStringView line, const std::vector<Token> &tokens, size_t &i)
{
    QString path = line.mid(tokens[i].offset, tokens[i].length).toString();
    while (i + 1 < tokens.size()) {
        const Token &next = tokens[i + 1];
        if (isOperator(line, next, u".") && i + 2 < tokens.size() && tokens[i + 2].kind == TokenKind::Identifier) {
            path += QLatin1Char('.') + line.mid(tokens[i + 2].offset, tokens[i + 2].length);
            i += 2;
        } else if (isOperator(line, next, u".") && i + 2 < tokens.size()
                   && tokens[i + 2].kind == TokenKind::IntegerLiteral) {
            path += QLatin1Char('.') + line.mid(tokens[i + 2].offset, tokens[i + 2].length); // a bit: w.3
            i += 2;
        } else if (isOperator(line, next, u"[")) {
            // Literal indexes only: A[2] or M[1, 2]; anything else depends on the moment.
            size_t j = i + 2;
            bool showable = true;
            QString index;
            while (j < tokens.size() && !isOperator(line, tokens[j], u"]")) {
                const Token &part = tokens[j];
                const bool literal = part.kind == TokenKind::IntegerLiteral || isOperator(line, part, u",")
                    || isOperator(line, part, u"-");
                showable = showable && literal;
                index += line.mid(part.offset, part.length);
                if (isOperator(line, part, u","))
                    index += QLatin1Char(' ');
                ++j;
            }
            // A computed index: the element is not shown, the variables in the index are.
            if (j >= tokens.size() || !showable)
                return {};
            path += QLatin1Char('[') + index + QLatin1Char(']');
            i = j;
        } else {
            break;
        }
    }
    return path;
}

} // namespace

std::vector<QStringList> variablePathsByLine(const QString &text)
{
    const QStringList lines = text.split(QLatin1Char('\n'));
    std::vector<QStringList> result(size_t(lines.size()));
    interp::LexState state;
    int parenDepth = 0;
    for (int lineNumber = 0; lineNumber < lines.size(); ++lineNumber) {
        const QStringView line = lines[lineNumber];
        const std::vector<Token> tokens = interp::tokenize(line, state);
        QStringList &paths = result[size_t(lineNumber)];
        for (size_t i = 0; i < tokens.size(); ++i) {
            const Token &token = tokens[i];
            if (isOperator(line, token, u"("))
                ++parenDepth;
            else if (isOperator(line, token, u")"))
                parenDepth = std::max(0, parenDepth - 1);
            const bool startsPath = token.kind == TokenKind::Identifier
                || (token.kind == TokenKind::DirectAddress && !line.mid(token.offset, token.length).contains(u'*'));
            // A member after a call result (F(x).y) is not a variable of its own.
            if (!startsPath || (i > 0 && isOperator(line, tokens[i - 1], u".")))
                continue;
            const size_t start = i;
            const QString path = token.kind == TokenKind::DirectAddress
                ? line.mid(token.offset, token.length).toString()
                : readPath(line, tokens, i);
            const Token *after = i + 1 < tokens.size() ? &tokens[i + 1] : nullptr;
            if (after && isOperator(line, *after, u"("))
                continue; // a call
            if (after && parenDepth > 0 && (isOperator(line, *after, u":=") || isOperator(line, *after, u"=>")))
                continue; // a formal parameter
            if (after && start == 0 && isOperator(line, *after, u":"))
                continue; // an IL label or a CASE label
            if (!path.isEmpty() && !paths.contains(path, Qt::CaseInsensitive))
                paths.append(path);
        }
    }
    return result;
}

QString onlineName(const QString &instance, const QString &path)
{
    if (path.startsWith(QLatin1Char('%')) || instance.isEmpty())
        return path;
    return instance + QLatin1Char('.') + path;
}

QString chipText(const OnlineChip &chip)
{
    QString value = chip.value;
    if (value.size() > kMaxValueLength)
        value = value.left(kMaxValueLength - 1) + QChar(0x2026);
    return chip.label + QStringLiteral(" = ") + value;
}

void paintOnlineChips(QPainter &painter, const QRectF &line, qreal x, const QList<OnlineChip> &chips,
                      const QFontMetrics &metrics)
{
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing);
    for (const OnlineChip &chip : chips) {
        if (chip.value.isEmpty())
            continue;
        const QString text = chipText(chip);
        const QString badge = chip.forced ? QStringLiteral("F") : QString();
        const qreal badgeWidth = badge.isEmpty() ? 0 : metrics.horizontalAdvance(badge) + 2 * kChipPadding;
        const QRectF box(x, line.top() + 1, metrics.horizontalAdvance(text) + 2 * kChipPadding + badgeWidth,
                         line.height() - 2);
        const bool isTrue = chip.value == QLatin1String("TRUE");
        const bool isFalse = chip.value == QLatin1String("FALSE");
        const QColor fill = isTrue ? QColor(0xc8, 0xf0, 0xc8) : isFalse ? QColor(0xee, 0xee, 0xee) : QColor(0xdd, 0xea, 0xfb);
        painter.setPen(chip.forced ? QPen(QColor(0xd0, 0x20, 0x20), 1.5) : QPen(QColor(0xa8, 0xb8, 0xcc)));
        painter.setBrush(fill);
        painter.drawRoundedRect(box, 3, 3);
        if (!badge.isEmpty()) {
            const QRectF badgeBox(box.left(), box.top(), badgeWidth, box.height());
            painter.setPen(Qt::NoPen);
            painter.setBrush(QColor(0xd0, 0x20, 0x20));
            painter.drawRoundedRect(badgeBox, 3, 3);
            painter.setPen(Qt::white);
            painter.drawText(badgeBox, Qt::AlignCenter, badge);
        }
        painter.setPen(QColor(0x20, 0x30, 0x50));
        painter.drawText(box.adjusted(kChipPadding + badgeWidth, 0, -kChipPadding, 0), Qt::AlignVCenter | Qt::AlignLeft,
                         text);
        x = box.right() + kChipGap;
    }
    painter.restore();
}

} // namespace iec::editors
