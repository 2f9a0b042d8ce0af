#include "interpreter/frontend/codesysmembers.h"

#include "interpreter/compiler/compilerstack.h"
#include "interpreter/compiler/parser.h"
#include "interpreter/frontend/iecprinter.h"
#include "interpreter/frontend/iecreader.h"
#include "interpreter/frontend/tokencursor.h"

#include <QCoreApplication>

#include <algorithm>

namespace iec::interp::frontend {

using model::plcopen::CodesysMember;
using model::plcopen::CodesysMemberDefinition;

namespace {

bool sameName(const QString &a, const QString &b)
{
    return a.compare(b, Qt::CaseInsensitive) == 0;
}

// ---- printing --------------------------------------------------------------------------------

QString header(const char *keyword, const CodesysMember &m, const std::optional<model::DataType> &type)
{
    QString text = QLatin1String(keyword);
    for (const QString &qualifier : m.qualifiers)
        text += QLatin1Char(' ') + qualifier;
    text += QLatin1Char(' ') + m.name;
    if (type)
        text += QStringLiteral(" : ") + printDataType(*type);
    return text + QLatin1Char('\n');
}

QString variables(const model::Interface &interface)
{
    QString text;
    for (const model::VarList &list : interface.varLists)
        text += printVarList(list);
    return text;
}

QString bodyPart(const std::optional<model::Body> &body, const QString &where, bool &editable)
{
    if (!body)
        return {}; // a prototype
    if (body->isGraphical()) {
        editable = false;
        return QStringLiteral("(* The %1 body of %2 has no IEC text form. *)\n").arg(languageName(body->language()), where);
    }
    QString text = body->text();
    if (!text.isEmpty() && !text.endsWith(QLatin1Char('\n')))
        text += QLatin1Char('\n');
    return text;
}

// ---- reading ---------------------------------------------------------------------------------

const QString kWrapper = QStringLiteral("__IecStudioMemberOwner");

// The parser's messages for the text inside the wrapper, at the lines of the text itself.
void passOn(const Diagnostics &parsed, int lastLine, const QString &pou, Diagnostics &into)
{
    for (const Diagnostic &d : parsed.all()) {
        SourceLocation at = d.location;
        at.line = std::clamp(at.line - 1, 1, std::max(lastLine, 1));
        if (d.severity == Diagnostic::Severity::Error)
            into.error(pou, at, d.message, d.hint);
        else
            into.warning(pou, at, d.message, d.hint);
    }
}

// The one member the wrapper holds, checked: a method, or a property's accessors.
const ast::Pou *onlyMember(const ast::CompilationUnit &unit)
{
    if (unit.pous.size() != 1 || !unit.types.empty() || !unit.configurations.empty())
        return nullptr;
    const ast::Pou &pou = unit.pous.front();
    if (!pou.sections.empty() || !pou.actions.empty() || !pou.body.statements.empty() || !pou.body.il.empty()
        || pou.body.sfc || pou.methods.empty())
        return nullptr;
    const bool method = pou.methods.front().role == ast::Method::Role::Method;
    if (method && pou.methods.size() != 1)
        return nullptr;
    for (const ast::Method &m : pou.methods) {
        if (!sameName(m.name, pou.methods.front().name) || (m.role == ast::Method::Role::Method) != method)
            return nullptr;
    }
    return &pou;
}

model::Body textBody(const ast::Body &parsed, const QString &text)
{
    model::Body body = model::Body::withLanguage(parsed.language == ast::Language::IL ? model::BodyLanguage::IL
                                                                                       : model::BodyLanguage::ST);
    body.setText(text);
    return body;
}

// Where the pieces of the text are: the declaration, and the text of each body with the offset
// it starts from (-1: none).
struct Pieces {
    int declarationEnd = 0;
    QString body, getter, setter;
    int bodyFrom = -1, getterFrom = -1, setterFrom = -1;
};

Pieces cut(QStringView text)
{
    Pieces pieces;
    TokenCursor cursor(text);
    const int headerEnd = cursor.lineEndAfter(cursor.start());
    const bool property = cursor.is("PROPERTY");
    // The header: METHOD, the qualifiers, the name and the type, on the first line.
    while (!cursor.atEnd() && cursor.start() < headerEnd && !cursor.isVarSection()) {
        pieces.declarationEnd = cursor.end();
        cursor.next();
    }
    if (!property) {
        while (cursor.isVarSection())
            pieces.declarationEnd = cursor.skipPast("END_VAR");
        pieces.bodyFrom = pieces.declarationEnd;
        while (!cursor.atEnd() && !cursor.is("END_METHOD"))
            cursor.next();
        pieces.body = bodyText(text, pieces.bodyFrom, cursor.start());
        return pieces;
    }
    while (!cursor.atEnd() && !cursor.is("END_PROPERTY")) {
        const bool get = cursor.is("GET");
        if (!get && !cursor.is("SET")) {
            cursor.next();
            continue;
        }
        int start = cursor.end();
        cursor.next();
        while (cursor.isVarSection())
            start = cursor.skipPast("END_VAR");
        const char *end = get ? "END_GET" : "END_SET";
        while (!cursor.atEnd() && !cursor.is(end))
            cursor.next();
        (get ? pieces.getter : pieces.setter) = bodyText(text, start, cursor.start());
        (get ? pieces.getterFrom : pieces.setterFrom) = start;
        cursor.next();
    }
    return pieces;
}

CodesysMemberDefinition::Accessor accessorOf(const ast::Method &m, bool setter, const QString &body,
    const QString &owner, Diagnostics &diagnostics)
{
    CodesysMemberDefinition::Accessor accessor;
    std::vector<ast::VarSection> sections = m.sections;
    if (setter && !sections.empty())
        sections.erase(sections.begin()); // the value written, which the parser declares itself
    accessor.interface.varLists = varListsFromAst(sections, owner, diagnostics);
    if (m.hasBody)
        accessor.body = textBody(m.body, body);
    return accessor;
}

} // namespace

namespace {

std::vector<CodesysMemberSummary> membersOf(const model::plcopen::CodesysClass &definition)
{
    std::vector<CodesysMemberSummary> result;
    for (const CodesysMember &m : definition.members) {
        if (std::ranges::none_of(result, [&](const CodesysMemberSummary &s) { return sameName(s.name, m.name); }))
            result.push_back({m.name, m.kind != CodesysMember::Kind::Method});
    }
    return result;
}

QString printMember(const model::plcopen::CodesysClass &definition, const QString &owner, const QString &name, bool &textual)
{
    std::vector<const CodesysMember *> parts;
    for (const CodesysMember &m : definition.members) {
        if (sameName(m.name, name))
            parts.push_back(&m);
    }
    if (parts.empty())
        return {};
    if (parts.front()->kind == CodesysMember::Kind::Method) {
        const CodesysMember &m = *parts.front();
        return header("METHOD", m, m.interface.returnType) + variables(m.interface)
            + bodyPart(m.body, owner + QLatin1Char('.') + m.name, textual) + QStringLiteral("END_METHOD\n");
    }
    QString text = header("PROPERTY", *parts.front(), parts.front()->type);
    // GET before SET, whatever order the file has.
    std::ranges::stable_sort(parts, [](const CodesysMember *a, const CodesysMember *b) {
        return a->kind == CodesysMember::Kind::Getter && b->kind != CodesysMember::Kind::Getter;
    });
    for (const CodesysMember *accessor : parts) {
        const bool get = accessor->kind == CodesysMember::Kind::Getter;
        text += get ? QStringLiteral("GET\n") : QStringLiteral("SET\n");
        text += variables(accessor->interface);
        text += bodyPart(accessor->body, owner + QLatin1Char('.') + accessor->name, textual);
        text += get ? QStringLiteral("END_GET\n") : QStringLiteral("END_SET\n");
    }
    return text + QStringLiteral("END_PROPERTY\n");
}

} // namespace

std::vector<CodesysMemberSummary> codesysMembers(const model::Pou &pou)
{
    return membersOf(model::plcopen::readCodesysClass(pou));
}

QString printCodesysMember(const model::Pou &pou, const QString &name, bool *editable)
{
    bool textual = true;
    const QString text = printMember(model::plcopen::readCodesysClass(pou), pou.name, name, textual);
    if (editable)
        *editable = textual;
    return text;
}

namespace {

QString printInterface(const model::plcopen::CodesysInterface &itf)
{
    QStringList bases = itf.definition.implements;
    if (!itf.definition.extends.isEmpty())
        bases.prepend(itf.definition.extends);
    QString text = QStringLiteral("INTERFACE ") + itf.name;
    if (!bases.isEmpty())
        text += QStringLiteral(" EXTENDS ") + bases.join(QStringLiteral(", "));
    text += QLatin1Char('\n');
    bool textual = true;
    for (const CodesysMemberSummary &member : membersOf(itf.definition))
        text += printMember(itf.definition, itf.name, member.name, textual);
    return text + QStringLiteral("END_INTERFACE\n");
}

} // namespace

QString printCodesysInterfaces(const model::Project &project)
{
    QString text;
    for (const model::plcopen::CodesysInterface &itf : model::plcopen::readCodesysInterfaces(project))
        text += printInterface(itf);
    return text;
}

QStringList codesysInterfaceNames(const model::Project &project)
{
    QStringList names;
    for (const model::plcopen::CodesysInterface &itf : model::plcopen::readCodesysInterfaces(project))
        names << itf.name;
    return names;
}

QString printCodesysInterface(const model::Project &project, const QString &name)
{
    for (const model::plcopen::CodesysInterface &itf : model::plcopen::readCodesysInterfaces(project)) {
        if (itf.name.compare(name, Qt::CaseInsensitive) == 0)
            return printInterface(itf);
    }
    return {};
}

MemberBodyLines memberBodyLines(QStringView text)
{
    const Pieces pieces = cut(text);
    // The line a body's first line is on: bodyText drops the rest of the line it starts on when
    // that is blank (the line break after END_VAR or GET).
    const auto lineOf = [&](int from) {
        if (from < 0)
            return 0;
        int line = int(text.left(from).count(u'\n')) + 1;
        const qsizetype newline = text.indexOf(u'\n', from);
        if (newline >= 0 && text.mid(from, newline - from).trimmed().isEmpty())
            ++line;
        return line;
    };
    return {lineOf(pieces.bodyFrom), lineOf(pieces.getterFrom), lineOf(pieces.setterFrom)};
}

CodesysMemberText readCodesysMemberText(QStringView text, const QString &owner)
{
    CodesysMemberText result;
    const QString wrapped = QStringLiteral("FUNCTION_BLOCK %1\n").arg(kWrapper) + text
        + QStringLiteral("\nEND_FUNCTION_BLOCK\n");
    Diagnostics parsed;
    ast::CompilationUnit unit;
    runOnCompilerStack([&] { unit = parseUnit(wrapped, parsed); });
    const int lastLine = int(text.count(u'\n')) + 1;
    const ast::Pou *pou = onlyMember(unit);
    const QString where = pou ? owner + QLatin1Char('.') + pou->methods.front().name : owner;
    passOn(parsed, lastLine, where, result.diagnostics);
    if (parsed.hasErrors())
        return result;
    if (!pou) {
        result.diagnostics.error(owner, {1, 1},
            QCoreApplication::translate("iec::interp::Compiler",
                "Write one METHOD ... END_METHOD or one PROPERTY ... END_PROPERTY here, and nothing before or after it."));
        return result;
    }
    const Pieces pieces = cut(text);
    CodesysMemberDefinition definition;
    const ast::Method &first = pou->methods.front();
    definition.name = first.name;
    definition.declarationText = text.left(pieces.declarationEnd).trimmed().toString() + QLatin1Char('\n');
    if (first.role == ast::Method::Role::Method) {
        definition.interface.varLists = varListsFromAst(first.sections, where, result.diagnostics);
        if (first.returnType)
            definition.interface.returnType = dataTypeFromAst(*first.returnType);
        if (first.hasBody)
            definition.body = textBody(first.body, pieces.body);
    } else {
        definition.property = true;
        for (const ast::Method &accessor : pou->methods) {
            const bool setter = accessor.role == ast::Method::Role::Setter;
            if (!setter && accessor.returnType)
                definition.interface.returnType = dataTypeFromAst(*accessor.returnType);
            if (setter && !definition.interface.returnType && !accessor.sections.empty()
                && !accessor.sections.front().vars.empty())
                definition.interface.returnType = dataTypeFromAst(accessor.sections.front().vars.front().type);
            (setter ? definition.setter : definition.getter)
                = accessorOf(accessor, setter, setter ? pieces.setter : pieces.getter, where, result.diagnostics);
        }
    }
    result.definition = std::move(definition);
    return result;
}

} // namespace iec::interp::frontend
