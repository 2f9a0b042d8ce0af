#include "interpreter/frontend/iecreader.h"

#include "interpreter/compiler/astdump.h"
#include "interpreter/compiler/compilerstack.h"
#include "model/filetext.h"
#include "interpreter/compiler/lexer.h"
#include "interpreter/compiler/parser.h"
#include "interpreter/frontend/codesysmembers.h"
#include "interpreter/frontend/iecprinter.h"
#include "interpreter/frontend/sourcefile.h"
#include "interpreter/frontend/tokencursor.h"
#include "interpreter/sfc/sfctext.h"

#include <QCoreApplication>
#include <QRegularExpression>

namespace iec::interp::frontend {

namespace {

// ---- expressions back to text (initial values, bounds, task settings) ------------------------

QString exprText(const ast::Expr &e)
{
    return ast::sourceText(e);
}

QString optionalText(const std::optional<ast::Expr> &e)
{
    return e ? exprText(*e) : QString();
}

// ---- declarations ----------------------------------------------------------------------------

model::DataType toModel(const ast::TypeSpec &spec);
std::vector<model::Variable> toModel(const std::vector<ast::VarDecl> &vars);

model::DataType namedType(const QString &name)
{
    if (isTypeName(name) && name.compare(QLatin1String("STRING"), Qt::CaseInsensitive) != 0)
        return {model::ElementaryType {name.toUpper()}};
    return {model::DerivedType {name, {}, {}}};
}

model::Range toModel(const ast::Range &range)
{
    return {exprText(range.low), exprText(range.high)};
}

model::DataType enumType(const ast::TypeSpec &spec)
{
    model::EnumType type;
    for (qsizetype i = 0; i < spec.enumValues.size(); ++i) {
        const auto &explicitValue = spec.enumExplicit[size_t(i)];
        type.values.push_back(
            {spec.enumValues[i], explicitValue ? std::optional(exprText(*explicitValue)) : std::nullopt});
    }
    if (!spec.name.isEmpty())
        type.baseType = model::Box<model::DataType>(namedType(spec.name));
    return {type};
}

model::DataType toModel(const ast::TypeSpec &spec)
{
    switch (spec.kind) {
    case ast::TypeSpec::Kind::Named:
        return namedType(spec.name);
    case ast::TypeSpec::Kind::String:
        return {model::StringType {spec.wide, spec.length ? std::optional(exprText(*spec.length)) : std::nullopt}};
    case ast::TypeSpec::Kind::Array: {
        model::ArrayType type;
        for (const ast::Range &range : spec.ranges)
            type.dimensions.push_back(toModel(range));
        type.baseType = model::Box<model::DataType>(toModel(spec.element.front()));
        return {type};
    }
    case ast::TypeSpec::Kind::Subrange: {
        const model::DataType base = namedType(spec.name);
        const bool isUnsigned = spec.name.startsWith(QLatin1Char('U'), Qt::CaseInsensitive);
        return {model::SubrangeType {isUnsigned, toModel(spec.ranges.front()), model::Box<model::DataType>(base)}};
    }
    case ast::TypeSpec::Kind::Enum:
        return enumType(spec);
    case ast::TypeSpec::Kind::Struct: {
        model::StructType type;
        type.members = toModel(spec.members);
        return {type};
    }
    case ast::TypeSpec::Kind::Pointer:
        return {model::PointerType {model::Box<model::DataType>(toModel(spec.element.front()))}};
    case ast::TypeSpec::Kind::Reference: // PLCopen has no reference type: CODESYS's own spelling
        return {model::DerivedType {QStringLiteral("REFERENCE TO ") + printDataType(toModel(spec.element.front())), {}, {}}};
    }
    return namedType(spec.name);
}

std::optional<model::Value> toModel(const ast::Initializer &init)
{
    switch (init.kind) {
    case ast::Initializer::Kind::None:
        return std::nullopt;
    case ast::Initializer::Kind::Expression:
        return model::Value {model::SimpleValue {optionalText(init.value)}};
    case ast::Initializer::Kind::Array: {
        model::ArrayValue value;
        for (size_t i = 0; i < init.items.size(); ++i) {
            const auto &repeat = init.repeats[i];
            const std::optional<model::Value> item = toModel(init.items[i]);
            value.values.push_back({repeat ? std::optional(exprText(*repeat)) : std::nullopt,
                model::Box<model::Value>(item.value_or(model::Value {}))});
        }
        return model::Value {value};
    }
    case ast::Initializer::Kind::Struct: {
        model::StructValue value;
        for (size_t i = 0; i < init.items.size(); ++i) {
            const std::optional<model::Value> item = toModel(init.items[i]);
            value.values.push_back(
                {init.memberNames[qsizetype(i)], model::Box<model::Value>(item.value_or(model::Value {}))});
        }
        return model::Value {value};
    }
    }
    return std::nullopt;
}

std::vector<model::Variable> toModel(const std::vector<ast::VarDecl> &vars)
{
    std::vector<model::Variable> result;
    for (const ast::VarDecl &decl : vars) {
        model::Variable variable;
        variable.name = decl.name;
        if (!decl.address.isEmpty())
            variable.address = decl.address;
        variable.type = toModel(decl.type);
        variable.initialValue = toModel(decl.init);
        result.push_back(std::move(variable));
    }
    return result;
}

std::optional<model::VarListKind> listKind(ast::VarKind kind)
{
    switch (kind) {
    case ast::VarKind::Local:
        return model::VarListKind::Local;
    case ast::VarKind::Input:
        return model::VarListKind::Input;
    case ast::VarKind::Output:
        return model::VarListKind::Output;
    case ast::VarKind::InOut:
        return model::VarListKind::InOut;
    case ast::VarKind::External:
        return model::VarListKind::External;
    case ast::VarKind::Global:
        return model::VarListKind::Global;
    case ast::VarKind::Temp:
        return model::VarListKind::Temp;
    case ast::VarKind::Access:
        return model::VarListKind::Access;
    case ast::VarKind::Config:
        return std::nullopt;
    }
    return std::nullopt;
}

// The name of the global variable list a section is, from the comment CODESYS V2.3 writes on
// the line before it: (* @GLOBAL_VARIABLE_LIST := IO *). Empty when there is none.
QString globalListName(QStringView text, const ast::VarSection &section)
{
    static const QRegularExpression named(
        QStringLiteral("\\(\\*\\s*@GLOBAL_VARIABLE_LIST\\s*:=\\s*([A-Za-z_][A-Za-z0-9_]*)\\s*\\*\\)\\s*$"));
    qsizetype lineStart = 0;
    for (int line = 1; line < section.location.line && lineStart >= 0; ++line)
        lineStart = text.indexOf(u'\n', lineStart) + 1;
    if (lineStart <= 0)
        return {};
    const QStringView before = text.left(lineStart).trimmed();
    const qsizetype previousLine = before.lastIndexOf(u'\n') + 1;
    return named.match(before.mid(previousLine).toString()).captured(1);
}

std::vector<model::VarList> toModel(const std::vector<ast::VarSection> &sections, const QString &owner,
    Diagnostics &diagnostics, QStringView text = {})
{
    std::vector<model::VarList> lists;
    for (const ast::VarSection &section : sections) {
        const auto kind = listKind(section.kind);
        if (!kind) {
            diagnostics.warning(owner, section.location,
                QCoreApplication::translate("iec::interp::Compiler", "VAR_CONFIG cannot be stored in a PLCopen project yet and was left out."));
            continue;
        }
        model::VarList list;
        list.kind = *kind;
        list.constant = section.constant;
        list.retain = section.retain;
        list.nonretain = section.nonRetain;
        list.variables = toModel(section.vars);
        if (const QString name = globalListName(text, section); list.kind == model::VarListKind::Global && !name.isEmpty())
            list.name = name;
        lists.push_back(std::move(list));
    }
    return lists;
}

// ---- configurations --------------------------------------------------------------------------

model::Task toModel(const ast::TaskDecl &decl, const QString &owner, Diagnostics &diagnostics)
{
    model::Task task;
    task.name = decl.name;
    if (decl.single)
        task.single = exprText(*decl.single);
    if (decl.interval)
        task.interval = exprText(*decl.interval);
    if (decl.priority) {
        bool ok = false;
        task.priority = exprText(*decl.priority).toUInt(&ok);
        if (!ok || task.priority > 65535)
            diagnostics.warning(owner, decl.priority->location,
                QCoreApplication::translate("iec::interp::Compiler", "The priority of task %1 must be a number from 0 to 65535; 0 is used.").arg(decl.name));
    }
    return task;
}

void addProgram(
    const ast::ProgramConfig &program, model::Resource &resource, const QString &owner, Diagnostics &diagnostics)
{
    if (!program.args.empty()) {
        diagnostics.warning(owner, program.location,
            QCoreApplication::translate("iec::interp::Compiler",
                "The arguments of program instance %1 cannot be stored in a PLCopen project and were left out.")
                .arg(program.instance));
    }
    const model::PouInstance instance {program.instance, program.type, {}, {}, {}, {}};
    for (model::Task &task : resource.tasks) {
        if (task.name.compare(program.task, Qt::CaseInsensitive) == 0) {
            task.pouInstances.push_back(instance);
            return;
        }
    }
    resource.pouInstances.push_back(instance); // no WITH (or an unknown task: the compiler reports it)
}

model::Configuration toModel(const ast::ConfigurationDecl &decl, QStringView text, Diagnostics &diagnostics)
{
    model::Configuration configuration;
    configuration.name = decl.name;
    configuration.globalVars = toModel(decl.globals, decl.name, diagnostics, text);
    for (const ast::ResourceDecl &r : decl.resources) {
        model::Resource resource;
        resource.name = r.name.isEmpty() ? QStringLiteral("Resource") : r.name;
        resource.globalVars = toModel(r.globals, decl.name, diagnostics, text);
        for (const ast::TaskDecl &task : r.tasks)
            resource.tasks.push_back(toModel(task, decl.name, diagnostics));
        for (const ast::ProgramConfig &program : r.programs)
            addProgram(program, resource, decl.name, diagnostics);
        configuration.resources.push_back(std::move(resource));
    }
    return configuration;
}

// ---- bodies: the text between the declarations and END_xxx, as written ------------------------

struct PouTexts {
    QString body;
    std::vector<std::pair<QString, QString>> actions; // name, text
    std::vector<QString> members; // METHOD ... END_METHOD, PROPERTY ... END_PROPERTY
};

// At a METHOD or PROPERTY: its whole text, up to and with its END_METHOD or END_PROPERTY.
QString memberText(TokenCursor &cursor, QStringView source)
{
    const char *end = cursor.is("METHOD") ? "END_METHOD" : "END_PROPERTY";
    const int start = cursor.start();
    return source.mid(start, cursor.skipPast(end) - start).toString();
}

// At PROGRAM / FUNCTION_BLOCK / FUNCTION: finds the body and the actions' texts.
PouTexts pouTexts(TokenCursor &cursor, QStringView source)
{
    const QByteArray end = "END_" + cursor.text().toString().toUpper().toLatin1();
    cursor.next(); // the keyword
    int bodyStart = cursor.start();
    while (cursor.is("ABSTRACT") || cursor.is("FINAL") || cursor.is("PUBLIC") || cursor.is("INTERNAL"))
        cursor.next();
    if (!cursor.atEnd()) { // the name
        bodyStart = cursor.end();
        cursor.next();
    }
    // EXTENDS Base IMPLEMENTS I1, Lib.I2 (edition 3): a list of dotted names each.
    while (cursor.is("EXTENDS") || cursor.is("IMPLEMENTS")) {
        cursor.next();
        while (cursor.isName()) {
            bodyStart = cursor.end();
            cursor.next();
            if (cursor.text() == u"." || cursor.text() == u",")
                cursor.next(); // the next part of the name, or the next name
            else
                break;
        }
    }
    if (cursor.is(":")) { // a function's result type: up to the end of its line
        const int lineEnd = cursor.lineEndAfter(cursor.end());
        while (!cursor.atEnd() && cursor.start() < lineEnd && !cursor.isVarSection() && !cursor.is(end.constData())) {
            bodyStart = cursor.end();
            cursor.next();
        }
    }
    while (cursor.isVarSection())
        bodyStart = cursor.skipPast("END_VAR");
    PouTexts texts;
    // Methods and properties stand before the body (edition 3) or after it (CODESYS exports).
    while (cursor.startsMember()) {
        const int memberStart = cursor.start();
        texts.members.push_back(memberText(cursor, source));
        bodyStart = memberStart + int(texts.members.back().size());
    }
    while (!cursor.atEnd() && !cursor.is(end.constData()) && !cursor.is("ACTION") && !cursor.startsMember())
        cursor.next();
    texts.body = bodyText(source, bodyStart, cursor.start());
    // Actions follow the body; in a textual SFC chart they may also stand between steps.
    while (!cursor.atEnd() && !cursor.is(end.constData())) {
        if (cursor.startsMember()) {
            texts.members.push_back(memberText(cursor, source));
            continue;
        }
        if (!cursor.is("ACTION")) {
            cursor.next();
            continue;
        }
        cursor.next();
        const QString name = cursor.atEnd() ? QString() : cursor.text().toString();
        cursor.next();
        const int actionStart = cursor.is(":") ? cursor.end() : cursor.start();
        while (!cursor.atEnd() && !cursor.is("END_ACTION"))
            cursor.next();
        texts.actions.emplace_back(name, bodyText(source, actionStart, cursor.start()));
        cursor.next();
    }
    cursor.skipPast(end.constData());
    return texts;
}

// The texts of every POU in source order.
std::vector<PouTexts> allPouTexts(QStringView source)
{
    std::vector<PouTexts> result;
    TokenCursor cursor(source);
    while (!cursor.atEnd()) {
        if (cursor.is("TYPE"))
            cursor.skipPast("END_TYPE");
        else if (cursor.is("CONFIGURATION"))
            cursor.skipPast("END_CONFIGURATION");
        else if (cursor.isVarSection())
            cursor.skipPast("END_VAR");
        else if (cursor.is("PROGRAM") || cursor.is("FUNCTION_BLOCK") || cursor.is("FUNCTION")
            || (cursor.is("INTERFACE") && cursor.nameFollows())) // in the parser's order of POUs
            result.push_back(pouTexts(cursor, source));
        else
            cursor.next();
    }
    return result;
}

model::PouKind toModel(ast::PouKind kind)
{
    switch (kind) {
    case ast::PouKind::Program:
        return model::PouKind::Program;
    case ast::PouKind::FunctionBlock:
        return model::PouKind::FunctionBlock;
    case ast::PouKind::Function:
        return model::PouKind::Function;
    case ast::PouKind::Interface: // not a POU in the model: see interfaceAddData
        return model::PouKind::FunctionBlock;
    }
    return model::PouKind::Program;
}

model::Body textBody(ast::Language language, const QString &text)
{
    model::Body body
        = model::Body::withLanguage(language == ast::Language::IL ? model::BodyLanguage::IL : model::BodyLanguage::ST);
    body.setText(text);
    return body;
}

// An action's body: a textual chart becomes a graphical SFC body as the POU's own chart does
// (`where`: Pou.Action); other text is kept as written.
model::Body actionBody(const ast::Body &parsed, const QString &text, const QString &where, Diagnostics &diagnostics)
{
    if (parsed.language == ast::Language::SFC && parsed.sfc)
        return sfc::chartToModel(*parsed.sfc, where, diagnostics);
    return textBody(parsed.language, text);
}

// Methods, properties, EXTENDS and IMPLEMENTS go where CODESYS keeps them: the POU's addData
// and its interface's (codesysmembers.h). The parse of the whole text reported their errors.
void addObjectOrientation(model::Pou &result, const ast::Pou &pou, const PouTexts &texts)
{
    for (const QString &text : texts.members) {
        if (const CodesysMemberText read = readCodesysMemberText(text, pou.name); read.definition)
            result.addData = model::plcopen::addDataWithMember(result.addData, {}, *read.definition);
    }
    if (result.pouInterface)
        result.pouInterface->addData
            = model::plcopen::addDataWithInheritance(result.pouInterface->addData, pou.extends, pou.implements);
}

model::plcopen::CodesysInterfaceDefinition interfaceDefinition(const ast::Pou &pou, const PouTexts &texts)
{
    model::plcopen::CodesysInterfaceDefinition definition {pou.name, pou.implements, {}};
    for (const QString &text : texts.members) {
        if (const CodesysMemberText read = readCodesysMemberText(text, pou.name); read.definition)
            definition.members.push_back(*read.definition);
    }
    return definition;
}

// An INTERFACE goes where CODESYS keeps it: an entry of the project's addData.
model::AddData interfaceAddData(const model::AddData &addData, const ast::Pou &pou, const PouTexts &texts)
{
    return model::plcopen::addDataWithInterface(addData, pou.name, interfaceDefinition(pou, texts));
}

model::Pou toModel(const ast::Pou &pou, const PouTexts &texts, Diagnostics &diagnostics)
{
    model::Pou result;
    result.name = pou.name;
    result.kind = toModel(pou.kind);
    model::Interface interface;
    if (pou.returnType)
        interface.returnType = toModel(*pou.returnType);
    interface.varLists = toModel(pou.sections, pou.name, diagnostics);
    result.pouInterface = std::move(interface);
    addObjectOrientation(result, pou, texts);
    if (pou.body.language == ast::Language::SFC && pou.body.sfc) {
        // The chart becomes a graphical SFC body; its ACTIONs become the POU's actions.
        result.bodies.push_back(sfc::chartToModel(*pou.body.sfc, pou.name, diagnostics));
        for (size_t i = 0; i < pou.body.sfc->actions.size() && i < texts.actions.size(); ++i) {
            model::PouAction action;
            action.name = texts.actions[i].first;
            action.body = actionBody(pou.body.sfc->actions[i].body, texts.actions[i].second, pou.name + QLatin1Char('.') + action.name, diagnostics);
            result.actions.push_back(std::move(action));
        }
        return result;
    }
    result.bodies.push_back(textBody(pou.body.language, texts.body));
    for (size_t i = 0; i < pou.actions.size() && i < texts.actions.size(); ++i) {
        model::PouAction action;
        action.name = texts.actions[i].first;
        action.body = actionBody(pou.actions[i].body, texts.actions[i].second, pou.name + QLatin1Char('.') + action.name, diagnostics);
        result.actions.push_back(std::move(action));
    }
    return result;
}

model::Project emptyProject(const QString &name)
{
    model::Project project;
    project.fileHeader.companyName = QStringLiteral("IEC Studio");
    project.fileHeader.productName = QStringLiteral("IEC Studio");
    project.contentHeader.name = name;
    return project;
}

} // namespace

std::vector<model::VarList> varListsFromAst(
    const std::vector<ast::VarSection> &sections, const QString &owner, Diagnostics &diagnostics)
{
    return toModel(sections, owner, diagnostics);
}

model::DataType dataTypeFromAst(const ast::TypeSpec &spec)
{
    return toModel(spec);
}

// Characters XML 1.0 cannot hold (NUL and the other control characters but tab and line breaks,
// U+FFFE, U+FFFF): a project file could not keep the text, so they are an error where they stand
// (a NUL in a comment cut the body short in the saved file; found by fuzz_iectext).
void reportUnstorableCharacters(QStringView text, Diagnostics &diagnostics)
{
    int line = 1;
    int column = 1;
    for (const QChar c : text) {
        const char16_t u = c.unicode();
        if (!model::fileCanKeep(u)) {
            diagnostics.error({}, {line, column},
                QCoreApplication::translate("iec::interp::Compiler",
                    "The text holds the control character U+%1, which a project file cannot keep; remove it.")
                    .arg(QStringLiteral("%1").arg(int(u), 4, 16, QLatin1Char('0')).toUpper()));
            return;
        }
        if (u == u'\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
}

InterfaceText readInterfaceText(QStringView text)
{
    InterfaceText result;
    reportUnstorableCharacters(text, result.diagnostics);
    ast::CompilationUnit unit;
    runOnCompilerStack([&] { unit = parseUnit(text, result.diagnostics); });
    if (result.diagnostics.hasErrors())
        return result;
    const bool one = unit.pous.size() == 1 && unit.pous.front().kind == ast::PouKind::Interface && unit.types.empty()
        && unit.configurations.empty() && unit.globals.empty();
    if (!one) {
        result.diagnostics.error({}, {1, 1, -1, -1},
            QCoreApplication::translate("iec::interp::Compiler", "This text must be one INTERFACE ... END_INTERFACE and nothing else."));
        return result;
    }
    const std::vector<PouTexts> texts = allPouTexts(text);
    result.definition = interfaceDefinition(unit.pous.front(), texts.empty() ? PouTexts {} : texts.front());
    return result;
}

TextReadResult readIecText(QStringView text, const QString &projectName)
{
    // Line ends as the file reader leaves them (decodeSourceFile): an XML file keeps no CR, so a
    // body holding one would read back from the saved project as another text (found by fuzz_iectext).
    QString withoutCr;
    if (text.contains(QLatin1Char('\r'))) {
        withoutCr = text.toString();
        useLfLineEnds(withoutCr);
        text = withoutCr;
    }
    TextReadResult result;
    result.project = emptyProject(projectName);
    reportUnstorableCharacters(text, result.diagnostics);
    ast::CompilationUnit unit;
    // On the compiler's stack, so that the parser's limits hold in any thread (limits.h).
    runOnCompilerStack([&] { unit = parseUnit(text, result.diagnostics); });
    for (const ast::TypeDecl &type : unit.types)
        result.project.types.dataTypes.push_back({type.name, toModel(type.type), toModel(type.init), {}, {}, {}, 0});
    const std::vector<PouTexts> texts = allPouTexts(text);
    for (size_t i = 0; i < unit.pous.size(); ++i) {
        const PouTexts &pouTexts = i < texts.size() ? texts[i] : PouTexts {};
        if (unit.pous[i].kind == ast::PouKind::Interface)
            result.project.addData = interfaceAddData(result.project.addData, unit.pous[i], pouTexts);
        else
            result.project.types.pous.push_back(toModel(unit.pous[i], pouTexts, result.diagnostics));
    }
    for (const ast::ConfigurationDecl &configuration : unit.configurations)
        result.project.instances.configurations.push_back(toModel(configuration, text, result.diagnostics));
    if (!unit.globals.empty()) {
        result.diagnostics.warning({}, unit.globals.front().location,
            QCoreApplication::translate("iec::interp::Compiler", "VAR_GLOBAL outside a CONFIGURATION cannot be stored in a PLCopen project; put it inside "
                           "the CONFIGURATION."));
    }
    return result;
}

} // namespace iec::interp::frontend
