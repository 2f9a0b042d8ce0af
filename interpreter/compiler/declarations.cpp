// Types, layouts, memory allocation and initial values.
#include "interpreter/compiler/codegen.h"
#include "interpreter/compiler/literals.h"
#include "interpreter/compiler/svghmi.h"

#include <QCoreApplication>
#include <QSet>

#include <cstring>

namespace iec::interp::detail {

using namespace ast;

namespace {

// The pointer-sized integers CODESYS 3.5 (__XINT, ...) and TwinCAT (XINT, ...) build in, as the
// elementary types they are on a 64-bit target (`key`: upper case; empty: not one of them).
QString pointerSizedType(const QString &key)
{
    const QStringView name = key.startsWith(QLatin1String("__")) ? QStringView(key).mid(2) : QStringView(key);
    if (name == QLatin1String("XINT"))
        return QStringLiteral("LINT");
    if (name == QLatin1String("UXINT"))
        return QStringLiteral("ULINT");
    if (name == QLatin1String("XWORD"))
        return QStringLiteral("LWORD");
    return {};
}

bool isShortLiteralPrefix(const QString &name)
{
    // T#, LT#, D#, LD# are literal prefixes, not type names a declaration may use.
    const QString upper = name.toUpper();
    return upper == QLatin1String("T") || upper == QLatin1String("LT") || upper == QLatin1String("D")
        || upper == QLatin1String("LD");
}

} // namespace

void Codegen::collectTypes(const CompilationUnit &unit, bool library)
{
    for (const TypeDecl &decl : unit.types) {
        const QString k = key(decl.name);
        if (m_typeDecls.contains(k)) {
            if (!library)
                error(decl.location, QCoreApplication::translate("iec::interp::Compiler", "The type %1 is declared twice.").arg(decl.name));
            continue;
        }
        m_typeDecls.insert(k, &decl);
    }
}

void Codegen::collectPous(const CompilationUnit &unit, bool library)
{
    for (const Pou &p : unit.pous) {
        const QString k = key(p.name);
        if (m_pouIndex.contains(k)) {
            // A user POU with a standard FB's name replaces the library one.
            if (!library && !m_pous[size_t(m_pouIndex.value(k))].fromLibrary) {
                m_pouName = p.name;
                error(p.location, QCoreApplication::translate("iec::interp::Compiler", "There are two POUs called %1.").arg(p.name));
            }
            continue;
        }
        if (m_typeDecls.contains(k) || elemByName(p.name)) {
            m_pouName = p.name;
            error(p.location, QCoreApplication::translate("iec::interp::Compiler", "%1 is already the name of a type.").arg(p.name));
            continue;
        }
        PouInfo info;
        info.ast = &p;
        info.index = static_cast<int>(m_pous.size());
        info.name = p.name;
        info.kind = p.kind;
        info.fromLibrary = library;
        m_pouIndex.insert(k, info.index);
        m_pous.push_back(info);
    }
}

const Type *Codegen::namedType(const QString &name, SourceLocation at, bool report)
{
    const QString k = key(name);
    if (!isShortLiteralPrefix(name)) {
        if (const auto e = elemByName(name))
            return elem(*e);
    }
    if (k == QLatin1String("STRING") || k == QLatin1String("WSTRING"))
        return m_types->string(k == QLatin1String("WSTRING"), 80);
    if (const Type *t = m_namedTypes.value(k))
        return t;
    if (const TypeDecl *decl = m_typeDecls.value(k)) {
        if (stackExhausted(decl->location))
            return nullptr;
        if (m_typesInProgress.value(k)) {
            error(decl->location, QCoreApplication::translate("iec::interp::Compiler", "The type %1 is defined in terms of itself.").arg(decl->name));
            return nullptr;
        }
        m_typesInProgress.insert(k, true);
        // A type is declared outside every POU: the variables of the POU that uses it first are not
        // in its scope (ARRAY[0..N] is the global N, even where that POU has an n of its own).
        const QString savedPou = std::exchange(m_pouName, QString());
        PouInfo *const savedCompiling = std::exchange(m_pou, nullptr);
        const PouInfo *const savedDeclaring = std::exchange(m_declaring, nullptr);
        const Type *resolved = resolveType(decl->type, decl->name);
        m_pouName = savedPou;
        m_pou = savedCompiling;
        m_declaring = savedDeclaring;
        m_typesInProgress.remove(k);
        if (!resolved)
            return nullptr;
        // An alias or a type with its own default value is a type of its own.
        Type *own = const_cast<Type *>(resolved);
        if (resolved->name.compare(decl->name, Qt::CaseInsensitive) != 0) {
            own = m_types->create(resolved->kind, decl->name);
            const QString ownName = own->name;
            *own = *resolved;
            own->name = ownName;
        }
        if (decl->init.kind != Initializer::Kind::None)
            own->init = &decl->init;
        if (own->subrange && decl->init.kind == Initializer::Kind::Expression) {
            const QString pou = m_pouName;
            m_pouName.clear(); // reported with the type, not with the POU that uses it first
            if (const auto value = evalConst(*decl->init.value); value && value->kind == Value::Kind::Constant)
                checkSubrange(*value, own, decl->init.location);
            m_pouName = pou;
        }
        m_namedTypes.insert(k, own);
        return own;
    }
    if (const int index = m_pouIndex.value(k, -1); index >= 0) {
        PouInfo &pou = m_pous[size_t(index)];
        if (pou.kind == PouKind::FunctionBlock) {
            if (!layoutPou(pou))
                return nullptr;
            return pou.frame;
        }
        if (pou.kind == PouKind::Interface)
            return m_types->interfaceType(pou.index, pou.name);
        if (report)
            error(at, (pou.kind == PouKind::Program
                    ? QCoreApplication::translate("iec::interp::Compiler", "%1 is a program, not a type; only function blocks can be instantiated.")
                    : QCoreApplication::translate("iec::interp::Compiler", "%1 is a function, not a type; only function blocks can be instantiated."))
                          .arg(name));
        return nullptr;
    }
    if (k == QLatin1String("T_MAXSTRING")) // TwinCAT's Tc2_System
        return m_types->string(false, 255);
    if (const QString base = pointerSizedType(k); !base.isEmpty())
        return namedType(base, at, report);
    if (const QString library = vendorLibraryOf(k); report && !library.isEmpty()) {
        missingVendorLibrary(name, library, at);
        return nullptr;
    }
    if (const QString base = svgHmiBaseType(k); !base.isEmpty()) {
        // One warning for the whole project, at the first such variable, like a missing library.
        if (report && !m_reportedLibraries.contains(QStringLiteral("SVGHMI"))) {
            m_reportedLibraries.insert(QStringLiteral("SVGHMI"));
            warning(at, QCoreApplication::translate("iec::interp::Compiler", "%1 is a type of Beremiz's SVGHMI, which IEC Studio does not have: its variables are read as %2 and no HMI is shown.").arg(name, base),
                QCoreApplication::translate("iec::interp::Compiler", "watch and write them in the watch pane instead"));
        }
        return namedType(base, at, report);
    }
    if (report)
        error(at, QCoreApplication::translate("iec::interp::Compiler", "Unknown type '%1'.").arg(name));
    return nullptr;
}

const Type *Codegen::resolveType(const TypeSpec &spec, const QString &name)
{
    switch (spec.kind) {
    case TypeSpec::Kind::Named:
        return namedType(spec.name, spec.location);
    case TypeSpec::Kind::String: {
        std::int64_t capacity = 80;
        if (spec.length) {
            const auto n = evalConstInt(*spec.length);
            if (!n)
                return nullptr;
            capacity = *n;
        }
        if (capacity < 1 || capacity > 65535) {
            error(spec.location, QCoreApplication::translate("iec::interp::Compiler", "A string holds 1 to 65535 characters, not %1.").arg(capacity));
            return nullptr;
        }
        return m_types->string(spec.wide, static_cast<std::uint32_t>(capacity));
    }
    case TypeSpec::Kind::Array: {
        const Type *element = resolveType(spec.element.front());
        if (!element)
            return nullptr;
        Type *t = m_types->create(TypeKind::Array, name);
        t->element = element;
        for (const Range &r : spec.ranges) {
            const auto low = evalConstInt(r.low), high = evalConstInt(r.high);
            if (!low || !high)
                return nullptr;
            if (*high < *low) {
                error(r.low.location, QCoreApplication::translate("iec::interp::Compiler", "The array range %1..%2 is empty; the upper bound must not be below the lower one.").arg(*low).arg(*high));
                return nullptr;
            }
            t->dims.push_back({*low, *high});
        }
        // The size is checked before it is computed in 32 bits.
        std::uint64_t bytes = element->size;
        for (const Dimension &d : t->dims)
            bytes *= static_cast<std::uint64_t>(d.count());
        if (bytes > 256u * 1024 * 1024) {
            error(spec.location, QCoreApplication::translate("iec::interp::Compiler", "This array needs %1 MB; an array may use at most 256 MB.").arg(bytes / (1024 * 1024)));
            return nullptr;
        }
        TypeTable::finishArray(*t);
        return t;
    }
    case TypeSpec::Kind::Pointer:
    case TypeSpec::Kind::Reference: {
        const Type *element = resolveType(spec.element.front());
        return element ? m_types->pointer(element, spec.kind == TypeSpec::Kind::Reference) : nullptr;
    }
    case TypeSpec::Kind::Subrange: {
        const Type *base = namedType(spec.name, spec.location);
        if (!base)
            return nullptr;
        if (base->kind != TypeKind::Elementary || !info(base->elem).isInt) {
            error(spec.location, QCoreApplication::translate("iec::interp::Compiler", "A subrange needs an integer type, not %1.").arg(typeName(base)));
            return nullptr;
        }
        const auto low = evalConstInt(spec.ranges[0].low), high = evalConstInt(spec.ranges[0].high);
        if (!low || !high)
            return nullptr;
        Type *t = m_types->create(TypeKind::Elementary, name.isEmpty() ? base->name : name);
        const QString n = t->name;
        *t = *base;
        t->name = n;
        t->subrange = std::make_pair(*low, *high);
        return t;
    }
    case TypeSpec::Kind::Enum: {
        Type *t = m_types->create(TypeKind::Enum, name.isEmpty() ? QStringLiteral("enumeration") : name);
        t->elem = Elem::Int;
        if (!spec.name.isEmpty()) {
            if (const auto e = elemByName(spec.name))
                t->elem = *e;
        }
        t->size = info(t->elem).size;
        t->align = t->size;
        std::int64_t next = 0;
        for (qsizetype i = 0; i < spec.enumValues.size(); ++i) {
            const auto &explicitValue = spec.enumExplicit[size_t(i)];
            if (explicitValue) {
                if (const auto v = evalConstInt(*explicitValue))
                    next = *v;
            }
            t->enumNames << spec.enumValues[i];
            t->enumValues.push_back(next);
            const QString k = key(spec.enumValues[i]);
            if (m_enumValues.contains(k) && m_enumValues.value(k).type != t)
                m_enumValues[k].ambiguous = true;
            else
                m_enumValues.insert(k, {t, next, false});
            ++next;
        }
        return t;
    }
    case TypeSpec::Kind::Struct: {
        Type *t = m_types->create(TypeKind::Struct, name);
        for (const VarDecl &v : spec.members) {
            Member m;
            m.name = v.name;
            m.location = v.location;
            m.type = resolveType(v.type);
            m.init = v.init.kind == Initializer::Kind::None ? nullptr : &v.init;
            if (!m.type)
                return nullptr;
            if (t->member(v.name)) {
                error(v.location, QCoreApplication::translate("iec::interp::Compiler", "The structure has two members called %1.").arg(v.name));
                continue;
            }
            t->members.push_back(m);
        }
        TypeTable::layout(*t);
        return t;
    }
    }
    return nullptr;
}

bool Codegen::layoutPou(PouInfo &pou)
{
    if (pou.laidOut)
        return pou.frame != nullptr;
    if (stackExhausted(pou.ast->location))
        return false;
    const QString savedPou = m_pouName;
    m_pouName = pou.name;
    if (pou.layoutInProgress) {
        error(pou.ast->location, QCoreApplication::translate("iec::interp::Compiler", "%1 contains an instance of itself, which would never end.").arg(pou.name));
        m_pouName = savedPou;
        return false;
    }
    if (pou.kind == PouKind::Interface) {
        pou.laidOut = true; // methods only: no variables of its own
        m_pouName = savedPou;
        return true;
    }
    pou.layoutInProgress = true;
    const PouInfo *savedDeclaring = m_declaring;
    m_declaring = &pou; // its CONSTANTs may size its arrays
    Type *frame = m_types->create(pou.kind == PouKind::FunctionBlock ? TypeKind::FunctionBlock : TypeKind::Struct, pou.name);
    frame->pou = pou.index;
    bool ok = true;
    QSet<QString> declared; // upper-case names, for "declared twice" without a quadratic search
    // EXTENDS: the base's variables first, at the offsets its own code uses; a class starts with
    // __CLASS, which tells its methods' callers which class an object is.
    std::uint32_t ownFrom = 0;
    if (const int base = baseOf(pou.index); base >= 0) {
        if (!layoutPou(m_pous[size_t(base)]) || !m_pous[size_t(base)].frame) {
            ok = false;
        } else {
            if (m_pous[size_t(base)].ast->isFinal)
                error(pou.ast->location, QCoreApplication::translate("iec::interp::Compiler", "%1 is FINAL; no function block can extend it.").arg(m_pous[size_t(base)].name));
            for (const Member &m : m_pous[size_t(base)].frame->members) {
                frame->members.push_back(m);
                declared.insert(key(m.name));
            }
            ownFrom = static_cast<std::uint32_t>(frame->members.size());
        }
    } else if (pou.ast && !pou.ast->extends.isEmpty()) {
        error(pou.ast->location, QCoreApplication::translate("iec::interp::Compiler", "%1 extends %2, which is no function block.").arg(pou.name, pou.ast->extends));
    } else if (pou.hasClassId) {
        Member classId;
        classId.name = QStringLiteral("__CLASS");
        classId.type = elem(Elem::UDInt);
        frame->members.push_back(classId);
        declared.insert(key(classId.name));
        ownFrom = 1;
    }
    // Functions: parameters first, so the rest can be reset in one copy on every call.
    // Programs and FBs: VAR_TEMP last, for the same reason.
    const auto rank = [&](VarKind kind) {
        if (pou.kind == PouKind::Function)
            return kind == VarKind::Input || kind == VarKind::InOut ? 0 : 1;
        return kind == VarKind::Temp ? 1 : 0;
    };
    for (int pass = 0; pass < 2; ++pass) {
        for (const VarSection &section : pou.ast->sections) {
            if (section.kind == VarKind::External || section.kind == VarKind::Global || section.kind == VarKind::Access
                || section.kind == VarKind::Config || rank(section.kind) != pass)
                continue;
            for (const VarDecl &v : section.vars) {
                if (declared.contains(key(v.name))) {
                    error(v.location, QCoreApplication::translate("iec::interp::Compiler", "%1 is declared twice.").arg(v.name));
                    continue;
                }
                declared.insert(key(v.name));
                Member m;
                m.name = v.name;
                m.location = v.location;
                m.kind = section.kind;
                m.retain = section.retain;
                m.constant = section.constant;
                m.address = v.address;
                m.byReference = section.kind == VarKind::InOut;
                m.init = v.init.kind == Initializer::Kind::None ? nullptr : &v.init;
                // A VAR_IN_OUT of the block's own type holds an address, not an instance: the
                // block need not be laid out before it.
                const bool ownTypeByReference = m.byReference && pou.kind == PouKind::FunctionBlock
                    && v.type.kind == TypeSpec::Kind::Named && key(v.type.name) == key(pou.name);
                m.type = ownTypeByReference ? frame : resolveType(v.type);
                if (!m.type) {
                    m_unusableVars.insert(QString::number(pou.index) + QLatin1Char(':') + key(v.name));
                    ok = false;
                    continue;
                }
                if (m.type->kind == TypeKind::FunctionBlock && m.type->pou >= 0 && m_pous[size_t(m.type->pou)].ast
                    && m_pous[size_t(m.type->pou)].ast->isAbstract && section.kind != VarKind::InOut) {
                    error(v.location, QCoreApplication::translate("iec::interp::Compiler", "%1 is ABSTRACT; declare an instance of a function block that extends it.").arg(typeName(m.type)));
                    ok = false;
                    continue;
                }
                if (m.type->kind == TypeKind::FunctionBlock && pou.kind == PouKind::Function && pou.methodOf < 0) {
                    error(v.location, QCoreApplication::translate("iec::interp::Compiler", "A function cannot hold a function block instance (%1); use a function block instead.").arg(v.name));
                    ok = false;
                    continue;
                }
                frame->members.push_back(m);
            }
        }
        if (pass == 0 && pou.kind == PouKind::Function && pou.ast->returnType) {
            pou.result = resolveType(*pou.ast->returnType);
            if (pou.result) {
                Member r;
                r.name = pou.ast->name; // a method's result is named like the method, not Block.Method
                r.kind = VarKind::Output;
                r.type = pou.result;
                r.location = pou.ast->location;
                frame->members.push_back(r);
            }
        }
    }
    TypeTable::layout(*frame);
    pou.reinitFrom = frame->size;
    for (size_t i = ownFrom; i < frame->members.size(); ++i) { // the base's VAR_TEMP is the base's to reset
        const Member &m = frame->members[i];
        if (pou.kind == PouKind::Function ? !(m.kind == VarKind::Input || m.kind == VarKind::InOut) : m.kind == VarKind::Temp) {
            pou.reinitFrom = m.offset;
            break;
        }
    }
    for (const Member &m : frame->members) {
        if (m.kind == VarKind::Input || m.kind == VarKind::InOut)
            pou.parameters.push_back(&m);
    }
    pou.frame = frame;
    pou.laidOut = true;
    pou.layoutInProgress = false;
    m_declaring = savedDeclaring;
    m_pouName = savedPou;
    return ok;
}

std::uint32_t Codegen::allocate(std::uint32_t size, std::uint32_t align)
{
    auto &image = m_module->initialImage;
    const std::uint64_t end = (std::uint64_t(image.size()) + align - 1) / align * align + std::max<std::uint32_t>(size, 1);
    if (end >= kTempMarker) {
        // Operands address at most 1 GB (bit 30 marks temporaries while a POU is compiled).
        if (!m_tooLarge)
            error({}, QCoreApplication::translate("iec::interp::Compiler", "The program needs more than 1 GB of memory for its variables."));
        m_tooLarge = true;
        return 0;
    }
    const std::uint32_t offset = (static_cast<std::uint32_t>(image.size()) + align - 1) / align * align;
    image.resize(offset + std::max<std::uint32_t>(size, 1), 0);
    return offset;
}

// The module's lists are the only record of them: the compiler resolves List.Variable through
// them as the runtime resolves watched names.
GlobalList *Codegen::globalList(const QString &name)
{
    auto &lists = m_module->globalLists;
    const auto it = std::find_if(lists.begin(), lists.end(), [&](const GlobalList &l) { return key(l.name) == key(name); });
    return it == lists.end() ? nullptr : &*it;
}

void Codegen::addToGlobalList(const QString &list, const QString &variable)
{
    GlobalList *found = globalList(list);
    if (!found)
        found = &m_module->globalLists.emplace_back(GlobalList{list, {}});
    found->variables << variable;
}

void Codegen::declareGlobals(const std::vector<VarSection> &sections)
{
    for (const VarSection &section : sections) {
        for (const VarDecl &v : section.vars) {
            const QString k = key(v.name);
            if (!section.listName.isEmpty())
                addToGlobalList(section.listName, v.name);
            if (m_globals.contains(k)) {
                error(v.location, QCoreApplication::translate("iec::interp::Compiler", "The global variable %1 is declared twice.").arg(v.name));
                continue;
            }
            const Type *type = resolveType(v.type);
            if (!type) {
                m_unusableVars.insert(QStringLiteral("-1:") + k);
                continue;
            }
            GlobalVar g;
            g.name = v.name;
            g.type = type;
            g.constant = section.constant;
            g.offset = allocate(type->size, type->align);
            writeInitial(g.offset, type, v.init.kind == Initializer::Kind::None ? nullptr : &v.init, v.name);
            if (section.constant && v.init.kind == Initializer::Kind::Expression) {
                if (auto value = evalConst(*v.init.value, false)) {
                    Value typed = coerce(*value, type, v.location);
                    if (typed.kind == Value::Kind::Constant)
                        g.value = typed.constant;
                }
            }
            if (section.retain)
                m_module->retain.push_back({g.offset, type->size});
            if (!v.address.isEmpty()) {
                locate(v.address, g.offset, type, v.location);
                g.located = parseImageAddress(v.address);
                if (g.located)
                    initialiseImage(*g.located, g.offset, type);
            }
            m_globals.insert(k, g);
            m_module->symbols.push_back({v.name, type, g.offset});
        }
    }
}

void Codegen::locate(const QString &address, std::uint32_t offset, const Type *type, SourceLocation at)
{
    const QString text = address.toUpper();
    if (text.size() < 3 || text.endsWith(QLatin1Char('*')))
        return; // %I* is assigned in the configuration; nothing to map
    const auto a = parseImageAddress(text);
    if (!a || (a->bit >= 0 && type->size != 1) || (a->bit < 0 && type->size != a->size && type->isElementary())) {
        error(at, QCoreApplication::translate("iec::interp::Compiler", "The address %1 does not fit a variable of type %2.").arg(address, typeName(type)));
        return;
    }
    LocatedVar located;
    located.address = text;
    located.area = a->area;
    located.byte = a->byte;
    located.bit = a->bit;
    located.size = a->size;
    located.offset = offset;
    m_module->located.push_back(located);
}

const GlobalVar *Codegen::directAddressVar(const QString &address, SourceLocation at)
{
    const QString k = address.toUpper();
    if (const auto it = m_globals.constFind(k); it != m_globals.constEnd())
        return &*it;
    const QChar size = k.size() > 2 && k[2].isLetter() ? k[2] : QLatin1Char('X');
    static const std::pair<char, Elem> sizes[] = {{'X', Elem::Bool}, {'B', Elem::Byte}, {'W', Elem::Word}, {'D', Elem::DWord}, {'L', Elem::LWord}};
    const Type *type = elem(Elem::Bool);
    for (const auto &[letter, e] : sizes) {
        if (size == QLatin1Char(letter))
            type = elem(e);
    }
    GlobalVar g;
    g.name = k;
    g.type = type;
    g.offset = allocate(type->size, type->align);
    locate(k, g.offset, type, at);
    g.located = parseImageAddress(k);
    m_module->symbols.push_back({k, type, g.offset});
    return &*m_globals.insert(k, g);
}

void Codegen::writeInitial(std::uint32_t offset, const Type *type, const Initializer *init, const QString &name)
{
    if (stackExhausted(init ? init->location : SourceLocation{}))
        return;
    if (!init)
        init = type->init;
    switch (type->kind) {
    case TypeKind::Elementary:
    case TypeKind::Enum:
        if (init && init->kind == Initializer::Kind::Expression) {
            if (auto value = evalConst(*init->value)) {
                const Value typed = coerce(*value, type, init->location, name);
                // A type's own default was checked once where the type is declared.
                if (typed.kind == Value::Kind::Constant && (init == type->init || checkSubrange(typed, type, init->location)))
                    writeConstant(offset, type, typed.constant, init->location);
            }
        } else if (init) {
            error(init->location, QCoreApplication::translate("iec::interp::Compiler", "A %1 is initialised with a single value.").arg(typeName(type)));
        } else if (type->subrange && (type->subrange->first > 0 || type->subrange->second < 0)) {
            ConstValue low;
            low.kind = ConstValue::Kind::Int;
            low.i = type->subrange->first;
            writeConstant(offset, type, low, {});
        }
        return;
    case TypeKind::String: {
        auto &image = m_module->initialImage;
        const std::uint16_t capacity = static_cast<std::uint16_t>(type->capacity);
        std::memcpy(image.data() + offset, &capacity, 2);
        if (init && init->kind == Initializer::Kind::Expression) {
            if (auto value = evalConst(*init->value)) {
                const Value typed = coerce(*value, type, init->location, name);
                if (typed.kind == Value::Kind::Constant)
                    writeConstant(offset, type, typed.constant, init->location);
            }
        }
        return;
    }
    case TypeKind::Array: {
        const std::uint32_t count = type->element->size ? type->size / type->element->size : 0;
        std::uint32_t index = 0;
        if (init && init->kind == Initializer::Kind::Array) {
            for (size_t i = 0; i < init->items.size(); ++i) {
                std::int64_t repeat = 1;
                if (init->repeats[i]) {
                    if (const auto n = evalConstInt(*init->repeats[i]))
                        repeat = *n;
                }
                const Initializer *item = init->items[i].kind == Initializer::Kind::None ? nullptr : &init->items[i];
                for (std::int64_t r = 0; r < repeat; ++r) {
                    if (index >= count) {
                        error(init->location, QCoreApplication::translate("iec::interp::Compiler", "There are more initial values than the array's %1 elements.").arg(count));
                        return;
                    }
                    writeInitial(offset + index++ * type->element->size, type->element, item);
                }
            }
        } else if (init && init->kind == Initializer::Kind::Expression && count > 0) {
            // ARRAY[..] OF INT := 5 is not IEC, but a single value for every element is what is meant.
            error(init->location, QCoreApplication::translate("iec::interp::Compiler", "An array is initialised with a list in brackets, e.g. [1, 2, 3] or [10(0)]."));
            return;
        }
        for (; index < count; ++index)
            writeInitial(offset + index * type->element->size, type->element, nullptr);
        return;
    }
    case TypeKind::Pointer:
    case TypeKind::Reference:
    case TypeKind::Interface:
        // Addresses are known when the program runs: a pointer starts at 0, a reference unset,
        // an interface variable without an instance.
        if (init) {
            const auto value = init->kind == Initializer::Kind::Expression ? evalConst(*init->value, false) : std::nullopt;
            if (value && value->constant.kind == ConstValue::Kind::Int && value->constant.i == 0)
                return;
            error(init->location, QCoreApplication::translate("iec::interp::Compiler", "A %1 starts at 0; set it in the code instead (p := ADR(x); or r REF= x;).").arg(typeName(type)));
        }
        return;
    case TypeKind::Struct:
    case TypeKind::FunctionBlock:
        for (const Member &m : type->members) {
            if (m.byReference)
                continue;
            const Initializer *memberInit = m.init;
            if (init && init->kind == Initializer::Kind::Struct) {
                for (qsizetype i = 0; i < init->memberNames.size(); ++i) {
                    if (init->memberNames[i].compare(m.name, Qt::CaseInsensitive) == 0)
                        memberInit = &init->items[size_t(i)];
                }
            }
            if (memberInit && memberInit == m.init) {
                // The member's own default: a problem with it belongs to the POU or the type that
                // declares it, not to the one that holds an instance.
                const QString holder = m_pouName;
                m_pouName = type->pou >= 0 ? m_pous[size_t(type->pou)].name : QString();
                writeInitial(offset + m.offset, m.type, memberInit, m.name);
                m_pouName = holder;
            } else {
                writeInitial(offset + m.offset, m.type, memberInit, m.name);
            }
        }
        if (type->kind == TypeKind::FunctionBlock && type->pou >= 0 && !type->members.empty() && type->members.front().name == QLatin1String("__CLASS")) {
            const std::uint32_t classId = static_cast<std::uint32_t>(type->pou + 1); // which class this instance is
            std::memcpy(m_module->initialImage.data() + offset, &classId, 4);
        }
        if (init && init->kind == Initializer::Kind::Struct) {
            for (qsizetype i = 0; i < init->memberNames.size(); ++i) {
                if (!type->member(init->memberNames[i]))
                    error(init->location, QCoreApplication::translate("iec::interp::Compiler", "%1 has no member %2.").arg(typeName(type), init->memberNames[i]));
            }
        } else if (init && init->kind != Initializer::Kind::None) {
            error(init->location, QCoreApplication::translate("iec::interp::Compiler", "A structure is initialised with (member := value, ...)."));
        }
        return;
    }
}

bool Codegen::writeConstant(std::uint32_t offset, const Type *type, const ConstValue &value, SourceLocation at)
{
    std::uint8_t *p = m_module->initialImage.data() + offset;
    switch (value.kind) {
    case ConstValue::Kind::None:
        return false;
    case ConstValue::Kind::Int:
        if (type->isElementary() && info(type->elem).isReal) {
            if (type->elem == Elem::Real) {
                const float f = static_cast<float>(value.i);
                std::memcpy(p, &f, 4);
            } else {
                const double d = static_cast<double>(value.i);
                std::memcpy(p, &d, 8);
            }
        } else {
            std::memcpy(p, &value.i, std::min<std::uint32_t>(type->size, 8)); // little endian
        }
        return true;
    case ConstValue::Kind::Real:
        if (type->elem == Elem::Real) {
            const float f = static_cast<float>(value.r);
            std::memcpy(p, &f, 4);
        } else {
            std::memcpy(p, &value.r, 8);
        }
        return true;
    case ConstValue::Kind::String: {
        if (type->kind != TypeKind::String)
            return false;
        if (value.s.size() > qsizetype(type->capacity)) {
            error(at, QCoreApplication::translate("iec::interp::Compiler", "The text has %1 characters but the string holds only %2.").arg(value.s.size()).arg(type->capacity));
            return false;
        }
        const std::uint16_t capacity = static_cast<std::uint16_t>(type->capacity);
        const std::uint16_t length = static_cast<std::uint16_t>(value.s.size());
        std::memcpy(p, &capacity, 2);
        std::memcpy(p + 2, &length, 2);
        for (qsizetype i = 0; i < value.s.size(); ++i) {
            const char16_t c = value.s[i].unicode();
            if (type->wide)
                std::memcpy(p + 4 + 2 * i, &c, 2);
            else
                p[4 + i] = static_cast<std::uint8_t>(c);
        }
        return true;
    }
    }
    return false;
}

std::optional<ConstValue> Codegen::literalValue(const Expr &expr, const Type **type, bool *untyped)
{
    *untyped = false;
    ConstValue v;
    v.kind = ConstValue::Kind::Int;
    if (expr.literal == TokenKind::Keyword) { // TRUE / FALSE
        *type = elem(Elem::Bool);
        v.i = expr.text == QLatin1String("TRUE") ? 1 : 0;
        return v;
    }
    QString text = expr.text;
    bool negated = false;
    if (text.startsWith(QLatin1Char('-')) && text.contains(QLatin1Char('#'))) {
        negated = true; // -T#5s written with a space-free minus
        text = text.mid(1);
    }
    const LiteralParts parts = splitTypedLiteral(text);
    const LiteralFamily family = literalFamilyOfPrefix(parts.typePrefix);
    const auto prefixType = [&](Elem fallback) {
        if (parts.typePrefix.isEmpty())
            return elem(fallback);
        if (const auto e = elemByName(parts.typePrefix))
            return elem(*e);
        return elem(fallback);
    };
    switch (expr.literal) {
    case TokenKind::IntegerLiteral: {
        if (family == LiteralFamily::Bool && (parts.body.compare(QLatin1String("TRUE"), Qt::CaseInsensitive) == 0
                                              || parts.body.compare(QLatin1String("FALSE"), Qt::CaseInsensitive) == 0)) {
            *type = elem(Elem::Bool);
            v.i = parts.body.compare(QLatin1String("TRUE"), Qt::CaseInsensitive) == 0 ? 1 : 0;
            return v;
        }
        const auto value = decodeInteger(parts.body);
        if (!value)
            return std::nullopt;
        *untyped = parts.typePrefix.isEmpty();
        *type = prefixType(Elem::LInt);
        const bool negative = value->negative != negated;
        if (!negative && value->magnitude > std::uint64_t(INT64_MAX)) {
            v.i = static_cast<std::int64_t>(value->magnitude);
            v.bigUnsigned = true;
        } else {
            v.i = static_cast<std::int64_t>(negative ? 0 - value->magnitude : value->magnitude);
        }
        if (!*untyped && (*type)->elem == Elem::Bool && v.i != 0 && v.i != 1)
            return std::nullopt;
        return v;
    }
    case TokenKind::RealLiteral: {
        const auto value = decodeReal(parts.body);
        if (!value)
            return std::nullopt;
        *untyped = parts.typePrefix.isEmpty();
        *type = prefixType(Elem::LReal);
        v.kind = ConstValue::Kind::Real;
        v.r = negated ? -*value : *value;
        if ((*type)->elem == Elem::Real) // REAL#0.1 is the float nearest 0.1, folded or not
            v.r = static_cast<float>(v.r);
        return v;
    }
    case TokenKind::TimeLiteral: {
        const auto value = decodeDuration(parts.body);
        if (!value)
            return std::nullopt;
        *type = prefixType(Elem::Time);
        v.i = negated ? -*value : *value;
        return v;
    }
    case TokenKind::DateTimeLiteral: {
        std::optional<std::int64_t> value;
        if (family == LiteralFamily::Date)
            value = decodeDate(parts.body);
        else if (family == LiteralFamily::TimeOfDay)
            value = decodeTimeOfDay(parts.body);
        else
            value = decodeDateAndTime(parts.body);
        if (!value)
            return std::nullopt;
        *type = prefixType(Elem::Dt);
        v.i = *value;
        return v;
    }
    case TokenKind::StringLiteral:
    case TokenKind::WStringLiteral: {
        const QString quoted = parts.typePrefix.isEmpty() ? text : parts.body.toString();
        const auto value = decodeString(quoted);
        if (!value)
            return std::nullopt;
        v.kind = ConstValue::Kind::String;
        v.s = *value;
        v.wide = expr.literal == TokenKind::WStringLiteral;
        for (const QChar c : v.s) {
            if (!v.wide && c.unicode() > 0xff) {
                *type = nullptr;
                return std::nullopt;
            }
        }
        *type = m_types->string(v.wide, static_cast<std::uint32_t>(std::max<qsizetype>(1, v.s.size())));
        return v;
    }
    default:
        return std::nullopt;
    }
}

std::optional<Value> Codegen::evalConst(const Expr &expr, bool report)
{
    // Constant expressions are compiled like any other expression: constants fold and emit no
    // code. Anything that emits code, or is not constant, is not a constant expression.
    const auto before = m_module->code.size();
    const size_t diagnosticsBefore = m_diagnostics.all().size();
    const Value v = compileExpr(expr);
    const bool emitted = m_module->code.size() != before;
    m_module->code.resize(before);
    if (v.kind == Value::Kind::Constant && !emitted)
        return v;
    if (report && v.kind != Value::Kind::Invalid && m_diagnostics.all().size() == diagnosticsBefore)
        error(expr.location, QCoreApplication::translate("iec::interp::Compiler", "This must be a constant: a literal, a CONSTANT or an expression of them."));
    return std::nullopt;
}

std::optional<Value> Codegen::evalConstOnce(const Expr &expr, bool report, bool &reported)
{
    const auto key = std::make_tuple(static_cast<const void *>(&expr), static_cast<const void *>(m_pou),
                                     static_cast<const void *>(m_declaring), report);
    const auto [slot, added] = m_constantValues.try_emplace(key);
    if (!added) {
        if (slot->second.busy) {
            error(expr.location, QCoreApplication::translate("iec::interp::Compiler", "This constant is defined in terms of itself."));
            slot->second.reported = reported = true;
            return std::nullopt;
        }
        reported = slot->second.reported;
        return slot->second.value;
    }
    slot->second.busy = true;
    const size_t messagesBefore = m_diagnostics.all().size();
    const std::optional<Value> value = evalConst(expr, report);
    // std::map: the iterator stays valid while others are added.
    slot->second.busy = false;
    slot->second.value = value;
    slot->second.reported = slot->second.reported
        || (!value && (m_diagnostics.all().size() != messagesBefore || m_stackReported));
    reported = slot->second.reported;
    return value;
}

std::optional<std::int64_t> Codegen::evalConstInt(const Expr &expr)
{
    const auto before = m_module->code.size();
    const Value v = compileExpr(expr);
    if (m_module->code.size() != before || v.kind != Value::Kind::Constant || v.constant.kind != ConstValue::Kind::Int
        || !v.type || !(v.untyped || info(v.type->elem).isInt || v.type->kind == TypeKind::Enum)) {
        m_module->code.resize(before);
        if (v.kind != Value::Kind::Invalid)
            error(expr.location, QCoreApplication::translate("iec::interp::Compiler", "This must be a constant integer."));
        return std::nullopt;
    }
    return v.constant.i;
}

} // namespace iec::interp::detail
