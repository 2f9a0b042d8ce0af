#pragma once

// Internal to the compiler: the state shared by the files that turn the AST into bytecode
// (compiler.cpp, declarations.cpp, expressions.cpp, conversions.cpp, calls.cpp, stdfunctions.cpp,
// statements.cpp, il.cpp; typeutil.h holds the small shared type predicates).

#include "interpreter/compiler/ast.h"
#include "interpreter/compiler/compiler.h"
#include "interpreter/compiler/diagnostics.h"
#include "interpreter/compiler/types.h"
#include "interpreter/vm/bytecode.h"

#include <QHash>
#include <QSet>
#include <QString>

#include <deque>
#include <functional>
#include <map>
#include <tuple>
#include <optional>
#include <vector>

namespace iec::interp::detail {

// Set on operands of temporaries while a POU is compiled; they are moved to the POU's temporary
// area once its size is known (see Codegen::finishTemporaries).
constexpr std::uint32_t kTempMarker = 0x40000000u;

// A value known at compile time: literals, CONSTANT variables, enumeration values.
struct ConstValue {
    enum class Kind { None, Int, Real, String };
    Kind kind = Kind::None;
    std::int64_t i = 0;       // Int (BOOL, integers, bit strings, times and dates as ns)
    bool bigUnsigned = false; // Int: i holds a ULINT/LWORD above INT64_MAX as its bit pattern
    double r = 0;             // Real
    QString s;                // String
    bool wide = false;
};

// The result of compiling an expression.
struct Value {
    enum class Kind { Invalid, Operand, Constant };
    Kind kind = Kind::Invalid;
    const Type *type = nullptr;
    // An integer or real literal without a type prefix: it takes the type its use needs (type is
    // then LINT or LREAL, standing for ANY_INT / ANY_REAL).
    bool untyped = false;
    // An untyped constant standing for a bit pattern (NOT 16#0159, SHL(507, 9)): in a narrower
    // type it is cut to that type's width instead of refused.
    bool bitPattern = false;
    // An untyped Operand: computed from literals alone (SEL(b, 0, 8) with b known only at run
    // time), held as LINT or LREAL and converted to the type its use needs. When every literal it
    // may be is known, their smallest and largest value.
    std::optional<std::pair<std::int64_t, std::int64_t>> literalRange;
    // A function block instance reached through an address (an array element, p^): operand holds
    // that address; the instance is not copied (an interface is made from it).
    bool instanceAddress = false;
    std::uint32_t operand = 0;
    ConstValue constant;

    bool valid() const { return kind != Kind::Invalid && type; }
};

// Something that can be read and perhaps written: a variable, an element, a member, a bit.
struct Place {
    enum class Kind { Invalid, Direct, Indirect, Bit, IndirectBit, Constant };
    Kind kind = Kind::Invalid;
    const Type *type = nullptr;
    std::uint32_t operand = 0; // Direct/Bit: the address; Indirect: where the address is stored
    int bit = 0;
    bool readOnly = false;
    QString readOnlyReason;
    QString text;              // as the user wrote it, for messages
    ConstValue constant;       // Constant
    int fbPou = -1;            // a function block instance: its POU
};

struct PouInfo {
    const ast::Pou *ast = nullptr;
    int index = -1;
    QString name;
    ast::PouKind kind = ast::PouKind::Program;
    Type *frame = nullptr;          // instance layout (program, FB) or the function's variables
    const Type *result = nullptr;   // function result type
    std::uint32_t frameBase = 0;    // function: absolute address of its variables
    std::uint32_t reinitFrom = 0;   // members from here on are reinitialised on every call
    std::uint32_t templateOffset = 0; // absolute address of the frame with all initial values
    std::vector<const Member *> parameters; // inputs and in-outs, in positional order
    bool layoutInProgress = false;
    bool laidOut = false;
    bool fromLibrary = false;
    // A PROGRAM called or read from other POUs (PRG1(); PRG1.Out, CODESYS): its one instance in
    // the image (0 when it has several instances, which makes the name ambiguous).
    std::uint32_t programBase = 0;
    int programInstances = 0;
    // Object orientation (oop.cpp): a method or property accessor is a Function owned by a
    // function block (methodOf); a block's methods by "NAME", "GET:NAME", "SET:NAME".
    int methodOf = -1;
    const ast::Method *method = nullptr;
    bool hasClassId = false; // the instance starts with __CLASS (inheritance, interfaces)
    QHash<QString, int> methods;
};

// A %-address of the process image: %QX4.1 is area Q, byte 4, bit 1; %QW2 is bytes 4 and 5.
struct ImageAddress {
    char area = 'I';
    std::uint32_t byte = 0;
    int bit = -1;           // -1: not a bit address
    std::uint32_t size = 1; // bytes (1 for a bit)
};
std::optional<ImageAddress> parseImageAddress(const QString &address);

struct GlobalVar {
    const Type *type = nullptr;
    std::uint32_t offset = 0;
    bool constant = false;
    std::optional<ConstValue> value; // CONSTANT with a constant initial value
    QString name;
    std::optional<ImageAddress> located; // AT %QW2 (or %QW2 in code): lives in the process image
};

struct EnumValue {
    const Type *type = nullptr;
    std::int64_t value = 0;
    bool ambiguous = false;
};

class Codegen
{
public:
    Codegen(Diagnostics &diagnostics, const CompileOptions &options);
    std::shared_ptr<Module> run(const std::vector<const ast::CompilationUnit *> &units);

