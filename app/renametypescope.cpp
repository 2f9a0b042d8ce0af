#include "app/renametypescope.h"

#include "interpreter/compiler/lexer.h"

namespace iec::app {

namespace {

bool sameName(QStringView a, QStringView b)
{
    return a.compare(b, Qt::CaseInsensitive) == 0;
}

} // namespace

QString renameMembers(const QString &text, const TypeScope &scope, const QString &typeName, const Renames &renames)
{
    TokenText tokens(text);
    struct Bracket {
        bool call = false;
        bool callsType = false; // a call of an instance of typeName, or of the function itself
        const model::DataType *element = nullptr; // '[': the type after the closing ']'
    };
    std::vector<Bracket> open;
    const model::DataType *current = nullptr; // the type of the expression just read
    QStringView currentPou; // a bare POU name just read (a function about to be called)
    for (size_t i = 0; i < tokens.size(); ++i) {
        const QStringView word = tokens.word(i);
        if (tokens.is(i, interp::TokenKind::Identifier)) {
            const bool inCall = !open.empty() && open.back().call;
            if (inCall && tokens.isAssignmentAfter(i)) {
                if (const QString *newName = open.back().callsType ? newNameOf(renames, word) : nullptr)
                    tokens.replace(i, *newName);
                current = nullptr;
                currentPou = {};
                continue;
            }
            current = scope.variableType(word);
            currentPou = !current && scope.isPou(word) ? word : QStringView();
            continue;
        }
        if (tokens.isOperator(i, u".") && tokens.is(i + 1, interp::TokenKind::Identifier)) {
            const QStringView member = tokens.word(i + 1);
            if (scope.isType(current, typeName)) {
                if (const QString *newName = newNameOf(renames, member))
                    tokens.replace(i + 1, *newName);
            }
            current = scope.memberType(current, member);
            currentPou = {};
            ++i;
            continue;
        }
        if (tokens.isOperator(i, u"[")) {
            open.push_back({.element = scope.elementType(current)});
            current = nullptr;
        } else if (tokens.isOperator(i, u"]")) {
            current = !open.empty() && !open.back().call ? open.back().element : nullptr;
            if (!open.empty())
                open.pop_back();
        } else if (tokens.isOperator(i, u"(")) {
            const bool callsType = current ? scope.isType(current, typeName) : sameName(currentPou, typeName);
            open.push_back({.call = true, .callsType = callsType});
            current = nullptr;
        } else {
            if (tokens.isOperator(i, u")") && !open.empty())
                open.pop_back();
            current = nullptr;
        }
        currentPou = {};
    }
    return tokens.result();
}

} // namespace iec::app
