#pragma once

#include "interpreter/compiler/diagnostics.h"
#include "interpreter/compiler/lexer.h"

#include <QString>
#include <QStringList>

#include <memory>
#include <optional>
#include <vector>

// The compiler's input: compilation units of POUs, types and configurations. It holds no
// pointers into any source text, so it can be built from a parsed .st file or, later, from the
// project model (whose ST/IL bodies are parsed with parseStBody / parseIlBody and whose graphical
// bodies are lowered to the same statements).
namespace iec::interp::ast {

// ---- expressions ---------------------------------------------------------------------------

enum class ExprKind {
    Literal,       // text = literal as written, literal = its token kind
    Name,          // text = identifier
    DirectAddress, // text = %IX0.1
    Member,        // operands[0].text
    BitAccess,     // operands[0].<bit> with bit = the integer in text
    Index,         // operands[0][operands[1..]]
    Unary,         // text = "-", "NOT", "+"
    Binary,        // text = operator: "**" "*" "/" "MOD" "+" "-" "<" ... "=" "<>" "AND" "XOR" "OR"
    Call,          // text = function name; callArgs
    Deref,         // operands[0]^ (a pointer or REF_TO dereferenced)
    Error,         // a place where parsing failed; already diagnosed
};

struct CallArg;

struct Expr {
    ExprKind kind = ExprKind::Error;
    SourceLocation location;
    QString text;
    TokenKind literal = TokenKind::Error;
    std::vector<Expr> operands;
    std::vector<CallArg> callArgs;