    // ---- declarations.cpp ----
    void collectTypes(const ast::CompilationUnit &unit, bool library);
    void collectPous(const ast::CompilationUnit &unit, bool library);
    const Type *resolveType(const ast::TypeSpec &spec, const QString &name = {});
    const Type *namedType(const QString &name, SourceLocation at, bool report = true);
    bool layoutPou(PouInfo &pou);
    void declareGlobals(const std::vector<ast::VarSection> &sections);
    std::uint32_t allocate(std::uint32_t size, std::uint32_t align);
    void writeInitial(std::uint32_t offset, const Type *type, const ast::Initializer *init, const QString &name = {});
    bool writeConstant(std::uint32_t offset, const Type *type, const ConstValue &value, SourceLocation at);
    std::optional<Value> evalConst(const ast::Expr &expr, bool report = true);
    // evalConst for the initial value of a CONSTANT read by name: evaluated once per POU, so a
    // chain of constants defined by constants costs its length, not its square, and a constant
    // defined by itself is reported instead of followed for ever. `reported`: no value because
    // of a message already given (the use says nothing more).
    std::optional<Value> evalConstOnce(const ast::Expr &expr, bool report, bool &reported);
    std::optional<std::int64_t> evalConstInt(const ast::Expr &expr);
    std::optional<ConstValue> literalValue(const ast::Expr &expr, const Type **type, bool *untyped);
    void locate(const QString &address, std::uint32_t offset, const Type *type, SourceLocation at);
    // ---- vendorlibraries.cpp ----
    void missingVendorLibrary(const QString &block, const QString &library, SourceLocation at);
    void checkVendorLibrariesReachable();
    QHash<int, QString> m_needsVendorLibrary; // POU index -> the library it needs
    QSet<QString> m_reportedLibraries;
    // ---- processimage.cpp ----
    void reserveProcessImage(const std::vector<const ast::CompilationUnit *> &units);
    Place imagePlace(const ImageAddress &address, const Type *type, const QString &text);
    void initialiseImage(const ImageAddress &address, std::uint32_t slot, const Type *type);
    const GlobalVar *directAddressVar(const QString &address, SourceLocation at);

