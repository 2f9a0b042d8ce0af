#include "interpreter/frontend/projectsource.h"

#include "interpreter/compiler/compilerstack.h"
#include "interpreter/compiler/parser.h"
#include "interpreter/frontend/iecprinter.h"
#include "interpreter/graphical/graphicallowering.h"
#include "interpreter/sfc/sfclowering.h"
#include "model/plcopen/codesysoop.h"

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

// ST and IL are parsed; LD and FBD are lowered to statements (graphical/). `owner` names the
// body in diagnostics: the POU, or Pou.Action for an action.
ast::Body lowerBody(const model::Body &body, ast::Pou &pou, const QString &owner, Diagnostics &diagnostics)
{
    ast::Body result;
    switch (body.language()) {
    case model::BodyLanguage::ST:
        result.language = ast::Language::ST;
        if (const auto cfc = graphical::cfcDiagram(body)) { // CODESYS CFC: empty ST text, diagram in addData
            graphical::LoweringContext context {pou, owner, diagnostics};
            result.statements = graphical::lowerBody(*cfc, context);
            break;
        }
        result.statements = parseStBody(body.text(), owner, diagnostics);
        break;
    case model::BodyLanguage::IL:
        result.language = ast::Language::IL;
        result.il = parseIlBody(body.text(), owner, diagnostics);
        break;
    case model::BodyLanguage::LD:
    case model::BodyLanguage::FBD: {
        result.language = ast::Language::ST;
        graphical::LoweringContext context {pou, owner, diagnostics};
        result.statements = graphical::lowerBody(body, context);
        break;
    }
    case model::BodyLanguage::SFC:
        result.language = ast::Language::ST; // only a POU body can be a chart; see addPou
        break;
    }
    return result;
}

// The variables and return type of a CODESYS method or property accessor, as the parser reads a
// FUNCTION's (so a PLCopen file and a .st file can never mean different things).
ast::Pou declarationOf(const model::plcopen::CodesysMember &m, const QString &owner, Diagnostics &diagnostics)
{
    model::Pou function;
    function.name = m.name;
    function.kind = model::PouKind::Function;
    model::Interface declared = m.interface;
    declared.addData.clear();
    if (m.kind == model::plcopen::CodesysMember::Kind::Getter)
        declared.returnType = m.type;
    if (m.kind == model::plcopen::CodesysMember::Kind::Setter && m.type) {
        model::VarList input; // the value written, named like the property
        input.kind = model::VarListKind::Input;
        model::Variable value;
        value.name = m.name;
        value.type = *m.type;
        input.variables.push_back(value);
        declared.varLists.insert(declared.varLists.begin(), input);
    }
    if (!declared.returnType) // a method without a result: a function needs one to print
        declared.returnType = model::DataType {model::ElementaryType {QStringLiteral("BOOL")}};
    function.pouInterface = declared;
    ast::CompilationUnit parsed = parseDeclarationsOf(printPouSkeleton(function), owner + QLatin1Char('.') + m.name, diagnostics);
    if (parsed.pous.empty())
        return {};
    ast::Pou result = std::move(parsed.pous.front());
    if (m.kind != model::plcopen::CodesysMember::Kind::Getter && !m.interface.returnType)
        result.returnType.reset(); // a method without a result, or a setter
    return result;
}

ast::Method::Role roleOf(const model::plcopen::CodesysMember &m)
{
    switch (m.kind) {
    case model::plcopen::CodesysMember::Kind::Getter: return ast::Method::Role::Getter;
    case model::plcopen::CodesysMember::Kind::Setter: return ast::Method::Role::Setter;
    case model::plcopen::CodesysMember::Kind::Method: break;
    }
    return ast::Method::Role::Method;
}

