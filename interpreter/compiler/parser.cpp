// The parser (parserclass.h): compilation units, POUs and their members, types, configurations,
// declarations and bodies; and the entry points of parser.h.
#include "interpreter/compiler/parser.h"

#include "interpreter/compiler/compilerstack.h"
#include "interpreter/compiler/parserclass.h"

namespace iec::interp {

namespace parsing {

// ============================================================================ units

CompilationUnit Parser::unit()
{
    CompilationUnit unit;
    while (!atEnd()) {
        m_pou.clear();
        if (isWord("PROGRAM") || isWord("FUNCTION") || isWord("FUNCTION_BLOCK") || (isWord("INTERFACE") && isName(1))) {
            pou(unit);
        } else if (isWord("TYPE")) {
            typeBlock(unit);
        } else if (isWord("CONFIGURATION")) {
            configuration(unit);
        } else if (isVarSectionStart()) {
            unit.globals.push_back(varSection());
        } else {
            unexpected(QCoreApplication::translate("iec::interp::Compiler", "PROGRAM, FUNCTION_BLOCK, FUNCTION, TYPE or CONFIGURATION"));
            ++m_pos;
            while (!atEnd() && !isPouStart() && !isVarSectionStart())
                ++m_pos;
            m_recovering = false;
        }
    }
    return unit;
}

void Parser::pou(CompilationUnit &unit)
{
    Pou p;
    p.location = here();
    std::string_view end;
    if (acceptWord("PROGRAM")) {
        p.kind = PouKind::Program;
        end = "END_PROGRAM";
    } else if (acceptWord("FUNCTION_BLOCK")) {
        p.kind = PouKind::FunctionBlock;
        end = "END_FUNCTION_BLOCK";
    } else if (acceptWord("INTERFACE")) {
        p.kind = PouKind::Interface;
        end = "END_INTERFACE";
    } else {
        acceptWord("FUNCTION");
        p.kind = PouKind::Function;
        end = "END_FUNCTION";
    }
    pouHeader(p);
    m_pou = p.name;
    if (p.kind == PouKind::Function) {
        if (acceptOp(u":"))
            p.returnType = typeSpec();
        else
            error(here(), QCoreApplication::translate("iec::interp::Compiler", "A FUNCTION needs a result type after its name."),
                  QCoreApplication::translate("iec::interp::Compiler", "write e.g. FUNCTION %1 : INT").arg(p.name));
    }
    while (isVarSectionStart())
        p.sections.push_back(varSection());
    members(p);
    if (p.kind != PouKind::Interface)
        p.body = body({end, "ACTION"});
    // Actions (and methods, properties) after the body, as CODESYS exports them.
    members(p);
    while (isWord("ACTION") && startsSfcElement()) {
        SfcAction action;
        action.location = here();
        ++m_pos;
        action.name = expectName(QCoreApplication::translate("iec::interp::Compiler", "the name of the action"));
        acceptOp(u":");
        action.body = body({"END_ACTION"});
        expectWord("END_ACTION");
        p.actions.push_back(std::move(action));
    }
    members(p);
    if (p.body.language == Language::SFC) { // in a chart, actions belong to the chart
        for (SfcAction &action : p.actions)
            p.body.sfc->actions.push_back(std::move(action));
        p.actions.clear();
    }
    if (acceptWord(end)) {
        // closed
    } else if (isMisspelledEnd()) {
        error(here(), QCoreApplication::translate("iec::interp::Compiler", "Expected %1 but found '%2'.").arg(QString::fromLatin1(end.data(), qsizetype(end.size())), text().toString()));
        ++m_pos;
        m_recovering = false;
    } else {
        error(p.location, QCoreApplication::translate("iec::interp::Compiler", "%1 has no %2.").arg(p.name, QString::fromLatin1(end.data(), qsizetype(end.size()))),
              QCoreApplication::translate("iec::interp::Compiler", "add %1 after its last statement").arg(QString::fromLatin1(end.data(), qsizetype(end.size()))));
        while (!atEnd() && !isPouStart())
            ++m_pos;
        m_recovering = false;
    }
    unit.pous.push_back(std::move(p));
}

// The name and, for function blocks and interfaces, ABSTRACT/FINAL, EXTENDS and IMPLEMENTS.
void Parser::pouHeader(Pou &p)
{
    while ((isWord("ABSTRACT") || isWord("FINAL") || isWord("PUBLIC") || isWord("INTERNAL")) && isName(1)) {
        p.isAbstract = p.isAbstract || isWord("ABSTRACT");
        p.isFinal = p.isFinal || isWord("FINAL");
        ++m_pos;
    }
    p.name = expectName(QCoreApplication::translate("iec::interp::Compiler", "the name of the POU"));
    if (p.kind != PouKind::FunctionBlock && p.kind != PouKind::Interface)
        return;
    if (acceptWord("EXTENDS")) {
        // An interface may extend several interfaces.
        do {
            const QString base = expectName(QCoreApplication::translate("iec::interp::Compiler", "the name it extends"));
            if (p.kind == PouKind::Interface)
                p.implements << base;
            else
                p.extends = base;
        } while (p.kind == PouKind::Interface && acceptOp(u","));
    }
    if (p.kind == PouKind::FunctionBlock && acceptWord("IMPLEMENTS")) {
        do
            p.implements << expectName(QCoreApplication::translate("iec::interp::Compiler", "the name of an interface"));
        while (acceptOp(u","));
    }
}

// PUBLIC, PRIVATE, PROTECTED, INTERNAL, ABSTRACT, FINAL before a method's or property's name.
Access Parser::qualifiers(bool &isAbstract, bool &isFinal)
{
    Access access = Access::Public;
    for (;;) {
        if (!isName(1) && !(!atEnd(1) && isWordToken(tok(1)) && !isOp(u":", 1) && !isOp(u";", 1)))
            break;
        if (acceptWord("PUBLIC"))
            access = Access::Public;
        else if (acceptWord("PRIVATE"))
            access = Access::Private;
        else if (acceptWord("PROTECTED"))
            access = Access::Protected;
        else if (acceptWord("INTERNAL"))
            access = Access::Internal;
        else if (acceptWord("ABSTRACT"))
            isAbstract = true;
        else if (acceptWord("FINAL"))
            isFinal = true;
        else
            break;
    }
    return access;
}

// The METHODs and PROPERTYs of a function block or interface, where they stand.
void Parser::members(Pou &p)
{
    while (startsMember()) {
        const size_t before = m_pos;
        if (isWord("METHOD"))
            p.methods.push_back(method(p.kind == PouKind::Interface));
        else
            property(p, p.kind == PouKind::Interface);
        skipIfStuck(before);
    }
}

Method Parser::method(bool prototype)
{
    Method m;
    m.location = here();
    ++m_pos; // METHOD
    m.access = qualifiers(m.isAbstract, m.isFinal);
    m.name = expectName(QCoreApplication::translate("iec::interp::Compiler", "the name of the method"));
    if (acceptOp(u":"))
        m.returnType = typeSpec();
    acceptOp(u";");
    while (isVarSectionStart())
        m.sections.push_back(varSection());
    m.hasBody = !prototype && !m.isAbstract;
    m.body = body({"END_METHOD"});
    if (!acceptWord("END_METHOD")) {
        error(m.location, QCoreApplication::translate("iec::interp::Compiler", "The method %1 has no END_METHOD.").arg(m.name));
        while (!atEnd() && !isWord("END_METHOD") && !isPouStart())
            ++m_pos;
        acceptWord("END_METHOD");
        m_recovering = false;
    }
    acceptOp(u";");
    return m;
}

// PROPERTY name : type, with GET ... END_GET and SET ... END_SET: a getter returning the value
// and a setter taking it, both named like the property.
void Parser::property(Pou &p, bool prototype)
{
    const SourceLocation at = here();
    ++m_pos; // PROPERTY
    Method getter;
    getter.location = at;
    getter.access = qualifiers(getter.isAbstract, getter.isFinal);
    getter.name = expectName(QCoreApplication::translate("iec::interp::Compiler", "the name of the property"));
    if (expectOp(u":", QCoreApplication::translate("iec::interp::Compiler", "':' and the type of the property")))
        getter.returnType = typeSpec();
    acceptOp(u";");
    bool hasGet = false, hasSet = false;
    Method setter = getter;
    setter.returnType.reset();
    getter.role = Method::Role::Getter;
    setter.role = Method::Role::Setter;
    while ((isWord("GET") || isWord("SET")) && !isOp(u":=", 1)) {
        const bool get = isWord("GET");
        Method &accessor = get ? getter : setter;
        (get ? hasGet : hasSet) = true;
        accessor.location = here();
        ++m_pos;
        while (isVarSectionStart())
            accessor.sections.push_back(varSection());
        accessor.hasBody = !prototype && !accessor.isAbstract;
        accessor.body = body({get ? "END_GET" : "END_SET"});
        expectWord(get ? "END_GET" : "END_SET");
        acceptOp(u";");
    }
    if (!acceptWord("END_PROPERTY")) {
        error(at, QCoreApplication::translate("iec::interp::Compiler", "The property %1 has no END_PROPERTY.").arg(getter.name));
        while (!atEnd() && !isWord("END_PROPERTY") && !isPouStart())
            ++m_pos;
        acceptWord("END_PROPERTY");
        m_recovering = false;
    }
    acceptOp(u";");
    if (hasSet && getter.returnType) {
        VarSection input;
        input.kind = VarKind::Input;
        VarDecl value;
        value.name = setter.name;
        value.location = setter.location;
        value.type = *getter.returnType;
        input.vars.push_back(std::move(value));
        setter.sections.insert(setter.sections.begin(), std::move(input));
        p.methods.push_back(std::move(setter));
    }
    if (hasGet || !hasSet)
        p.methods.push_back(std::move(getter));
}

void Parser::typeBlock(CompilationUnit &unit)
{
    ++m_pos; // TYPE
    while (!atEnd() && !isWord("END_TYPE") && !isPouStart()) {
        const size_t before = m_pos;
        TypeDecl decl;
        decl.location = here();
        decl.name = expectName(QCoreApplication::translate("iec::interp::Compiler", "the name of a type"));
        if (decl.name.isEmpty() || !expectOp(u":", QCoreApplication::translate("iec::interp::Compiler", "':' after the type name"))) {
            synchronize(false);
            skipIfStuck(before);
            continue;
        }
        decl.type = typeSpec();
        if (acceptOp(u":="))
            decl.init = declarationInitializer();
        // CODESYS (2.3 exports, 3.5, TwinCAT) writes END_STRUCT END_TYPE with no ';' between.
        if (!acceptOp(u";") && !isWord("END_TYPE")) {
            error(afterPrevious(), QCoreApplication::translate("iec::interp::Compiler", "Missing ';' after the declaration of type %1.").arg(decl.name));
            synchronize(false);
        }
        m_recovering = false;
        unit.types.push_back(std::move(decl));
    }
    expectWord("END_TYPE");
    m_recovering = false;
}

void Parser::configuration(CompilationUnit &unit)
{
    ConfigurationDecl config;
    config.location = here();
    ++m_pos;
    config.name = expectName(QCoreApplication::translate("iec::interp::Compiler", "the name of the configuration"));
    m_pou = config.name;
    while (isVarSectionStart())
        config.globals.push_back(varSection());
    if (isWord("RESOURCE")) {
        while (acceptWord("RESOURCE")) {
            ResourceDecl resource;
            resource.location = here();
            resource.name = expectName(QCoreApplication::translate("iec::interp::Compiler", "the name of the resource"));
            if (acceptWord("ON"))
                resource.on = expectName(QCoreApplication::translate("iec::interp::Compiler", "the processor type after ON"));
            resourceContents(resource, "END_RESOURCE");
            expectWord("END_RESOURCE");
            config.resources.push_back(std::move(resource));
        }
    } else {
        ResourceDecl resource; // tasks and programs directly in the configuration
        resource.location = config.location;
        resourceContents(resource, "END_CONFIGURATION");
        config.resources.push_back(std::move(resource));
    }
    expectWord("END_CONFIGURATION");
    m_recovering = false;
    unit.configurations.push_back(std::move(config));
}

void Parser::resourceContents(ResourceDecl &resource, std::string_view end)
{
    while (!atEnd() && !isWord(end) && !isWord("END_CONFIGURATION")) {
        if (isVarSectionStart()) {
            resource.globals.push_back(varSection());
        } else if (acceptWord("TASK")) {
            TaskDecl task;
            task.location = here();
            task.name = expectName(QCoreApplication::translate("iec::interp::Compiler", "the name of the task"));
            if (expectOp(u"(", QCoreApplication::translate("iec::interp::Compiler", "'(' with the task's INTERVAL and PRIORITY"))) {
                while (!atEnd() && !isOp(u")")) {
                    const bool single = isWord("SINGLE"), interval = isWord("INTERVAL"), priority = isWord("PRIORITY");
                    if (!single && !interval && !priority) {
                        unexpected(QCoreApplication::translate("iec::interp::Compiler", "SINGLE, INTERVAL or PRIORITY"));
                        break;
                    }
                    ++m_pos;
                    expectOp(u":=", QStringLiteral("':='"));
                    Expr value = expression();
                    (single ? task.single : interval ? task.interval : task.priority) = std::move(value);
                    if (!acceptOp(u","))
                        break;
                }
                expectOp(u")", QStringLiteral("')'"));
            }
            endStatement();
            resource.tasks.push_back(std::move(task));
        } else if (acceptWord("PROGRAM")) {
            ProgramConfig program;
            program.location = here();
            program.retain = acceptWord("RETAIN");
            acceptWord("NON_RETAIN");
            program.instance = expectName(QCoreApplication::translate("iec::interp::Compiler", "the name of the program instance"));
            if (acceptWord("WITH"))
                program.task = expectName(QCoreApplication::translate("iec::interp::Compiler", "the task name after WITH"));
            expectOp(u":", QCoreApplication::translate("iec::interp::Compiler", "':' and the program type"));
            program.type = expectName(QCoreApplication::translate("iec::interp::Compiler", "the program type"));
            if (acceptOp(u"("))
                program.args = callArguments();
            endStatement();
            resource.programs.push_back(std::move(program));
        } else {
            const size_t before = m_pos;
            unexpected(QCoreApplication::translate("iec::interp::Compiler", "TASK, PROGRAM or %1").arg(QString::fromLatin1(end.data(), qsizetype(end.size()))));
            synchronize(false);
            skipIfStuck(before);
        }
    }
}

VarSection Parser::varSection()
{
    VarSection section;
    section.location = here();
    struct Kind {
        std::string_view word;
        VarKind kind;
    };
    static constexpr Kind kinds[] = {
        {"VAR", VarKind::Local},          {"VAR_INPUT", VarKind::Input},   {"VAR_OUTPUT", VarKind::Output},
        {"VAR_IN_OUT", VarKind::InOut},   {"VAR_EXTERNAL", VarKind::External}, {"VAR_GLOBAL", VarKind::Global},
        {"VAR_TEMP", VarKind::Temp},      {"VAR_ACCESS", VarKind::Access}, {"VAR_CONFIG", VarKind::Config},
    };
    for (const Kind &k : kinds) {
        if (isWord(k.word))
            section.kind = k.kind;
    }
    ++m_pos;
    for (;;) {
        if (acceptWord("CONSTANT"))
            section.constant = true;
        else if (acceptWord("RETAIN"))
            section.retain = true;
        else if (acceptWord("NON_RETAIN"))
            section.nonRetain = true;
        else if (!acceptWord("PERSISTENT"))
            break;
    }
    varDeclarations(section.vars, "END_VAR");
    if (!acceptWord("END_VAR"))
        error(section.location, QCoreApplication::translate("iec::interp::Compiler", "This variable section has no END_VAR."),
              QCoreApplication::translate("iec::interp::Compiler", "add END_VAR after its last declaration"));
    m_recovering = false;
    return section;
}

void Parser::varDeclarations(std::vector<VarDecl> &out, std::string_view end)
{
    while (!atEnd() && !isWord(end) && !isBlockWord() && !isStatementKeyword()) {
        // "a := 1;" is a statement: the section above lacks its END_VAR, which the caller reports.
        if (isName() && (isOp(u":=", 1) || isOp(u"(", 1) || isOp(u".", 1) || isOp(u"[", 1)))
            break;
        std::vector<VarDecl> names;
        do {
            if (!isName()) {
                unexpected(QCoreApplication::translate("iec::interp::Compiler", "a variable name"));
                break;
            }
            VarDecl decl;
            decl.location = here();
            decl.name = takeName();
            names.push_back(std::move(decl));
        } while (acceptOp(u","));
        QString address;
        if (acceptWord("AT")) {
            if (!atEnd() && tok().kind == TokenKind::DirectAddress)
                address = takeName();
            else
                unexpected(QCoreApplication::translate("iec::interp::Compiler", "an address such as %IX0.0 after AT"));
        }
        if (names.empty() || !expectOp(u":", QCoreApplication::translate("iec::interp::Compiler", "':' and a type"))) {
            synchronize(false);
            continue;
        }
        TypeSpec type = typeSpec();
        Initializer init;
        if (acceptOp(u":="))
            init = declarationInitializer();
        else if (isOp(u"="))
            error(here(), QCoreApplication::translate("iec::interp::Compiler", "An initial value is given with ':=', not '='."),
                  QCoreApplication::translate("iec::interp::Compiler", "write %1 : ... := value;").arg(names.front().name));
        if (!acceptOp(u";")) {
            error(afterPrevious(), QCoreApplication::translate("iec::interp::Compiler", "Missing ';' after the declaration of %1.").arg(names.front().name));
            synchronize(false);
        }
        m_recovering = false;
        for (VarDecl &decl : names) {
            decl.address = address;
            decl.type = type;
            decl.init = init;
            out.push_back(std::move(decl));
        }
    }
}

TypeSpec Parser::typeSpec()
{
    TypeSpec spec;
    spec.location = here();
    std::optional<Nested> level;
    if (isWord("ARRAY") || isWord("STRUCT")) {
        level.emplace(m_typeDepth);
        if (typeTooDeep()) {
            refuseDeepType();
            return spec;
        }
    }
    if (acceptWord("ARRAY")) {
        spec.kind = TypeSpec::Kind::Array;
        if (expectOp(u"[", QCoreApplication::translate("iec::interp::Compiler", "'[' and the index range, e.g. ARRAY[1..10]"))) {
            do {
                Range range;
                range.low = expression();
                if (expectOp(u"..", QCoreApplication::translate("iec::interp::Compiler", "'..' between the bounds")))
                    range.high = expression();
                spec.ranges.push_back(std::move(range));
            } while (acceptOp(u","));
            expectOp(u"]", QStringLiteral("']'"));
        }
        expectWord("OF");
        spec.element.push_back(typeSpec());
        return spec;
    }
    if (acceptWord("STRUCT")) {
        spec.kind = TypeSpec::Kind::Struct;
        varDeclarations(spec.members, "END_STRUCT");
        if (!acceptWord("END_STRUCT"))
            error(spec.location, QCoreApplication::translate("iec::interp::Compiler", "This STRUCT has no END_STRUCT."));
        return spec;
    }
    if (acceptOp(u"(")) {
        spec.kind = TypeSpec::Kind::Enum;
        do {
            spec.enumValues << expectName(QCoreApplication::translate("iec::interp::Compiler", "an enumeration value"));
            std::optional<Expr> value;
            if (acceptOp(u":="))
                value = expression();
            spec.enumExplicit.push_back(std::move(value));
        } while (acceptOp(u","));
        expectOp(u")", QCoreApplication::translate("iec::interp::Compiler", "')' after the enumeration values"));
        if (!atEnd() && (tok().kind == TokenKind::TypeName))
            spec.name = takeName(); // CODESYS: (a, b) INT
        return spec;
    }
    // CODESYS POINTER TO T and REFERENCE TO T, IEC 61131-3 ed.3 REF_TO T.
    if ((isWord("POINTER") || isWord("REFERENCE")) && isWord("TO", 1)) {
        spec.kind = isWord("POINTER") ? TypeSpec::Kind::Pointer : TypeSpec::Kind::Reference;
        m_pos += 2;
        spec.element.push_back(typeSpec());
        return spec;
    }
    if (isWord("REF_TO")) {
        spec.kind = TypeSpec::Kind::Pointer;
        ++m_pos;
        spec.element.push_back(typeSpec());
        return spec;
    }
    if (isWord("STRING") || isWord("WSTRING")) {
        spec.kind = TypeSpec::Kind::String;
        spec.wide = isWord("WSTRING");
        ++m_pos;
        const bool square = acceptOp(u"[");
        if (square || acceptOp(u"(")) {
            spec.length = expression();
            expectOp(square ? u"]" : u")", QCoreApplication::translate("iec::interp::Compiler", "the closing bracket of the string length"));
        }
        return spec;
    }
    if (atEnd() || !(tok().kind == TokenKind::TypeName || isName())) {
        unexpected(QCoreApplication::translate("iec::interp::Compiler", "a type"));
        return spec;
    }
    spec.name = takeName();
    if (acceptOp(u"(")) { // subrange INT (0..100)
        spec.kind = TypeSpec::Kind::Subrange;
        Range range;
        range.low = expression();
        expectOp(u"..", QCoreApplication::translate("iec::interp::Compiler", "'..' between the bounds"));
        range.high = expression();
        spec.ranges.push_back(std::move(range));
        expectOp(u")", QStringLiteral("')'"));
    }
    return spec;
}

// One value of an array's initial values, or n(value) repeated n times.
void Parser::arrayItem(Initializer &init)
{
    std::optional<Expr> repeat;
    if (!atEnd() && tok().kind == TokenKind::IntegerLiteral && isOp(u"(", 1)) {
        repeat = expression(9); // just the literal
        ++m_pos;                // (
        Initializer item;
        if (!isOp(u")"))
            item = initializer();
        expectOp(u")", QCoreApplication::translate("iec::interp::Compiler", "')' after the repeated value"));
        init.items.push_back(std::move(item));
    } else {
        init.items.push_back(initializer());
    }
    init.repeats.push_back(std::move(repeat));
}

// The initial value of a declaration. CoDeSys 2.3 writes an array's values without brackets
// (FACTS : ARRAY[0..12] OF DINT := 1, 1, 2, 6, ...; or := 10(0), 5;), which is read as [...].
Initializer Parser::declarationInitializer()
{
    // An array of structures: := (x := 1, y := 2), (x := 3, y := 4);
    const bool bare = !isOp(u"[")
        && ((!atEnd() && tok().kind == TokenKind::IntegerLiteral && isOp(u"(", 1)) || continuesWithComma());
    if (!bare)
        return initializer();
    Initializer list;
    list.location = here();
    list.kind = Initializer::Kind::Array;
    do
        arrayItem(list);
    while (acceptOp(u","));
    return list;
}

// Whether the value that starts here is followed by a ',' at the same depth before the ';' that
// ends the declaration.
bool Parser::continuesWithComma() const
{
    int depth = 0;
    for (size_t ahead = 0; !atEnd(ahead); ++ahead) {
        if (isOp(u"(", ahead) || isOp(u"[", ahead))
            ++depth;
        else if (isOp(u")", ahead) || isOp(u"]", ahead))
            --depth;
        else if (depth == 0 && isOp(u",", ahead))
            return true;
        else if (depth < 0 || isOp(u";", ahead) || (depth == 0 && isOp(u":=", ahead))
                 || (tok(ahead).kind == TokenKind::Keyword && text(ahead).startsWith(u"END_", Qt::CaseInsensitive)))
            return false;
    }
    return false;
}

Initializer Parser::initializer()
{
    Initializer init;
    init.location = here();
    std::optional<Nested> level;
    if (isOp(u"[") || (isOp(u"(") && isName(1) && isOp(u":=", 2))) {
        level.emplace(m_typeDepth);
        if (typeTooDeep()) {
            refuseDeepInitializer();
            return init;
        }
    }
    if (acceptOp(u"[")) {
        init.kind = Initializer::Kind::Array;
        if (acceptOp(u"]"))
            return init;
        do
            arrayItem(init);
        while (acceptOp(u","));
        expectOp(u"]", QCoreApplication::translate("iec::interp::Compiler", "']' at the end of the array's initial values"));
        return init;
    }
    if (isOp(u"(") && isName(1) && isOp(u":=", 2)) {
        ++m_pos;
        init.kind = Initializer::Kind::Struct;
        do {
            init.memberNames << expectName(QCoreApplication::translate("iec::interp::Compiler", "a member name"));
            expectOp(u":=", QStringLiteral("':='"));
            init.items.push_back(initializer());
        } while (acceptOp(u","));
        expectOp(u")", QCoreApplication::translate("iec::interp::Compiler", "')' at the end of the structure's initial values"));
        return init;
    }
    init.kind = Initializer::Kind::Expression;
    init.value = expression();
    return init;
}

Body Parser::body(std::initializer_list<std::string_view> ends)
{
    Body b;
    if (isEnd(ends))
        return b;
    if (looksLikeSfc()) {
        b.language = Language::SFC;
        b.sfc = std::make_shared<SfcChart>();
        sfc(*b.sfc, ends);
    } else if (looksLikeIl()) {
        b.language = Language::IL;
        b.il = ilInstructions(ends);
    } else {
        b.language = Language::ST;
        b.statements = statements();
        // A misspelled END_PROGRAM that ends the text or comes before the next POU: the POU reports it.
        const auto pouStartsAt = [&](size_t ahead) {
            static constexpr std::string_view starts[] = {"PROGRAM", "FUNCTION", "FUNCTION_BLOCK", "TYPE", "CONFIGURATION", "ACTION"};
            return atEnd(ahead) || std::any_of(std::begin(starts), std::end(starts), [&](std::string_view w) { return equalsUpper(text(ahead), w); });
        };
        if (!isEnd(ends) && !atEnd() && !(isMisspelledEnd() && pouStartsAt(1)) && !startsMember()) {
            unexpected(QCoreApplication::translate("iec::interp::Compiler", "a statement"));
            while (!isEnd(ends) && !isPouStart())
                ++m_pos;
            m_recovering = false;
        }
    }
    return b;
}

bool Parser::looksLikeSfc() const
{
    return (isWord("INITIAL_STEP") || isWord("STEP") || isWord("TRANSITION")) && startsSfcElement();
}

bool Parser::looksLikeIl() const
{
    if (atEnd())
        return false;
    // A label "Start:" is IL unless an ST statement follows it (CODESYS has labels in ST too).
    if (isName() && isOp(u":", 1)) {
        const bool stFollows = (isName(2) && (isOp(u":=", 3) || isOp(u"(", 3) || isOp(u".", 3) || isOp(u"[", 3) || isOp(u"^", 3)))
            || isWord("IF", 2) || isWord("FOR", 2) || isWord("WHILE", 2) || isWord("CASE", 2) || isWord("REPEAT", 2);
        return !stFollows;
    }
    if (tok().kind != TokenKind::Keyword || !isIlOperator(text()))
        return false;
    // "R := TRUE;", "ADD(...)" and "R REF= x;" are ST; "LD x" is IL.
    return !(isOp(u":=", 1) || isOp(u"(", 1) || isOp(u".", 1) || isOp(u"[", 1) || isOp(u"=>", 1) || isOp(u"^", 1)
             || (isWord("REF", 1) && isOp(u"=", 2)));
}

} // namespace parsing


using namespace ast;
using parsing::Parser;

int binaryPrecedence(QStringView op)
{
    for (const parsing::BinaryOperator &o : parsing::kBinaryOperators) {
        if (op == QLatin1String(o.canonical))
            return o.precedence;
    }
    return 0;
}

// The entry points parse on the compiler's stack (compilerstack.h): the nesting limits above are
// safe there whatever thread asks (an editor's check while typing, the GUI thread).
namespace {

template<class Result, class Read>
Result onCompilerStack(Read read)
{
    Result result;
    runOnCompilerStack([&] { result = read(); });
    return result;
}

} // namespace

CompilationUnit parseUnit(QStringView text, Diagnostics &diagnostics)
{
    return onCompilerStack<CompilationUnit>([&] { return Parser(text, diagnostics, QString(), 1).unit(); });
}

std::vector<Stmt> parseStBody(QStringView text, const QString &pou, Diagnostics &diagnostics, int firstLine)
{
    return onCompilerStack<std::vector<Stmt>>([&] { return Parser(text, diagnostics, pou, firstLine).stBody(); });
}

std::vector<IlInstruction> parseIlBody(QStringView text, const QString &pou, Diagnostics &diagnostics, int firstLine)
{
    return onCompilerStack<std::vector<IlInstruction>>([&] { return Parser(text, diagnostics, pou, firstLine).ilBody(); });
}

std::vector<VarSection> parseDeclarations(QStringView text, const QString &pou, Diagnostics &diagnostics,
                                          int firstLine)
{
    return onCompilerStack<std::vector<VarSection>>([&] { return Parser(text, diagnostics, pou, firstLine).declarations(); });
}

} // namespace iec::interp
