// Object orientation as CODESYS 3.5 writes it (IEC 61131-3 ed.3): METHODs and PROPERTYs of
// function blocks, EXTENDS, INTERFACE/IMPLEMENTS, THIS^ and SUPER^, ABSTRACT/FINAL and access
// specifiers.
//
// A method is compiled like a function (its parameters and locals in a static frame, set up anew
// on every call) that runs on an instance: it is called with CallFb, so the function block's
// variables are instance-relative as in the block's own body. A property is a getter (a method
// returning the value, named like the property) and a setter (a method whose input is named like
// it). Every function block that takes part in inheritance or interfaces starts with a hidden
// __CLASS (its POU index + 1): a call through an interface, a pointer or THIS reads it and
// branches to the implementation of the object's class (dynamic dispatch); a call on an instance
// variable knows its class already.
#include "interpreter/compiler/codegen.h"
#include "interpreter/compiler/typeutil.h"

#include <QCoreApplication>
#include <QSet>

#include <algorithm>
#include <functional>

namespace iec::interp::detail {

using namespace ast;

namespace {

QString roleKey(Method::Role role, const QString &name)
{
    const char *prefix = role == Method::Role::Getter ? "GET:" : role == Method::Role::Setter ? "SET:" : "";
    return QLatin1String(prefix) + key(name);
}

} // namespace

// Methods and property accessors become PouInfo entries of kind Function owned by their block.
void Codegen::registerMethods()
{
    const size_t count = m_pous.size();
    QSet<QString> extended;
    for (size_t i = 0; i < count; ++i) {
        if (m_pous[i].ast && !m_pous[i].ast->extends.isEmpty())
            extended.insert(key(m_pous[i].ast->extends));
    }
    for (size_t i = 0; i < count; ++i) {
        const Pou *owner = m_pous[i].ast;
        if (!owner || (owner->kind != PouKind::FunctionBlock && owner->kind != PouKind::Interface))
            continue;
        m_pous[i].hasClassId = owner->kind == PouKind::FunctionBlock
            && (!owner->methods.empty() || !owner->extends.isEmpty() || !owner->implements.isEmpty() || extended.contains(key(owner->name)));
        for (const Method &m : owner->methods) {
            Pou &function = m_methodAsts.emplace_back();
            function.kind = PouKind::Function;
            function.name = m.name;
            function.location = m.location;
            function.returnType = m.returnType;
            function.sections = m.sections;
            function.body = m.body;
            PouInfo info;
            info.ast = &function;
            info.index = static_cast<int>(m_pous.size());
            info.name = methodCodeName(owner->name, m.name, m.role);
            info.kind = PouKind::Function;
            info.fromLibrary = m_pous[i].fromLibrary;
            info.methodOf = static_cast<int>(i);
            info.method = &m;
            const QString k = roleKey(m.role, m.name);
            if (m_pous[i].methods.contains(k)) {
                m_pouName = owner->name;
                error(m.location, QCoreApplication::translate("iec::interp::Compiler", "%1 has two methods or properties called %2.").arg(owner->name, m.name));
                continue;
            }
            m_pous[i].methods.insert(k, info.index);
            m_pous.push_back(info);
        }
    }
}

// A function block that IMPLEMENTS an interface has every method and property accessor the
// interface (and the interfaces it extends) declares, itself or through its base, as CODESYS
// requires; an ABSTRACT block may leave them to the blocks that extend it.
void Codegen::checkImplementations()
{
    for (const PouInfo &block : m_pous) {
        const Pou *a = block.ast;
        if (!a || block.kind != PouKind::FunctionBlock || block.fromLibrary || a->implements.isEmpty())
            continue;
        m_pouName = block.name;
        QSet<int> seen;
        std::function<void(int, int)> check = [&](int itf, int depth) {
            if (itf < 0 || depth > 32 || seen.contains(itf) || m_pous[size_t(itf)].kind != PouKind::Interface || a->isAbstract)
                return;
            seen.insert(itf);
            QList<int> prototypes = m_pous[size_t(itf)].methods.values();
            std::sort(prototypes.begin(), prototypes.end()); // as declared, whatever the hash's order
            for (const int index : prototypes) {
                const Method *prototype = m_pous[size_t(index)].method;
                if (!prototype || findMethod(block.index, prototype->name, prototype->role) >= 0)
                    continue;
                const QString itfName = m_pous[size_t(itf)].name;
                error(a->location, prototype->role == Method::Role::Method
                        ? QCoreApplication::translate("iec::interp::Compiler", "%1 must implement the method %2 of %3.").arg(a->name, prototype->name, itfName)
                        : prototype->role == Method::Role::Getter
                        ? QCoreApplication::translate("iec::interp::Compiler", "%1 must implement the GET of the property %2 of %3.").arg(a->name, prototype->name, itfName)
                        : QCoreApplication::translate("iec::interp::Compiler", "%1 must implement the SET of the property %2 of %3.").arg(a->name, prototype->name, itfName));
            }
            for (const QString &parent : m_pous[size_t(itf)].ast->implements)
                check(m_pouIndex.value(key(parent), -1), depth + 1);
        };
        for (const QString &itf : a->implements) {
            const int index = m_pouIndex.value(key(itf), -1);
            if (index < 0 || m_pous[size_t(index)].kind != PouKind::Interface)
                error(a->location, QCoreApplication::translate("iec::interp::Compiler", "%1 implements %2, which is no interface of the project.").arg(a->name, itf));
            check(index, 0);
        }
    }
}

// What CODESYS checks of methods along EXTENDS: a FINAL method is not overridden, and a block
// that is not ABSTRACT has code for every method and accessor it has, its own or inherited (an
// ABSTRACT one left without an implementation could be called and has nothing to run).
void Codegen::checkOverrides()
{
    for (const PouInfo &block : m_pous) {
        const Pou *a = block.ast;
        if (!a || block.kind != PouKind::FunctionBlock || block.fromLibrary)
            continue;
        m_pouName = block.name;
        const int base = baseOf(block.index);
        for (const Method &m : a->methods) {
            const int overridden = base >= 0 ? findMethod(base, m.name, m.role) : -1;
            if (overridden >= 0 && m_pous[size_t(overridden)].method->isFinal)
                error(m.location, QCoreApplication::translate("iec::interp::Compiler", "%1 cannot override %2: it is FINAL.")
                                      .arg(methodCodeName(a->name, m.name, m.role), m_pous[size_t(overridden)].name));
        }
        if (a->isAbstract)
            continue;
        QSet<QString> seen;
        for (int c = block.index, depth = 0; c >= 0 && depth < 64; c = baseOf(c), ++depth) {
            QList<int> methods = m_pous[size_t(c)].methods.values();
            std::sort(methods.begin(), methods.end());
            for (const int index : methods) {
                const Method *m = m_pous[size_t(index)].method;
                if (!m)
                    continue;
                const QString k = roleKey(m->role, m->name);
                if (seen.contains(k))
                    continue;
                seen.insert(k);
                const int resolved = findMethod(block.index, m->name, m->role);
                if (resolved >= 0 && m_pous[size_t(resolved)].method->isAbstract)
                    error(a->location, QCoreApplication::translate("iec::interp::Compiler", "%1 must implement the ABSTRACT %2, or be ABSTRACT itself.")
                                           .arg(a->name, m_pous[size_t(resolved)].name));
            }
        }
    }
}

// The block a function block extends, or -1.
int Codegen::baseOf(int pou) const
{
    const Pou *a = pou >= 0 ? m_pous[size_t(pou)].ast : nullptr;
    if (!a || a->extends.isEmpty())
        return -1;
    const int base = m_pouIndex.value(key(a->extends), -1);
    return base >= 0 && m_pous[size_t(base)].kind == PouKind::FunctionBlock ? base : -1;
}

// The method (or accessor) `name` of class `pou` or the nearest class it extends; -1 for none.
int Codegen::findMethod(int pou, const QString &name, Method::Role role) const
{
    for (int c = pou, depth = 0; c >= 0 && depth < 64; c = baseOf(c), ++depth) {
        if (const int m = m_pous[size_t(c)].methods.value(roleKey(role, name), -1); m >= 0)
            return m;
    }
    return -1;
}

// The prototype of `name` in interface `pou` or the interfaces it extends; -1 for none.
int Codegen::findInterfaceMethod(int pou, const QString &name, Method::Role role, int depth) const
{
    if (pou < 0 || depth > 32)
        return -1;
    if (const int m = m_pous[size_t(pou)].methods.value(roleKey(role, name), -1); m >= 0)
        return m;
    for (const QString &parent : m_pous[size_t(pou)].ast->implements) {
        if (const int m = findInterfaceMethod(m_pouIndex.value(key(parent), -1), name, role, depth + 1); m >= 0)
            return m;
    }
    return -1;
}

// Whether class `pou` is `of` or extends it (for a function block), or implements it (for an
// interface), directly, through its base or through interfaces that extend it.
bool Codegen::isA(int pou, int of) const
{
    std::function<bool(int, int)> implements = [&](int itf, int depth) {
        if (itf == of)
            return true;
        if (itf < 0 || depth > 32 || !m_pous[size_t(itf)].ast)
            return false;
        for (const QString &parent : m_pous[size_t(itf)].ast->implements) {
            if (implements(m_pouIndex.value(key(parent), -1), depth + 1))
                return true;
        }
        return false;
    };
    for (int c = pou, depth = 0; c >= 0 && depth < 64; c = baseOf(c), ++depth) {
        if (c == of)
            return true;
        if (m_pous[size_t(of)].kind == PouKind::Interface) {
            for (const QString &itf : m_pous[size_t(c)].ast->implements) {
                if (implements(m_pouIndex.value(key(itf), -1), 0))
                    return true;
            }
        }
    }
    return false;
}

// The class whose code is being compiled: the block itself, or the owner of a method.
int Codegen::currentClass() const
{
    if (!m_pou)
        return -1;
    if (m_pou->methodOf >= 0)
        return m_pou->methodOf;
    return m_pou->kind == PouKind::FunctionBlock ? m_pou->index : -1;
}

// PRIVATE: only the class itself; PROTECTED: it and the classes that extend it.
bool Codegen::mayCall(const PouInfo &method, SourceLocation at)
{
    if (!method.method || method.method->access == Access::Public || method.method->access == Access::Internal)
        return true;
    const int here = currentClass();
    const bool allowed = method.method->access == Access::Private ? here == method.methodOf : (here >= 0 && isA(here, method.methodOf));
    if (!allowed)
        error(at, QCoreApplication::translate("iec::interp::Compiler", "%1 is %2 and cannot be called from here.")
                      .arg(method.name, method.method->access == Access::Private ? QStringLiteral("PRIVATE") : QStringLiteral("PROTECTED")));
    return allowed;
}

// THIS (a pointer to the running instance) and SUPER (the same, as its base class).
Place Codegen::selfPointer(bool super, SourceLocation at)
{
    const int cls = currentClass();
    const int target = super ? baseOf(cls) : cls;
    if (target < 0 || !m_pous[size_t(target)].frame) {
        error(at, super ? QCoreApplication::translate("iec::interp::Compiler", "SUPER is only known in a function block that EXTENDS another one.")
                        : QCoreApplication::translate("iec::interp::Compiler", "THIS is only known in a function block and its methods."));
        return {};
    }
    const Type *pointer = m_types->pointer(m_pous[size_t(target)].frame);
    const std::uint32_t address = temp(pointer);
    instr(op::Lea, address, kInstanceRelative);
    Place p;
    p.kind = Place::Kind::Direct;
    p.type = pointer;
    p.operand = address;
    p.text = super ? QStringLiteral("SUPER") : QStringLiteral("THIS");
    p.readOnly = true;
    p.readOnlyReason = QCoreApplication::translate("iec::interp::Compiler", "%1 cannot be changed.").arg(p.text);
    m_superCall = super;
    return p;
}

// A call of method `name` on an object of static class `cls` (a function block or an interface)
// at `address` (an operand holding its image address). Dynamic: the object's __CLASS picks the
// implementation, among the classes that are `cls`.
Value Codegen::dynamicCall(int cls, const QString &name, Method::Role role, std::uint32_t address, const std::vector<Argument> &args,
                           SourceLocation at, const Place *destination, bool statement)
{
    const bool isInterface = m_pous[size_t(cls)].kind == PouKind::Interface;
    const int declared = isInterface ? findInterfaceMethod(cls, name, role) : findMethod(cls, name, role);
    if (declared < 0)
        return {};
    if (!mayCall(m_pous[size_t(declared)], at))
        return {};
    // The implementation each class uses, grouped: one call per implementation.
    std::vector<std::pair<int, std::vector<int>>> implementations;
    for (const PouInfo &c : m_pous) {
        if (c.kind != PouKind::FunctionBlock || !c.hasClassId || !c.ast || c.ast->isAbstract || !isA(c.index, cls))
            continue;
        const int impl = findMethod(c.index, name, role);
        if (impl < 0 || !m_pous[size_t(impl)].method || !m_pous[size_t(impl)].method->hasBody)
            continue;
        auto group = std::find_if(implementations.begin(), implementations.end(), [&](const auto &g) { return g.first == impl; });
        if (group == implementations.end())
            implementations.push_back({impl, {c.index}});
        else
            group->second.push_back(c.index);
    }
    const PouInfo &prototype = m_pous[size_t(declared)];
    if (!layoutPou(const_cast<PouInfo &>(prototype)))
        return {};
    const Type *resultType = prototype.result;
    if (implementations.empty()) {
        error(at, QCoreApplication::translate("iec::interp::Compiler", "No function block implements %1.%2, so it cannot be called.").arg(m_pous[size_t(cls)].name, name));
        return {};
    }
    // The arguments are computed once, before the object's class is looked at.
    std::vector<Argument> computed = args;
    for (Argument &a : computed) {
        if (!a.isOutput && !a.value && a.expr)
            a.value = compileExpr(*a.expr);
    }
    Place object;
    object.kind = Place::Kind::Indirect;
    object.operand = address;
    object.type = m_pous[size_t(implementations.front().second.front())].frame;
    instr(op::CheckPtr, 0, address, 0, 4);
    const std::uint32_t out = resultType ? temp(resultType) : 0;
    if (implementations.size() == 1) {
        const Value v = callUserFunction(m_pous[size_t(implementations.front().first)], computed, at, nullptr, &object);
        if (resultType && v.valid())
            emitMove(out, v.operand, resultType);
        return resultType ? operandValue(out, resultType) : Value{};
    }
    const std::uint32_t classId = temp(elem(Elem::UDInt));
    instr(op::Load4, classId, address);
    std::vector<std::uint32_t> toEnd;
    for (const auto &[impl, classes] : implementations) {
        std::vector<std::uint32_t> toCall;
        for (const int c : classes) {
            ConstValue id;
            id.kind = ConstValue::Kind::Int;
            id.i = c + 1;
            toCall.push_back(instr(typedOp(op::BrEq, VT::U32), 0, classId, constantOperand(elem(Elem::UDInt), id)));
        }
        const std::uint32_t skip = instr(op::Jmp);
        for (const std::uint32_t j : toCall)
            patchJump(j, here());
        const Value v = callUserFunction(m_pous[size_t(impl)], computed, at, nullptr, &object);
        if (resultType && v.valid())
            emitMove(out, v.operand, resultType);
        toEnd.push_back(instr(op::Jmp));
        patchJump(skip, here());
    }
    for (const std::uint32_t j : toEnd)
        patchJump(j, here());
    (void)destination;
    (void)statement;
    return resultType ? operandValue(out, resultType) : Value{};
}

// obj.M(...), itf.M(...), THIS^.M(...), SUPER^.M(...), p^.M(...) and M(...) inside a block.
// nullopt when the callee is no method.
std::optional<Value> Codegen::methodCall(const Expr &callee, const std::vector<CallArg> &callArgs, SourceLocation at, bool asStatement,
                                         const Place *destination)
{
    const std::vector<Argument> args = arguments(callArgs);
    if (callee.kind == ExprKind::Name) {
        const int cls = currentClass();
        if (cls < 0 || (m_pou->frame && m_pou->frame->member(callee.text)))
            return std::nullopt;
        if (findMethod(cls, callee.text, Method::Role::Method) < 0)
            return std::nullopt;
        const Place self = selfPointer(false, at);
        m_superCall = false;
        return dynamicCall(cls, callee.text, Method::Role::Method, self.operand, args, at, destination, asStatement);
    }
    if (callee.kind != ExprKind::Member)
        return std::nullopt;
    const Expr &baseExpr = callee.operands.front();
    // Only names and members are looked at first, so that looking does not emit code twice.
    const Expr *root = &baseExpr;
    while (root->kind == ExprKind::Member || root->kind == ExprKind::Deref)
        root = &root->operands.front();
    if (root->kind != ExprKind::Name)
        return std::nullopt;
    const size_t before = m_diagnostics.all().size();
    m_superCall = false;
    const Place base = resolvePlace(baseExpr, false);
    const bool super = m_superCall;
    m_superCall = false;
    if (base.kind == Place::Kind::Invalid || !base.type) {
        if (m_diagnostics.all().size() != before)
            return Value{};
        return std::nullopt;
    }
    if (base.type->kind == TypeKind::Interface) {
        const int itf = base.type->pou;
        if (findInterfaceMethod(itf, callee.text, Method::Role::Method) < 0)
            return std::nullopt;
        const Value address = read(base);
        return dynamicCall(itf, callee.text, Method::Role::Method, materialize(address), args, at, destination, asStatement);
    }
    if (base.type->kind != TypeKind::FunctionBlock || base.type->pou < 0)
        return std::nullopt;
    const int cls = base.type->pou;
    const int method = findMethod(cls, callee.text, Method::Role::Method);
    if (method < 0)
        return std::nullopt;
    PouInfo &info = m_pous[size_t(method)];
    if (!mayCall(info, at))
        return Value{};
    // An instance variable is of its own class; behind a pointer (and THIS) it may be of a
    // class that extends it. SUPER^.M() is the base's implementation.
    if (base.kind == Place::Kind::Indirect && !super) {
        return dynamicCall(cls, callee.text, Method::Role::Method, base.operand, args, at, destination, asStatement);
    }
    if (!info.method->hasBody) {
        error(at, QCoreApplication::translate("iec::interp::Compiler", "%1 is ABSTRACT and has no code to run.").arg(info.name));
        return Value{};
    }
    return callUserFunction(info, args, at, destination, &base);
}

// obj.P read through its getter; nullopt when P is no property.
std::optional<Value> Codegen::propertyRead(const Expr &expr)
{
    return propertyAccess(expr, nullptr);
}

// obj.P := value through its setter (or P := value inside the block); false when P is no property.
bool Codegen::propertyWrite(const Expr &target, const Expr &value, SourceLocation at)
{
    Argument a;
    a.expr = &value;
    a.location = at;
    const std::optional<Value> done = propertyAccess(target, &a);
    return done.has_value();
}

std::optional<Value> Codegen::propertyAccess(const Expr &expr, const Argument *assigned)
{
    const Method::Role role = assigned ? Method::Role::Setter : Method::Role::Getter;
    std::vector<Argument> args;
    if (assigned) {
        Argument a = *assigned;
        a.name = expr.text; // the setter's input is named like the property
        args.push_back(a);
    }
    if (expr.kind == ExprKind::Name) {
        const int cls = currentClass();
        if (cls < 0 || (m_pou->frame && m_pou->frame->member(expr.text)) || findMethod(cls, expr.text, role) < 0)
            return std::nullopt;
        const Place self = selfPointer(false, expr.location);
        m_superCall = false;
        return dynamicCall(cls, expr.text, role, self.operand, args, expr.location, nullptr, assigned != nullptr);
    }
    if (expr.kind != ExprKind::Member)
        return std::nullopt;
    const Expr *root = &expr.operands.front();
    while (root->kind == ExprKind::Member || root->kind == ExprKind::Deref || root->kind == ExprKind::Index)
        root = &root->operands.front();
    if (root->kind != ExprKind::Name)
        return std::nullopt;
    // Look at the base's type without emitting code: only when it is a block or an interface
    // with such a property is the base compiled.
    const Place probe = probeType(expr.operands.front());
    if (!probe.type)
        return std::nullopt;
    const bool isInterface = probe.type->kind == TypeKind::Interface;
    if (!isInterface && probe.type->kind != TypeKind::FunctionBlock)
        return std::nullopt;
    const int cls = probe.type->pou;
    if (cls < 0 || (isInterface ? findInterfaceMethod(cls, expr.text, role) : findMethod(cls, expr.text, role)) < 0) {
        // A property with only the other accessor: a clear message instead of "no member".
        const Method::Role other = assigned ? Method::Role::Getter : Method::Role::Setter;
        if (cls >= 0 && (isInterface ? findInterfaceMethod(cls, expr.text, other) : findMethod(cls, expr.text, other)) >= 0) {
            error(expr.location, assigned ? QCoreApplication::translate("iec::interp::Compiler", "The property %1 has no SET and cannot be written.").arg(expr.text)
                                          : QCoreApplication::translate("iec::interp::Compiler", "The property %1 has no GET and cannot be read.").arg(expr.text));
            return Value{};
        }
        return std::nullopt;
    }
    m_superCall = false;
    const Place base = resolvePlace(expr.operands.front());
    const bool super = m_superCall;
    m_superCall = false;
    if (base.kind == Place::Kind::Invalid)
        return Value{};
    if (isInterface)
        return dynamicCall(cls, expr.text, role, materialize(read(base)), args, expr.location, nullptr, assigned != nullptr);
    const int accessor = findMethod(cls, expr.text, role);
    if (base.kind == Place::Kind::Indirect && !super)
        return dynamicCall(cls, expr.text, role, base.operand, args, expr.location, nullptr, assigned != nullptr);
    if (!mayCall(m_pous[size_t(accessor)], expr.location))
        return Value{};
    const Value v = callUserFunction(m_pous[size_t(accessor)], args, expr.location, nullptr, &base);
    return assigned ? Value{} : v;
}

// The type of a variable expression (names and members only), without emitting code.
Place Codegen::probeType(const Expr &expr)
{
    const std::uint32_t codeSize = here();
    const size_t diagnostics = m_diagnostics.all().size();
    const std::uint32_t tempTop = m_tempTop;
    const std::uint32_t lastTarget = m_lastTarget;
    const bool super = m_superCall;
    const Place p = resolvePlace(expr, false);
    // Undo what looking emitted: the caller compiles the expression itself.
    m_module->code.resize(codeSize);
    m_tempTop = tempTop;
    m_lastTarget = lastTarget;
    m_superCall = super;
    if (m_diagnostics.all().size() != diagnostics)
        return {};
    return p;
}

// The address of a function block instance, as the value of an interface (itf := fbInstance).
std::optional<Value> Codegen::interfaceOf(const Value &v, const Type *to, SourceLocation at)
{
    if (!to || to->kind != TypeKind::Interface || !v.valid())
        return std::nullopt;
    if (v.type->kind == TypeKind::Interface) {
        if (v.type->pou != to->pou && !isA(v.type->pou, to->pou)) {
            error(at, QCoreApplication::translate("iec::interp::Compiler", "%1 does not extend %2.").arg(typeName(v.type), typeName(to)));
            return Value{};
        }
        Value same = v;
        same.type = to;
        return same;
    }
    if (v.untyped && v.kind == Value::Kind::Constant && v.constant.kind == ConstValue::Kind::Int && v.constant.i == 0)
        return constantValue(to, v.constant); // no object
    if (v.type->kind != TypeKind::FunctionBlock || v.kind != Value::Kind::Operand)
        return std::nullopt;
    if (!isA(v.type->pou, to->pou)) {
        error(at, QCoreApplication::translate("iec::interp::Compiler", "%1 does not implement %2.").arg(typeName(v.type), typeName(to)));
        return Value{};
    }
    const std::uint32_t out = temp(to);
    if (v.instanceAddress)
        instr(op::Mov4, out, v.operand);
    else
        instr(op::Lea, out, v.operand);
    return operandValue(out, to);
}

} // namespace iec::interp::detail