    // ---- expressions.cpp ----
    Value compileExpr(const ast::Expr &expr, const Place *destination = nullptr);
    // A REFERENCE TO variable stands for what it refers to unless derefReferences is false
    // (REF=, __ISVALIDREF).
    Place resolvePlace(const ast::Expr &expr, bool reportUnknown = true, bool derefReferences = true);
    Place resolvePlaceRaw(const ast::Expr &expr, bool reportUnknown);
    // mayFuse: an element's address computed just before may be folded into the load (then the
    // place's address operand is never written; false when it is needed again).
    Value read(const Place &place, bool mayFuse = true);
    std::optional<std::uint16_t> fusedIndexOp(const Place &place, bool load) const;
    void store(const Place &place, Value value, SourceLocation at);
    // A value assigned to a subrange type: a constant is checked now, anything else at run time.
    bool checkSubrange(const Value &value, const Type *type, SourceLocation at);
    Value coerce(Value value, const Type *to, SourceLocation at, const QString &context = {});
    bool warnImplicit(const Type *from, const Type *to, SourceLocation at);
    Value coerceUntypedOperand(Value value, const Type *to, SourceLocation at, const std::function<Value()> &mismatch);
    Value convertExplicit(Value value, const Type *to, SourceLocation at, bool truncate = false);
    std::uint32_t materialize(const Value &value);
    std::uint32_t constantOperand(const Type *type, const ConstValue &value);
    std::uint32_t temp(const Type *type);
    void emitMove(std::uint32_t to, std::uint32_t from, const Type *type);
    Value binary(const QString &op, Value left, Value right, SourceLocation at, const Place *destination = nullptr);
    Value binaryTyped(const QString &op, Value left, Value right, SourceLocation at, const Place *destination);
    Value unary(const QString &op, Value operand, SourceLocation at, const Place *destination = nullptr);
    Value shortCircuit(const ast::Expr &expr);
    const Type *commonType(const Type *a, const Type *b) const;
    const Type *integerCommonType(const Type *a, const Type *b) const;
    Value operandValue(std::uint32_t operand, const Type *type) const;
    Value constantValue(const Type *type, const ConstValue &value, bool untyped = false) const;
    const Type *boolType() const { return m_types->elementary(Elem::Bool); }
    const Type *elem(Elem e) const { return m_types->elementary(e); }
    Place memberPlace(const Place &base, const Member &member, const QString &text);

    // ---- calls.cpp ----
    // One argument of a call: from the source (expr) or already computed (value, e.g. the IL
    // accumulator that is a function's first argument).
    struct Argument {
        QString name;
        bool isOutput = false;
        bool negated = false;
        const ast::Expr *expr = nullptr;
        std::optional<Value> value;
        SourceLocation location;
    };
    static std::vector<Argument> arguments(const std::vector<ast::CallArg> &args);
    Value compileCall(const ast::Expr &call, bool asStatement, const Place *destination = nullptr);
    Value callNamed(const QString &name, const Place *callee, std::vector<Argument> args, SourceLocation at,
                    bool asStatement, const Place *destination);
    void callFunctionBlock(const Place &instance, const std::vector<Argument> &args, SourceLocation at);
    Place programPlace(const PouInfo &pou, const QString &name, SourceLocation at);
    // A method is called on `instance` (CallFb); a plain function has none.
    Value callUserFunction(PouInfo &fn, const std::vector<Argument> &args, SourceLocation at, const Place *destination,
                           const Place *instance = nullptr);
    void noteCall(int callee, SourceLocation at);
    // VAR_IN_OUT passes the variable itself, so its type must be the parameter's (a subrange and
    // its base type count as one; their values are checked where they cross). Invalid after a
    // message. inOutAddress: the operand holding the variable's address for the parameter slot.
    Place inOutVariable(const Member &parameter, const Argument &a, const QString &callee);
    std::uint32_t inOutAddress(const Place &variable);
    bool sameInOutType(const Type *parameter, const Type *variable) const;
    bool sameStoredType(const Type *parameter, const Type *variable) const; // same type and same subrange
    // A variable passed to VAR_IN_OUT whose type allows values the other side does not: its value
    // is checked before the call (for the parameter's subrange) and after it (for its own).
    struct InOutCheck {
        Place variable;
        SourceLocation location;
    };
    void checkInOutBefore(const Member &parameter, const Place &variable, SourceLocation at, std::vector<InOutCheck> &after);
    void checkInOutAfter(const std::vector<InOutCheck> &after);
    // CODESYS actions: `Act();` inside the POU, `Inst.Act();` on an instance (ST, and CAL in IL).
    // False when `callee` names no action; then it is an ordinary call.
    bool callAction(const ast::Expr &callee, const std::vector<ast::CallArg> &args, SourceLocation at, bool asStatement);
    std::optional<NativeBlock> nativeBlock(const Type *fbType) const;

