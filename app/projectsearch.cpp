#include "app/projectsearch.h"

#include "editors/declarations/declarationtext.h"
#include "interpreter/compiler/lexer.h"
#include "interpreter/frontend/codesysmembers.h"
#include "interpreter/frontend/iecprinter.h"

#include <QRegularExpression>

#include <functional>

namespace iec::app {

using model::BodyRef;
using Access = SearchHit::Access;

namespace {

bool sameName(QStringView a, QStringView b)
{
    return a.compare(b, Qt::CaseInsensitive) == 0;
}

// A text a graphical element shows, and how the element uses the variable it names.
struct ElementText {
    QString text;
    Access access = Access::None;
    bool isVariable = false; // the text is a variable reference (an expression), not a label
};

// Every body the project tree opens, in its order: each POU's own body, its actions, its transitions.
void forEachBody(const model::Project &project, const std::function<void(const model::Pou &, const BodyRef &, const model::Body &)> &visit)
{
    for (const model::Pou &pou : project.types.pous) {
        if (const model::Body *body = pou.body())
            visit(pou, {pou.id, BodyRef::Part::Pou, {}}, *body);
        for (const model::PouPart &action : pou.actions)
            visit(pou, {pou.id, BodyRef::Part::Action, action.name}, action.body);
        for (const model::PouPart &transition : pou.transitions)
            visit(pou, {pou.id, BodyRef::Part::Transition, transition.name}, transition.body);
    }
}

QString placeOf(const model::Pou &pou, const BodyRef &ref)
{
    return ref.part == BodyRef::Part::Pou ? pou.name : pou.name + QLatin1Char('.') + ref.name;
}

QString inlineText(const model::Body &body)
{
    return body.isGraphical() ? QString() : body.text();
}

std::vector<ElementText> elementTexts(const model::Element &element)
{
    std::vector<ElementText> texts;
    const auto variable = [&](const QString &text, Access access) { texts.push_back({text, access, true}); };
    const auto label = [&](const QString &text) {
        if (!text.isEmpty())
            texts.push_back({text, Access::None, false});
    };
    std::visit(
        [&](const auto &e) {
            using T = std::decay_t<decltype(e)>;
            if constexpr (std::is_same_v<T, model::Comment> || std::is_same_v<T, model::Error>) {
                label(e.content.text);
            } else if constexpr (std::is_same_v<T, model::Connector> || std::is_same_v<T, model::Continuation>) {
                label(e.name);
            } else if constexpr (std::is_same_v<T, model::Block>) {
                label(e.typeName);
                if (e.instanceName)
                    variable(*e.instanceName, Access::Read);
            } else if constexpr (std::is_same_v<T, model::InVariable>) {
                variable(e.expression, Access::Read);
            } else if constexpr (std::is_same_v<T, model::OutVariable>) {
                variable(e.expression, Access::Written);
            } else if constexpr (std::is_same_v<T, model::InOutVariable>) {
                variable(e.expression, Access::ReadWritten);
            } else if constexpr (std::is_same_v<T, model::Label> || std::is_same_v<T, model::Jump>) {
                label(e.label);
            } else if constexpr (std::is_same_v<T, model::Contact>) {
                variable(e.variable, Access::Read);
            } else if constexpr (std::is_same_v<T, model::Coil>) {
                variable(e.variable, Access::Written);
            } else if constexpr (std::is_same_v<T, model::Step>) {
                label(e.name);
            } else if constexpr (std::is_same_v<T, model::MacroStep>) {
                label(e.name.value_or(QString()));
            } else if constexpr (std::is_same_v<T, model::JumpStep>) {
                label(e.targetName);
            } else if constexpr (std::is_same_v<T, model::Transition>) {
                if (e.condition) {
                    if (const auto *reference = std::get_if<model::Reference>(&e.condition->kind))
                        label(reference->name);
                    else if (const auto *inlined = std::get_if<model::InlineCondition>(&e.condition->kind))
                        texts.push_back({inlineText(*inlined->body), Access::Read, false});
                }
            } else if constexpr (std::is_same_v<T, model::ActionBlock>) {
                for (const model::ActionBlockAction &action : e.actions) {
                    if (action.reference)
                        label(action.reference->name);
                    if (action.inlineBody)
                        texts.push_back({inlineText(**action.inlineBody), Access::None, false});
                    if (action.indicator)
                        variable(*action.indicator, Access::Written);
                }
            }
        },
        element);
    return texts;
}

// 1-based line and column of `offset` in `text`, and the line's text.
struct TextPlace {
    int line = 1;
    int column = 1;
    QString lineText;
};

TextPlace placeAt(const QString &text, int offset)
{
    // (lastIndexOf from -1 would search from the end.)
    const int lineStart = offset == 0 ? 0 : int(text.lastIndexOf(QLatin1Char('\n'), offset - 1)) + 1;
    int lineEnd = text.indexOf(QLatin1Char('\n'), offset);
    if (lineEnd < 0)
        lineEnd = int(text.size());
    return {int(QStringView(text).left(offset).count(u'\n')) + 1, offset - lineStart + 1,
        text.mid(lineStart, lineEnd - lineStart).trimmed()};
}

std::optional<QRegularExpression> patternOf(const SearchQuery &query, QString *error)
{
    QString pattern = query.regularExpression ? query.text : QRegularExpression::escape(query.text);
    if (query.wholeWord)
        pattern = QStringLiteral("(?<![A-Za-z0-9_])(?:%1)(?![A-Za-z0-9_])").arg(pattern);
    // ^ and $ are the ends of a line, as in the editors' own find.
    QRegularExpression expression(pattern,
        query.caseSensitive ? QRegularExpression::MultilineOption
                            : QRegularExpression::MultilineOption | QRegularExpression::CaseInsensitiveOption);
    if (!expression.isValid()) {
        *error = ProjectSearch::tr("The regular expression is not valid: %1.").arg(expression.errorString());
        return std::nullopt;
    }
    return expression;
}

bool matches(const QRegularExpression &pattern, const QString &text)
{
    const QRegularExpressionMatch match = pattern.match(text);
    return match.hasMatch() && match.capturedLength() > 0;
}

void findInText(const QRegularExpression &pattern, const QString &text, const SearchHit &base, std::vector<SearchHit> &hits)
{
    QRegularExpressionMatchIterator it = pattern.globalMatch(text);
    while (it.hasNext()) {
        const QRegularExpressionMatch match = it.next();
        if (match.capturedLength() == 0)
            continue;
        const TextPlace at = placeAt(text, int(match.capturedStart()));
        SearchHit hit = base;
        hit.line = at.line;
        hit.column = at.column;
        hit.length = int(match.capturedLength());
        hit.text = at.lineText;
        hits.push_back(hit);
    }
}

QString variableLine(const model::Variable &variable)
{
    return editors::declarationLine(variable.name, variable.address.value_or(QString()),
        interp::frontend::printDataType(variable.type),
        variable.initialValue ? interp::frontend::printValue(*variable.initialValue) : QString(),
        variable.documentation ? variable.documentation->text : QString());
}

// Calls `visit` with every declared variable of the project: the POUs' (with the POU's body as
// the place) and the global lists'.
void forEachDeclaration(const model::Project &project,
    const std::function<void(SearchHit base, const model::VarList &, const model::Variable &)> &visit)
{
    for (const model::Pou &pou : project.types.pous) {
        if (!pou.pouInterface)
            continue;
        for (const model::VarList &list : pou.pouInterface->varLists) {
            for (const model::Variable &variable : list.variables) {
                SearchHit base;
                base.place = pou.name;
                base.body = BodyRef {pou.id, BodyRef::Part::Pou, {}};
                base.variable = variable.name;
                visit(base, list, variable);
            }
        }
    }
    for (const editors::GlobalListRef &ref : editors::globalLists(project.instances)) {
        for (const model::VarList &list : editors::globalListDeclarations(project.instances, ref).varLists) {
            for (const model::Variable &variable : list.variables) {
                SearchHit base;
                base.place = ref.displayName();
                base.list = ref;
                base.variable = variable.name;
                visit(base, list, variable);
            }
        }
    }
}

// ---- cross references

// The uses of `name` in IEC text (ST, IL or an inline condition): each a hit with its access.
// `qualifiers` are the prefixes that still mean this variable (`IO.Valve` for a global of IO).
void usesInText(const QString &text, bool il, const QString &name, const QStringList &qualifiers,
    const SearchHit &base, std::vector<SearchHit> &hits)
{
    const std::vector<interp::Token> tokens = interp::tokenize(text);
    const auto word = [&](size_t i) { return QStringView(text).mid(tokens[i].offset, tokens[i].length); };
    const auto isOperator = [&](size_t i, QStringView op) {
        return i < tokens.size() && tokens[i].kind == interp::TokenKind::Operator && word(i) == op;
    };
    int depth = 0;
    size_t lineFirst = 0; // IL: the first token of the current line
    for (size_t i = 0; i < tokens.size(); ++i) {
        if (il && (i == 0 || text.mid(tokens[i - 1].offset, tokens[i].offset - tokens[i - 1].offset).contains(QLatin1Char('\n'))))
            lineFirst = i;
        if (isOperator(i, u"("))
            ++depth;
        else if (isOperator(i, u")"))
            depth = std::max(0, depth - 1);
        if (tokens[i].kind != interp::TokenKind::Identifier || !sameName(word(i), name))
            continue;
        // `x.name` is a member of x, unless x is the name of the variable's global list.
        if (i >= 2 && isOperator(i - 1, u".") && !qualifiers.contains(word(i - 2).toString(), Qt::CaseInsensitive))
            continue;
        Access access = Access::Read;
        if (il) {
            size_t op = lineFirst;
            if (op + 1 < tokens.size() && isOperator(op + 1, u":")) // a label first
                op += 2;
            const QString operation = op < tokens.size() ? word(op).toString().toUpper() : QString();
            if (op + 1 == i && (operation == u"ST" || operation == u"STN" || operation == u"S" || operation == u"R"))
                access = Access::Written;
        } else if ((depth == 0 && isOperator(i + 1, u":=")) || (i > 0 && isOperator(i - 1, u"=>"))) {
            access = Access::Written;
        }
        const TextPlace at = placeAt(text, tokens[i].offset);
        SearchHit hit = base;
        hit.line = at.line;
        hit.column = at.column;
        hit.length = tokens[i].length;
        hit.text = at.lineText;
        hit.access = access;
        hits.push_back(hit);
    }
}

// Whether the expression a graphical element shows names the variable ("Count", "Tank.Level",
// "IO.Valve", "a[i]").
bool expressionNames(const QString &expression, const QString &name, const QStringList &qualifiers)
{
    std::vector<SearchHit> uses;
    usesInText(expression, false, name, qualifiers, {}, uses);
    return !uses.empty();
}

void usesInBody(const model::Body &body, const QString &name, const QStringList &qualifiers, const SearchHit &base,
    std::vector<SearchHit> &hits)
{
    if (!body.isGraphical()) {
        usesInText(body.text(), body.language() == model::BodyLanguage::IL, name, qualifiers, base, hits);
        return;
    }
    for (const model::Element &element : *body.elements()) {
        for (const ElementText &shown : elementTexts(element)) {
            // Labels (steps, action names) never name a variable; inline conditions read them.
            const bool mayName = shown.isVariable || shown.access == Access::Read;
            if (!mayName || !expressionNames(shown.text, name, qualifiers))
                continue;
            SearchHit hit = base;
            hit.localId = model::header(element).localId;
            hit.text = shown.text;
            hit.access = shown.access;
            hits.push_back(hit);
        }
    }
}

bool declaresLocally(const model::Pou &pou, const QString &name)
{
    if (!pou.pouInterface)
        return false;
    for (const model::VarList &list : pou.pouInterface->varLists) {
        if (list.kind == model::VarListKind::External)
            continue;
        for (const model::Variable &variable : list.variables) {
            if (sameName(variable.name, name))
                return true;
        }
    }
    return false;
}

} // namespace

SearchResult ProjectSearch::find(const model::Project &project, const SearchQuery &query)
{
    SearchResult result;
    if (query.text.isEmpty())
        return result;
    const std::optional<QRegularExpression> pattern = patternOf(query, &result.error);
    if (!pattern)
        return result;
    forEachBody(project, [&](const model::Pou &pou, const BodyRef &ref, const model::Body &body) {
        SearchHit base;
        base.place = placeOf(pou, ref);
        base.body = ref;
        if (!body.isGraphical()) {
            findInText(*pattern, body.text(), base, result.hits);
            return;
        }
        for (const model::Element &element : *body.elements()) {
            for (const ElementText &shown : elementTexts(element)) {
                if (!matches(*pattern, shown.text))
                    continue;
                SearchHit hit = base;
                hit.localId = model::header(element).localId;
                hit.text = shown.text.simplified();
                result.hits.push_back(hit);
            }
        }
    });
    for (const model::Pou &pou : project.types.pous) {
        for (const interp::frontend::CodesysMemberSummary &member : interp::frontend::codesysMembers(pou)) {
            SearchHit base;
            base.place = pou.name + QLatin1Char('.') + member.name;
            base.body = BodyRef {pou.id, BodyRef::Part::Pou, {}};
            base.member = member.name;
            findInText(*pattern, interp::frontend::printCodesysMember(pou, member.name), base, result.hits);
        }
    }
    for (const QString &name : interp::frontend::codesysInterfaceNames(project)) {
        SearchHit base;
        base.place = name;
        base.interfaceName = name;
        findInText(*pattern, interp::frontend::printCodesysInterface(project, name), base, result.hits);
    }
    forEachDeclaration(project, [&](SearchHit base, const model::VarList &, const model::Variable &variable) {
        const QString line = variableLine(variable);
        if (!matches(*pattern, line))
            return;
        base.text = line;
        result.hits.push_back(base);
    });
    return result;
}

std::vector<SearchHit> ProjectSearch::crossReferences(const model::Project &project, model::PouId from, const QString &name)
{
    std::vector<SearchHit> hits;
    const model::Pou *owner = project.findPou(from);
    if (name.isEmpty())
        return hits;
    const bool local = owner && declaresLocally(*owner, name);
    // Declarations: the POU's own, or (for a global) the list's and the VAR_EXTERNALs.
    QStringList qualifiers;
    forEachDeclaration(project, [&](SearchHit base, const model::VarList &list, const model::Variable &variable) {
        if (!sameName(variable.name, name))
            return;
        const bool inOwner = base.body && base.body->pou == from;
        const bool wanted = local ? inOwner && list.kind != model::VarListKind::External
                                  : base.list || list.kind == model::VarListKind::External;
        if (!wanted)
            return;
        if (base.list && !base.list->name.isEmpty())
            qualifiers << base.list->name;
        base.text = variableLine(variable);
        base.access = Access::Declared;
        hits.push_back(base);
    });
    forEachBody(project, [&](const model::Pou &pou, const BodyRef &ref, const model::Body &body) {
        const bool sees = local ? pou.id == from : !declaresLocally(pou, name);
        if (!sees)
            return;
        SearchHit base;
        base.place = placeOf(pou, ref);
        base.body = ref;
        usesInBody(body, name, qualifiers, base, hits);
    });
    return hits;
}

QString ProjectSearch::accessText(SearchHit::Access access)
{
    switch (access) {
    case Access::None:
        return {};
    case Access::Declared:
        return tr("declared");
    case Access::Read:
        return tr("read");
    case Access::Written:
        return tr("written");
    case Access::ReadWritten:
        return tr("read and written");
    }
    return {};
}

} // namespace iec::app