// CODESYS's methods, properties, EXTENDS and IMPLEMENTS of a block, from its addData.
void addCodesysClass(const model::Pou &pou, ast::Pou &result, Diagnostics &diagnostics)
{
    const model::plcopen::CodesysClass oop = model::plcopen::readCodesysClass(pou);
    result.extends = oop.extends;
    result.implements = oop.implements;
    for (const model::plcopen::CodesysMember &m : oop.members) {
        ast::Method method;
        method.name = m.name;
        method.role = roleOf(m);
        method.access = m.qualifiers.contains(QLatin1String("PRIVATE")) ? ast::Access::Private
            : m.qualifiers.contains(QLatin1String("PROTECTED"))          ? ast::Access::Protected
            : m.qualifiers.contains(QLatin1String("INTERNAL"))           ? ast::Access::Internal
                                                                          : ast::Access::Public;
        method.isAbstract = m.qualifiers.contains(QLatin1String("ABSTRACT"));
        method.isFinal = m.qualifiers.contains(QLatin1String("FINAL"));
        ast::Pou declared = declarationOf(m, pou.name, diagnostics);
        method.sections = std::move(declared.sections);
        method.returnType = declared.returnType;
        method.hasBody = m.body.has_value() && !method.isAbstract;
        if (m.body)
            method.body = lowerBody(*m.body, result, ast::methodCodeName(pou.name, m.name, method.role), diagnostics);
        result.methods.push_back(std::move(method));
    }
}

void addPou(const model::Pou &pou, ast::CompilationUnit &unit, Diagnostics &diagnostics)
{
    ast::CompilationUnit declared = parseDeclarationsOf(printPouSkeleton(pou), pou.name, diagnostics);
    if (declared.pous.empty())
        return; // the name itself could not be parsed; already reported
    ast::Pou result = std::move(declared.pous.front());
    result.name = pou.name;
    if (pou.kind == model::PouKind::FunctionBlock)
        addCodesysClass(pou, result, diagnostics);
    const model::Body *body = pou.body();
    if (body && body->language() == model::BodyLanguage::SFC) {
        // The chart's lowering runs its actions and transitions itself.
        result.body.language = ast::Language::ST;
        sfc::lowerChart(pou, result, diagnostics);
    } else {
        if (body)
            result.body = lowerBody(*body, result, pou.name, diagnostics);
        for (const model::PouAction &action : pou.actions) {
            ast::SfcAction parsed;
            parsed.name = action.name;
            // Lines count in the action's own text, so its diagnostics name it: Main.Reset:2:5.
            if (action.body.language() == model::BodyLanguage::SFC) {
                parsed.body.language = ast::Language::ST;
                sfc::lowerActionChart(pou, action, result, parsed.body.statements, diagnostics);
            } else {
                parsed.body = lowerBody(action.body, result, pou.name + QLatin1Char('.') + action.name, diagnostics);
            }
            result.actions.push_back(std::move(parsed));
        }
    }
    unit.pous.push_back(std::move(result));
}

// The text of the project (declarations and ST/IL bodies) as the compiler's input.
// The printed text has one VAR_GLOBAL block per global variable list, in order, but no list
// names: they are copied over so that `List.Variable` resolves (CODESYS global lists).
void nameSections(const std::vector<model::VarList> &lists, std::vector<ast::VarSection> &sections)
{
    if (lists.size() != sections.size())
        return;
    for (size_t i = 0; i < lists.size(); ++i)
        sections[i].listName = lists[i].name.value_or(QString());
}

void nameGlobalLists(const model::Configuration &configuration, ast::ConfigurationDecl &declared)
{
    nameSections(configuration.globalVars, declared.globals);
    if (configuration.resources.size() != declared.resources.size())
        return;
    for (size_t i = 0; i < configuration.resources.size(); ++i)
        nameSections(configuration.resources[i].globalVars, declared.resources[i].globals);
}

