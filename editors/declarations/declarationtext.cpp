#include "editors/declarations/declarationtext.h"

#include "interpreter/compiler/lexer.h"
#include "interpreter/compiler/parser.h"
#include "interpreter/frontend/iecprinter.h"
#include "interpreter/frontend/iecreader.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include <algorithm>
#include <map>

namespace iec::editors {

namespace {

namespace ast = interp::ast;

QString variableLine(const model::Variable &variable)
{
    return declarationLine(variable.name, variable.address.value_or(QString()),
        interp::frontend::printDataType(variable.type),
        variable.initialValue ? interp::frontend::printValue(*variable.initialValue) : QString(),
        variable.documentation ? variable.documentation->text : QString());
}

// The comment's words without (* *) or //, on one line as the text view prints them (a comment
// over two lines read back as one changed the model; found by fuzz_declarations).
QString commentContent(QStringView token)
{
    if (token.startsWith(u"//"))
        return token.mid(2).toString().simplified();
    return token.mid(2, token.size() - 4).toString().simplified();
}

// 1-based line of every comment in `text`, with its content.
std::multimap<int, QString> commentsByLine(QStringView text)
{
    std::multimap<int, QString> comments;
    int line = 1;
    int counted = 0;
    for (const interp::Token &token : interp::tokenize(text)) {
        line += int(text.mid(counted, token.offset - counted).count(u'\n'));
        counted = token.offset;
        if (token.kind == interp::TokenKind::Comment)
            comments.emplace(line, commentContent(text.mid(token.offset, token.length)));
    }
    return comments;
}

void checkSection(const ast::VarSection &section, std::vector<DeclarationProblem> &problems)
{
    if (section.kind == ast::VarKind::Access || section.kind == ast::VarKind::Config)
        problems.push_back({section.location.line, section.location.column,
            QCoreApplication::translate("iec::editors::DeclarationText",
                "VAR_ACCESS and VAR_CONFIG belong in a configuration, not in a POU.")});
}

void checkVariable(const ast::VarDecl &decl, std::vector<DeclarationProblem> &problems)
{
    if (!isValidIdentifier(decl.name))
        problems.push_back({decl.location.line, decl.location.column, invalidNameMessage(decl.name)});
    if (!decl.address.isEmpty() && !isValidAddress(decl.address))
        problems.push_back({decl.location.line, decl.location.column, invalidAddressMessage(decl.address)});
}

// Semantic checks the parser leaves to the compiler, which the editor wants before applying.
std::vector<DeclarationProblem> checkSections(const std::vector<ast::VarSection> &sections)
{
    std::vector<DeclarationProblem> problems;
    QStringList seen;
    for (const ast::VarSection &section : sections) {
        checkSection(section, problems);
        for (const ast::VarDecl &decl : section.vars) {
            checkVariable(decl, problems);
            if (seen.contains(decl.name, Qt::CaseInsensitive))
                problems.push_back({decl.location.line, decl.location.column, duplicateNameMessage(decl.name)});
            seen << decl.name;
        }
    }
    return problems;
}

// The model's var lists for text that parsed: the IEC text reader converts a POU's declarations,
// so the text is wrapped in one.
std::vector<model::VarList> varListsOf(QStringView text)
{
    const QString pou = QStringLiteral("PROGRAM DeclarationText\n") + text + QStringLiteral("\nEND_PROGRAM\n");
    const interp::frontend::TextReadResult read = interp::frontend::readIecText(pou, QString());
    if (read.project.types.pous.empty() || !read.project.types.pous.front().pouInterface)
        return {};
    return read.project.types.pous.front().pouInterface->varLists;
}

const model::Variable *findVariable(const model::Interface &declarations, const QString &name)
{
    for (const model::VarList &list : declarations.varLists) {
        const auto it = std::ranges::find_if(
            list.variables, [&](const model::Variable &v) { return v.name.compare(name, Qt::CaseInsensitive) == 0; });
        if (it != list.variables.end())
            return &*it;
    }
    return nullptr;
}

// The n-th list of `kind` in `lists`, or nullptr.
const model::VarList *nthListOfKind(const std::vector<model::VarList> &lists, model::VarListKind kind, int n)
{
    for (const model::VarList &list : lists) {
        if (list.kind == kind && n-- == 0)
            return &list;
    }
    return nullptr;
}

// Keeps what the text cannot show: the lists' vendor data (the n-th list of a kind inherits from
// the n-th of that kind before) and the variables' (by name).
void keepHiddenData(std::vector<model::VarList> &lists, const model::Interface &base)
{
    std::map<model::VarListKind, int> seen;
    for (model::VarList &list : lists) {
        if (const model::VarList *old = nthListOfKind(base.varLists, list.kind, seen[list.kind]++)) {
            list.name = old->name;
            list.addData = old->addData;
            list.documentation = old->documentation;
            list.extras = old->extras;
        }
        for (model::Variable &variable : list.variables) {
            if (const model::Variable *old = findVariable(base, variable.name)) {
                variable.globalId = old->globalId;
                variable.addData = old->addData;
                variable.extras = old->extras;
            }
        }
    }
}

// The parser accepts PERSISTENT after VAR but does not keep it: it is read from the header line.
void readPersistence(std::vector<model::VarList> &lists, const std::vector<ast::VarSection> &sections, QStringView text)
{
    static const QRegularExpression persistent(
        QStringLiteral("\\bPERSISTENT\\b"), QRegularExpression::CaseInsensitiveOption);
    const QList<QStringView> lines = text.split(u'\n');
    for (size_t s = 0; s < lists.size() && s < sections.size(); ++s) {
        const int line = sections[s].location.line - 1;
        if (line >= 0 && line < lines.size())
            lists[s].persistent = persistent.match(lines[line].toString()).hasMatch();
    }
}

void attachComments(std::vector<model::VarList> &lists, const std::vector<ast::VarSection> &sections,
    const std::multimap<int, QString> &comments)
{
    for (size_t s = 0; s < lists.size() && s < sections.size(); ++s) {
        for (size_t v = 0; v < lists[s].variables.size() && v < sections[s].vars.size(); ++v) {
            const auto comment = comments.find(sections[s].vars[v].location.line);
            if (comment != comments.end() && !comment->second.isEmpty())
                lists[s].variables[v].documentation = model::FormattedText {comment->second, {}};
        }
    }
}

} // namespace

QString sectionHeader(const model::VarList &list)
{
    // The printer owns the keywords, so the first line it prints for the empty list is used.
    model::VarList header = list;
    header.variables.clear();
    return interp::frontend::printVarList(header).section(QLatin1Char('\n'), 0, 0);
}

QString invalidNameMessage(const QString &name)
{
    return QCoreApplication::translate("iec::editors::DeclarationText",
        "\"%1\" is not a valid name: use letters, digits and single underscores, and no keyword.")
        .arg(name);
}

QString invalidAddressMessage(const QString &address)
{
    return QCoreApplication::translate(
        "iec::editors::DeclarationText", "\"%1\" is not an address such as %IX0.0, %QW3 or %MD10.")
        .arg(address);
}

QString duplicateNameMessage(const QString &name)
{
    return QCoreApplication::translate("iec::editors::DeclarationText", "%1 is declared twice.").arg(name);
}

QString declarationLine(const QString &name, const QString &address, const QString &type, const QString &initialValue,
    const QString &comment)
{
    QString line = name;
    if (!address.isEmpty())
        line += QStringLiteral(" AT ") + address;
    line += QStringLiteral(" : ") + type;
    if (!initialValue.isEmpty())
        line += QStringLiteral(" := ") + initialValue;
    line += QLatin1Char(';');
    if (!comment.trimmed().isEmpty()) {
        // One line keeps one declaration a line; a "*)" inside would end a (* *) comment early,
        // so such a text becomes a // comment, which runs to the end of the line.
        const QString content = comment.simplified();
        if (content.contains(QStringLiteral("*)")))
            line += QStringLiteral(" // ") + content;
        else
            line += QStringLiteral(" (* ") + content + QStringLiteral(" *)");
    }
    return line;
}

QString declarationText(const model::Interface &declarations)
{
    QStringList sections;
    for (const model::VarList &list : declarations.varLists) {
        QString section = sectionHeader(list) + QLatin1Char('\n');
        for (const model::Variable &variable : list.variables)
            section += QStringLiteral("    ") + variableLine(variable) + QLatin1Char('\n');
        sections << section + QStringLiteral("END_VAR\n");
    }
    return sections.join(QLatin1Char('\n'));
}

DeclarationTextResult readDeclarationText(QStringView text, const model::Interface &base)
{
    DeclarationTextResult result;
    interp::Diagnostics diagnostics;
    const std::vector<ast::VarSection> sections = interp::parseDeclarations(text, QString(), diagnostics);
    for (const interp::Diagnostic &diagnostic : diagnostics.all()) {
        if (diagnostic.severity == interp::Diagnostic::Severity::Error)
            result.problems.push_back({diagnostic.location.line, diagnostic.location.column, diagnostic.message});
    }
    if (result.problems.empty())
        result.problems = checkSections(sections);
    if (!result.problems.empty())
        return result;
    std::vector<model::VarList> lists = varListsOf(text);
    attachComments(lists, sections, commentsByLine(text));
    readPersistence(lists, sections, text);
    keepHiddenData(lists, base);
    model::Interface declarations = base;
    declarations.varLists = std::move(lists);
    result.declarations = std::move(declarations);
    for (const ast::VarSection &section : sections) {
        result.sectionPlaces.push_back({section.location.line, section.location.column, {}});
        for (const ast::VarDecl &decl : section.vars)
            result.variablePlaces.push_back({decl.location.line, decl.location.column, {}});
    }
    return result;
}

bool isValidAddress(const QString &address)
{
    static const QRegularExpression pattern(
        QStringLiteral("^%[IQM](\\*|[XBWDL]?\\d+(\\.\\d+)*)$"), QRegularExpression::CaseInsensitiveOption);
    return pattern.match(address).hasMatch();
}

bool isValidIdentifier(const QString &name)
{
    return interp::isIecIdentifier(name);
}

} // namespace iec::editors
