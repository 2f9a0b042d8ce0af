#include "editors/text/completion.h"

#include "editors/text/standardlibrary.h"

#include <QSet>

#include <algorithm>

namespace iec::editors {

bool isIdentifierChar(QChar c)
{
    return c.isLetterOrNumber() || c == QLatin1Char('_');
}

CompletionContext completionContext(QStringView line, int column)
{
    column = std::clamp(column, 0, int(line.size()));
    CompletionContext context;
    int start = column;
    while (start > 0 && isIdentifierChar(line[start - 1]))
        --start;
    context.prefix = line.mid(start, column - start).toString();
    context.prefixStart = start;
    if (start == 0 || line[start - 1] != QLatin1Char('.'))
        return context;

    // Walk back over the path: identifiers, dots and [index] groups.
    const int pathEnd = start - 1;
    int i = pathEnd;
    while (i > 0) {
        const QChar c = line[i - 1];
        if (isIdentifierChar(c) || c == QLatin1Char('.')) {
            --i;
        } else if (c == QLatin1Char(']')) {
            int depth = 0;
            int j = i - 1;
            for (; j >= 0; --j) {
                if (line[j] == QLatin1Char(']'))
                    ++depth;
                else if (line[j] == QLatin1Char('[') && --depth == 0)
                    break;
            }
            if (j < 0)
                break;
            i = j;
        } else {
            break;
        }
    }
    context.memberPath = line.mid(i, pathEnd - i).toString();
    return context;
}

QList<CompletionItem> completionItems(
    const CompletionContext &context, const CompletionProvider *provider, TextLanguage language)
{
    QList<CompletionItem> candidates;
    if (!context.memberPath.isEmpty()) {
        if (provider) {
            candidates = provider->members(context.memberPath);
            if (candidates.isEmpty()) {
                if (const StdPou *fb = findStandardPou(provider->typeOf(context.memberPath));
                    fb && fb->kind == StdPou::Kind::FunctionBlock) {
                    for (const StdParameter &p : fb->inputs)
                        candidates.append({p.name, CompletionItem::Kind::Member, p.type, {}});
                    for (const StdParameter &p : fb->outputs)
                        candidates.append({p.name, CompletionItem::Kind::Member, p.type, {}});
                }
            }
        }
    } else {
        if (provider) {
            candidates += provider->variables();
            candidates += provider->pous();
        }
        for (const StdPou &pou : standardPous()) {
            candidates.append({pou.name,
                pou.kind == StdPou::Kind::Function ? CompletionItem::Kind::Function
                                                   : CompletionItem::Kind::FunctionBlock,
                pou.signature(), stdCategoryName(pou.category)});
        }
        for (const QString &keyword : completionKeywords(language)) {
            const bool type = elementaryTypeNames().contains(keyword);
            candidates.append({keyword, type ? CompletionItem::Kind::TypeName : CompletionItem::Kind::Keyword, {}, {}});
        }
    }

    QList<CompletionItem> result;
    QSet<QString> seen;
    for (const CompletionItem &item : std::as_const(candidates)) {
        if (!item.text.startsWith(context.prefix, Qt::CaseInsensitive))
            continue;
        const QString key = item.text.toUpper();
        if (seen.contains(key))
            continue; // the provider's own names come first and win
        seen.insert(key);
        result.append(item);
    }
    std::stable_sort(result.begin(), result.end(), [](const CompletionItem &a, const CompletionItem &b) {
        return a.text.compare(b.text, Qt::CaseInsensitive) < 0;
    });
    return result;
}

} // namespace iec::editors