ast::CompilationUnit parseProjectText(const model::Project &project, Diagnostics &diagnostics)
{
    ast::CompilationUnit unit;
    for (const model::DataTypeDecl &type : project.types.dataTypes) {
        ast::CompilationUnit declared = parseDeclarationsOf(printTypeDeclaration(type), type.name, diagnostics);
        moveAppend(unit.types, declared.types);
    }
    for (const model::Pou &pou : project.types.pous)
        addPou(pou, unit, diagnostics);
    for (const model::plcopen::CodesysInterface &itf : model::plcopen::readCodesysInterfaces(project)) {
        ast::Pou interfacePou;
        interfacePou.kind = ast::PouKind::Interface;
        interfacePou.name = itf.name;
        // The interfaces it extends: CODESYS writes each as <Extends>, which reads the first as
        // `extends` and the others as `implements`.
        if (!itf.definition.extends.isEmpty())
            interfacePou.implements << itf.definition.extends;
        interfacePou.implements << itf.definition.implements;
        for (const model::plcopen::CodesysMember &m : itf.definition.members) {
            ast::Method prototype;
            prototype.name = m.name;
            prototype.role = roleOf(m);
            prototype.hasBody = false;
            ast::Pou declared = declarationOf(m, itf.name, diagnostics);
            prototype.sections = std::move(declared.sections);
            prototype.returnType = declared.returnType;
            interfacePou.methods.push_back(std::move(prototype));
        }
        unit.pous.push_back(std::move(interfacePou));
    }
    for (const model::Configuration &configuration : project.instances.configurations) {
        ast::CompilationUnit declared
            = parseDeclarationsOf(printConfiguration(configuration), configuration.name, diagnostics);
        if (declared.configurations.size() == 1)
            nameGlobalLists(configuration, declared.configurations.front());
        moveAppend(unit.configurations, declared.configurations);
    }
    return unit;
}

} // namespace

ProjectUnit buildUnit(const model::Project &project, Diagnostics &diagnostics)
{
    Diagnostics parsing;
    ProjectUnit result;
    // Parsing and lowering on the compiler's stack, like the compile (limits.h).
    runOnCompilerStack([&] { result.unit = parseProjectText(project, parsing); });
    result.parseErrors = parsing.hasUnrequestedErrors();
    diagnostics.append(parsing);
    return result;
}

namespace {

std::shared_ptr<const Module> compileParsedUnit(
    const ProjectUnit &unit, Diagnostics &diagnostics, const CompileOptions &options)
{
    Diagnostics compiling;
    const bool hasTextualCharts = std::any_of(unit.unit.pous.begin(), unit.unit.pous.end(),
        [](const ast::Pou &pou) {
            return pou.body.language == ast::Language::SFC
                || std::any_of(pou.actions.begin(), pou.actions.end(), [](const ast::SfcAction &a) { return a.body.language == ast::Language::SFC; });
        });
    if (hasTextualCharts) { // parsed straight from .st text: lower the charts here
        ast::CompilationUnit lowered = unit.unit;
        sfc::lowerTextualCharts(lowered, compiling);
        std::shared_ptr<const Module> module = compiling.hasErrors() ? nullptr : compile({&lowered}, compiling, options);
        diagnostics.append(compiling);
        return diagnostics.hasErrors() ? nullptr : module;
    }
    std::shared_ptr<const Module> module = compile({&unit.unit}, compiling, options);
    diagnostics.append(compiling);
    return diagnostics.hasErrors() ? nullptr : module;
}

} // namespace

std::shared_ptr<const Module> compileUnit(
    const ProjectUnit &unit, Diagnostics &diagnostics, const CompileOptions &options)
{
    if (unit.parseErrors)
        return nullptr;
    // The lowering of textual charts on the compiler's stack, like the compile (limits.h).
    std::shared_ptr<const Module> module;
    runOnCompilerStack([&] { module = compileParsedUnit(unit, diagnostics, options); });
    return module;
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
    // Lowering and parsing run on the compiler's stack too (limits.h).
    std::shared_ptr<const Module> module;
    runOnCompilerStack([&] { module = compileUnit(buildUnit(project, diagnostics), diagnostics, options); });
    return module;
}

} // namespace iec::interp::frontend