    // ---- pointers.cpp ----
    std::uint32_t offsetAddress(std::uint32_t address, std::int64_t bytes);
    Place checkedTarget(std::uint32_t address, const Type *type, const QString &text);
    Place dereferenced(const Place &slot);
    Place pointee(const ast::Expr &expr, bool reportUnknown);
    Value addressOf(const ast::Expr &expr, const QString &function);
    std::optional<Value> pointerFunction(const QString &name, const std::vector<ast::CallArg> &args, SourceLocation at);
    void referenceAssignment(const ast::Stmt &s);
    std::optional<Value> pointerArithmetic(const QString &op, Value left, Value right, SourceLocation at);
    std::optional<Value> coercePointer(Value v, const Type *to, SourceLocation at);

    // ---- oop.cpp ----
    void registerMethods();
    void checkImplementations();
    void checkOverrides();
    int baseOf(int pou) const;
    int findMethod(int pou, const QString &name, ast::Method::Role role) const;
    int findInterfaceMethod(int pou, const QString &name, ast::Method::Role role, int depth = 0) const;
    bool isA(int pou, int of) const;
    int currentClass() const;
    bool mayCall(const PouInfo &method, SourceLocation at);
    Place selfPointer(bool super, SourceLocation at);
    Value dynamicCall(int cls, const QString &name, ast::Method::Role role, std::uint32_t address, const std::vector<Argument> &args,
                      SourceLocation at, const Place *destination, bool statement);
    std::optional<Value> methodCall(const ast::Expr &callee, const std::vector<ast::CallArg> &args, SourceLocation at, bool asStatement,
                                    const Place *destination);
    std::optional<Value> propertyRead(const ast::Expr &expr);
    bool propertyWrite(const ast::Expr &target, const ast::Expr &value, SourceLocation at);
    std::optional<Value> propertyAccess(const ast::Expr &expr, const Argument *assigned);
    Place probeType(const ast::Expr &expr);
    std::optional<Value> interfaceOf(const Value &v, const Type *to, SourceLocation at);
    std::deque<ast::Pou> m_methodAsts; // methods as functions (PouInfo::ast points here)
    bool m_superCall = false;          // the place just resolved was reached through SUPER

    // ---- stdfunctions.cpp ----
    // Standard functions and conversions; nullopt when `name` is none of them.
    std::optional<Value> standardFunction(const QString &name, std::vector<Value> args,
                                          const std::vector<QString> &argNames, SourceLocation at,
                                          const Place *destination);

    // ---- statements.cpp ----
    void compileStatements(const std::vector<ast::Stmt> &list);
    void compileStatement(const ast::Stmt &stmt);
    Value condition(const ast::Expr &expr);
    // A FOR loop whose counter cannot pass a constant end value (wraparound or subrange).
    void warnForLoopEnd(const ast::Stmt &s, const Place &counter, const Value &start, const ConstValue &end, const ConstValue &step, bool up);

    QHash<QString, std::uint32_t> m_stLabels; // the ST body's labels (upper case) -> pc
    std::vector<std::pair<std::uint32_t, const ast::Stmt *>> m_stJumps;
    void resolveStJumps();

    // ---- il.cpp ----
    void compileIl(const std::vector<ast::IlInstruction> &list);
    const Type *ilJoinType(const std::vector<Value> &arriving);

    // ---- emission helpers (compiler.cpp) ----
    std::uint32_t instr(std::uint16_t opcode, std::uint32_t a = 0, std::uint32_t b = 0, std::uint32_t c = 0,
                       std::uint32_t d = 0, std::uint16_t aux = 0);
    std::uint32_t here() const { return static_cast<std::uint32_t>(m_module->code.size()); }
    void patchJump(std::uint32_t at, std::uint32_t target)
    {
        m_module->code[at].a = target;
        markTarget(target);
    }
    // A jump lands at `pc`: the instruction before it may no longer be merged with what follows.
    void markTarget(std::uint32_t pc) { m_lastTarget = std::max(m_lastTarget, pc); }
    void markLine(SourceLocation at);
    // Jumps to `target` when `condition` is `when`; a comparison just computed into a temporary
    // becomes one fused compare-and-jump. Returns the instruction whose target may be patched.
    std::uint32_t branchIf(const Value &condition, bool when, std::uint32_t target = 0);
    bool lastWrites(std::uint32_t operand) const;
    // A loop's test that is one Br* right after `i := i + s` ending the body: one IncBr*.
    void fuseStepIntoBranch(std::uint32_t top, std::uint32_t test);
    void error(SourceLocation at, const QString &message, const QString &hint = {});
    void warning(SourceLocation at, const QString &message, const QString &hint = {});
    // Whether the compiler's stack is nearly used up (compilerstack.h): then the caller goes no
    // deeper, and the first time `at` gets the message. Checked where recursion follows chains
    // the parser cannot limit (constants defined by constants, types by types).
    bool stackExhausted(SourceLocation at);
    bool m_stackReported = false;
    struct ConstantSlot {
        bool busy = false;     // being evaluated: a use now is a cycle
        bool reported = false; // no value, and a message says why
        std::optional<Value> value;
    };
    // (initial value, POU compiled, POU laid out, report) -> its value (evalConstOnce).
    std::map<std::tuple<const void *, const void *, const void *, bool>, ConstantSlot> m_constantValues;

