#include "interpreter/frontend/projectsource.h"

#include "interpreter/compiler/parser.h"
#include "interpreter/frontend/iecprinter.h"

namespace iec::interp::frontend {

namespace {

void add(Diagnostics &to, const Diagnostic &d, const QString &pou)
{
    if (d.severity == Diagnostic::Severity::Error)
        to.error(pou, d.location, d.message, d.hint);
    else
        to.warning(pou, d.location, d.message, d.hint);
}

// Parses printed declarations; their diagnostics are filed under `owner` (the type, POU or
// configuration they came from) because the parser of a whole unit knows no POU for TYPE blocks.
ast::CompilationUnit parseDeclarationsOf(const QString &text, const QString &owner, Diagnostics &diagnostics)
{
    Diagnostics local;
    ast::CompilationUnit unit = parseUnit(text, local);
    for (const Diagnostic &d : local.all())
        add(diagnostics, d, d.pou.isEmpty() ? owner : d.pou);
    return unit;
}

template<typename T> void moveAppend(std::vector<T> &to, std::vector<T> &from)
{
    to.insert(to.end(), std::make_move_iterator(from.begin()), std::make_move_iterator(from.end()));
}

ast::Body parseBody(const model::Body &body, const QString &pou, Diagnostics &diagnostics)
{
    ast::Body result;
    switch (body.language()) {
    case model::BodyLanguage::ST:
        result.language = ast::Language::ST;
        result.statements = parseStBody(body.text(), pou, diagnostics);
        break;
    case model::BodyLanguage::IL:
        result.language = ast::Language::IL;
        result.il = parseIlBody(body.text(), pou, diagnostics);
        break;
    case model::BodyLanguage::LD:
    case model::BodyLanguage::FBD:
    case model::BodyLanguage::SFC:
        break; // an empty body; reportGraphicalBodies says why
    }
    return result;
}

void addPou(const model::Pou &pou, ast::CompilationUnit &unit, Diagnostics &diagnostics)
{
    ast::CompilationUnit declared = parseDeclarationsOf(printPouSkeleton(pou), pou.name, diagnostics);
    if (declared.pous.empty())
        return; // the name itself could not be parsed; already reported
    ast::Pou result = std::move(declared.pous.front());
    result.name = pou.name;
    if (const model::Body *body = pou.body())
        result.body = parseBody(*body, pou.name, diagnostics);
    for (const model::PouAction &action : pou.actions) {
        if (action.body.isGraphical())
            continue; // actions are not called by the compiler yet; SFC will run them
        ast::SfcAction parsed;
        parsed.name = action.name;
        // Lines count in the action's own text, so its diagnostics name it: Main.Reset:2:5.
        parsed.body = parseBody(action.body, pou.name + QLatin1Char('.') + action.name, diagnostics);
        result.actions.push_back(std::move(parsed));
    }
    unit.pous.push_back(std::move(result));
}

// One error per POU whose body is LD, FBD or SFC: the compiler cannot lower them yet. Returns
// their names.
QStringList reportGraphicalBodies(const model::Project &project, Diagnostics &diagnostics)
{
    QStringList names;
    for (const model::Pou &pou : project.types.pous) {
        const model::Body *body = pou.body();
        if (!body || !body->isGraphical())
            continue;
        diagnostics.error(pou.name, {},
            QStringLiteral("%1 is written in %2, which this version cannot run yet.")
                .arg(pou.name, languageName(body->language())),
            QStringLiteral("write it in ST or IL to run it now"));
        names << pou.name;
    }
    return names;
}

// The text of the project (declarations and ST/IL bodies) as the compiler's input.
ast::CompilationUnit parseProjectText(const model::Project &project, Diagnostics &diagnostics)
{
    ast::CompilationUnit unit;
    for (const model::DataTypeDecl &type : project.types.dataTypes) {
        ast::CompilationUnit declared = parseDeclarationsOf(printTypeDeclaration(type), type.name, diagnostics);
        moveAppend(unit.types, declared.types);
    }
    for (const model::Pou &pou : project.types.pous)
        addPou(pou, unit, diagnostics);
    for (const model::Configuration &configuration : project.instances.configurations) {
        ast::CompilationUnit declared
            = parseDeclarationsOf(printConfiguration(configuration), configuration.name, diagnostics);
        moveAppend(unit.configurations, declared.configurations);
    }
    return unit;
}

} // namespace

ProjectUnit buildUnit(const model::Project &project, Diagnostics &diagnostics)
{
    Diagnostics parsing;
    ProjectUnit result {parseProjectText(project, parsing), false};
    result.parseErrors = parsing.hasErrors();
    diagnostics.append(parsing);
    result.notRunnable = reportGraphicalBodies(project, diagnostics);
    return result;
}

std::shared_ptr<const Module> compileUnit(
    const ProjectUnit &unit, Diagnostics &diagnostics, const CompileOptions &options)
{
    if (unit.parseErrors)
        return nullptr;
    // A POU that cannot run yet (an error already in `diagnostics`) does not stop the others
    // from being checked, but nothing runs.
    Diagnostics compiling;
    std::shared_ptr<const Module> module = compile({&unit.unit}, compiling, options);
    for (const Diagnostic &d : compiling.all()) {
        if (!unit.notRunnable.contains(d.pou, Qt::CaseInsensitive))
            add(diagnostics, d, d.pou);
    }
    return diagnostics.hasErrors() ? nullptr : module;
}

void dropConfigurations(ast::CompilationUnit &unit)
{
    for (ast::ConfigurationDecl &configuration : unit.configurations) {
        moveAppend(unit.globals, configuration.globals);
        for (ast::ResourceDecl &resource : configuration.resources)
            moveAppend(unit.globals, resource.globals);
    }
    unit.configurations.clear();
}

std::shared_ptr<const Module> compileProject(
    const model::Project &project, Diagnostics &diagnostics, const CompileOptions &options)
{
    return compileUnit(buildUnit(project, diagnostics), diagnostics, options);
}

} // namespace iec::interp::frontend