    // A sum of 100,000 terms is a tree 100,000 levels deep (operators are left-associative):
    // copying and destroying work through a list instead of recursing once per level (ast.cpp).
    Expr() = default;
    Expr(const Expr &other);
    Expr(Expr &&other) noexcept = default;
    Expr &operator=(const Expr &other);
    Expr &operator=(Expr &&other) noexcept = default;
    ~Expr();
};

// One argument of a call: positional (name empty), `name := value` or `name => variable`.
struct CallArg {
    QString name;
    bool isOutput = false;
    bool negatedOutput = false; // NOT Q => x
    Expr value;
};

// ---- types and initial values ----------------------------------------------------------------

struct VarDecl;
struct TypeSpec;

struct Range {
    Expr low;
    Expr high;
};

struct TypeSpec {
    enum class Kind { Named, String, Array, Subrange, Enum, Struct, Pointer, Reference };
    Kind kind = Kind::Named;
    SourceLocation location;
    QString name;                       // Named: INT, TON, MyType; Subrange/Enum: base type (may be empty)
    bool wide = false;                  // String: WSTRING
    std::optional<Expr> length;         // String: [n]
    std::vector<Range> ranges;          // Array dimensions; Subrange: one
    std::vector<TypeSpec> element;      // Array: the element type (one); Pointer, Reference: the type pointed to
    QStringList enumValues;             // Enum
    std::vector<std::optional<Expr>> enumExplicit; // Enum: := value per item
    std::vector<VarDecl> members;       // Struct
};

struct Initializer {
    enum class Kind { None, Expression, Array, Struct };
    Kind kind = Kind::None;
    SourceLocation location;
    std::optional<Expr> value;              // Expression
    std::vector<Initializer> items;         // Array items / Struct member values
    std::vector<std::optional<Expr>> repeats; // Array: 3(0) has repeat 3; parallel to items
    QStringList memberNames;                // Struct: parallel to items
};

// ---- declarations ----------------------------------------------------------------------------

enum class VarKind { Local, Input, Output, InOut, External, Global, Temp, Access, Config };

struct VarDecl {
    QString name;
    SourceLocation location;
    QString address; // AT %IX0.0; empty when none
    TypeSpec type;
    Initializer init;
};

struct VarSection {
    VarKind kind = VarKind::Local;
    // A named global variable list (a CODESYS GVL such as IO): its variables may also be written
    // List.Variable. Empty for plain VAR_GLOBAL blocks.
    QString listName;
    bool constant = false;
    bool retain = false;
    bool nonRetain = false;
    SourceLocation location;
    std::vector<VarDecl> vars;
};

struct TypeDecl {
    QString name;
    SourceLocation location;
    TypeSpec type;
    Initializer init;
};

// ---- statements ------------------------------------------------------------------------------

// Jump and Label: JMP name; and name: in ST (CODESYS), target.text is the label.
// RefAssign: target REF= value (CODESYS REFERENCE TO).
enum class StmtKind { Assign, Call, If, Case, For, While, Repeat, Exit, Continue, Return, Empty, Jump, Label, RefAssign };

struct Stmt;

struct ConditionalBlock {
    Expr condition;
    SourceLocation location;
    std::vector<Stmt> body;
};

struct CaseLabel {
    Expr low;
    std::optional<Expr> high; // 10..20
};

struct CaseBranch {
    std::vector<CaseLabel> labels;
    std::vector<Stmt> body;
};

struct Stmt {
    StmtKind kind = StmtKind::Empty;
    SourceLocation location;
    Expr target;                           // Assign: left side; For: control variable; Case: selector; Call: the call
    Expr value;                            // Assign: right side; For: start; While/Repeat: condition
    std::optional<Expr> to, by;            // For
    std::vector<ConditionalBlock> branches; // If: IF and ELSIF
    std::vector<CaseBranch> cases;         // Case
    std::vector<Stmt> body;                // For/While/Repeat body; If/Case ELSE part
    bool hasElse = false;
};

// ---- instruction list ------------------------------------------------------------------------

struct IlInstruction {
    SourceLocation location;
    QString label;            // "Next1" for "Next1:"; may stand alone with an empty op
    QString op;               // upper case: LD, ANDN, JMPC, CAL, ")", or a function / FB input name
    bool openParen = false;   // MUL (6  -> deferred operation
    std::optional<Expr> operand;
    std::vector<CallArg> callArgs; // CAL T1(PT := T#1s); function calls with several operands
};

// ---- sequential function chart (textual form) -------------------------------------------------

struct SfcActionAssociation {
    SourceLocation location;
    QString action;
    QString qualifier;      // N, R, S, L, D, P, P0, P1, SD, DS, SL; empty means N
    std::optional<Expr> duration;
    QString indicator;
};

struct SfcStep {
    SourceLocation location;
    QString name;
    bool initial = false;
    std::vector<SfcActionAssociation> actions;
};

struct Body;

struct SfcTransition {
    SourceLocation location;
    QString name;              // may be empty
    std::optional<Expr> priority;
    QStringList from;
    QStringList to;
    std::optional<Expr> condition;      // := expression;
    std::vector<IlInstruction> ilCondition; // or an IL body
};

struct SfcAction;

struct SfcChart {
    std::vector<SfcStep> steps;
    std::vector<SfcTransition> transitions;
    std::vector<SfcAction> actions;
};

// ---- POUs and units --------------------------------------------------------------------------

enum class Language { None, ST, IL, SFC };

struct Body {
    Language language = Language::None;
    std::vector<Stmt> statements;     // ST
    std::vector<IlInstruction> il;    // IL
    std::shared_ptr<SfcChart> sfc;    // SFC (shared_ptr breaks the Body <-> SfcAction cycle)
};

struct SfcAction {
    SourceLocation location;
    QString name;
    Body body;
};

// Interface: an INTERFACE (edition 3, CODESYS): methods and properties without bodies.
enum class PouKind { Program, FunctionBlock, Function, Interface };

enum class Access { Public, Private, Protected, Internal };

// A METHOD of a function block or interface; a PROPERTY is a getter (a method named like the
// property returning its value) and a setter (a method whose VAR_INPUT is named like the property).
struct Method {
    enum class Role { Method, Getter, Setter };
    Role role = Role::Method;
    QString name;                 // the method, or the property
    SourceLocation location;
    Access access = Access::Public;
    bool isAbstract = false;
    bool isFinal = false;
    bool hasBody = true;          // false: a prototype (interfaces, ABSTRACT)
    std::optional<TypeSpec> returnType;
    std::vector<VarSection> sections;
    Body body;
};

// What messages, faults and the debugger call a method's code: "Counter.Add", and for a
// property's accessors "Counter.Count.GET" and "Counter.Count.SET", so that a message in a
// property with both says which of its bodies it is in.
inline QString methodCodeName(const QString &owner, const QString &name, Method::Role role)
{
    const QString member = owner + QLatin1Char('.') + name;
    switch (role) {
    case Method::Role::Getter: return member + QLatin1String(".GET");
    case Method::Role::Setter: return member + QLatin1String(".SET");
    case Method::Role::Method: break;
    }
    return member;
}

struct Pou {
    PouKind kind = PouKind::Program;
    QString name;
    SourceLocation location;
    std::optional<TypeSpec> returnType; // functions
    std::vector<VarSection> sections;
    Body body;
    std::vector<SfcAction> actions;     // ACTION ... END_ACTION inside the POU (CODESYS style)
    // Object orientation (IEC 61131-3 ed.3 as CODESYS writes it).
    bool isAbstract = false;
    bool isFinal = false;
    QString extends;                    // EXTENDS Base (function blocks)
    QStringList implements;             // IMPLEMENTS I1, I2 (function blocks); EXTENDS of an interface
    std::vector<Method> methods;        // methods and property accessors
};

struct TaskDecl {
    QString name;
    SourceLocation location;
    std::optional<Expr> single;
    std::optional<Expr> interval;
    std::optional<Expr> priority;
};

struct ProgramConfig {
    QString instance;
    SourceLocation location;
    bool retain = false;
    QString task; // empty: no WITH
    QString type;
    std::vector<CallArg> args;
};

struct ResourceDecl {
    QString name;
    QString on;
    SourceLocation location;
    std::vector<VarSection> globals;
    std::vector<TaskDecl> tasks;
    std::vector<ProgramConfig> programs;
};

struct ConfigurationDecl {
    QString name;
    SourceLocation location;
    std::vector<VarSection> globals;
    std::vector<ResourceDecl> resources;
};

struct CompilationUnit {
    std::vector<TypeDecl> types;
    std::vector<Pou> pous;
    std::vector<VarSection> globals; // VAR_GLOBAL outside a configuration (CODESYS global lists)
    std::vector<ConfigurationDecl> configurations;
};

} // namespace iec::interp::ast