    // ---- state ----
    Diagnostics &m_diagnostics;
    CompileOptions m_options;
    std::shared_ptr<Module> m_module;
    TypeTable *m_types = nullptr;
    QHash<QString, const Type *> m_namedTypes;       // upper-case name
    QHash<QString, const ast::TypeDecl *> m_typeDecls;
    QHash<QString, bool> m_typesInProgress;
    QHash<QString, int> m_pouIndex;                  // upper-case name -> index in m_pous
    std::vector<PouInfo> m_pous;
    QHash<QString, GlobalVar> m_globals;             // upper-case name
    QHash<QString, EnumValue> m_enumValues;          // upper-case value name
    QHash<QByteArray, std::uint32_t> m_constants;    // type + bytes -> offset
    std::map<int, std::vector<std::pair<int, SourceLocation>>> m_calls;

    // The POU being compiled.
    PouInfo *m_pou = nullptr;
    const PouInfo *m_declaring = nullptr; // the POU whose variables are being laid out
    // The units being compiled, and whether their global variables are declared yet: before, a
    // global CONSTANT is known by its value (earlyGlobalConstant), as array bounds need it.
    std::vector<const ast::CompilationUnit *> m_units;
    bool m_globalsDeclared = false;
    QString m_pouName;
    std::uint32_t m_tempTop = 0;
    std::uint32_t m_tempMax = 0;
    std::vector<std::pair<std::uint32_t, const Type *>> m_stringTemps;
    std::uint32_t m_pouCodeStart = 0;
    struct Loop {
        std::vector<std::uint32_t> exits;
        std::vector<std::uint32_t> continues;
    };
    std::vector<Loop> m_loops;
    int m_lastLine = -1;
    qint64 m_lastLocalId = -1;
    std::uint32_t m_lastTarget = 0;
    bool m_tooLarge = false;
    std::uint32_t m_returnJump = 0;

    void compilePouBody(PouInfo &pou);
    void compileActionBody(PouInfo &pou, const ast::SfcAction &action, int moduleIndex);
    void beginBody(PouInfo &pou, int moduleIndex, SourceLocation at);
    void endBody(const ast::Body &body);
    // Actions of POUs: "<POU index>:<upper-case action name>" -> index in Module::pous.
    QHash<QString, int> m_actions;
    int actionIndex(int pou, const QString &name) const;
    int m_lineOwner = -1; // the body being compiled: its index in Module::pous, for the line table
    void finishTemporaries();
    void packRungs();
    Value lookupName(const QString &name, SourceLocation at);
    Place namePlace(const ast::Expr &expr, bool reportUnknown);
    std::optional<Place> earlyGlobalConstant(const QString &name);
    Place globalPlace(const GlobalVar &global, const QString &name);
    bool typedLiteralFits(const ConstValue &value, const Type *type, const ast::Expr &expr);
    void addToGlobalList(const QString &list, const QString &variable);
    GlobalList *globalList(const QString &name); // the module's list of that name, or null
    // Variables whose declaration was reported (an unknown type): their uses stay quiet, so one
    // typo gives one message. "<POU index>:<upper-case name>", POU index -1 for globals.
    QSet<QString> m_unusableVars;
    bool unusableVar(const QString &name) const;
};

// The vendor library a block of that (upper-case) name comes from; empty for none we know.
QString vendorLibraryOf(const QString &upperName);

// Upper-case key for case-insensitive IEC names.
inline QString key(const QString &name)
{
    return name.toUpper();
}

} // namespace iec::interp::detail
