#include "interpreter/runtime/symbols.h"

#include "interpreter/compiler/lexer.h"
#include "interpreter/compiler/literals.h"
#include "interpreter/runtime/valueformat.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include <cmath>
#include <cstring>
#include <limits>
#include <algorithm>

namespace iec::interp {

namespace {

template<typename T>
T load(const std::uint8_t *p)
{
    T v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

std::optional<VariableRef> resolveAddress(const Module &module, const QString &name)
{
    static const QRegularExpression pattern(QStringLiteral("^%([IQM])([XBWDL]?)(\\d+)(?:\\.(\\d+))?$"),
                                            QRegularExpression::CaseInsensitiveOption);
    const auto m = pattern.match(name);
    if (!m.hasMatch())
        return std::nullopt;
    VariableRef ref;
    ref.imageArea = m.captured(1).toUpper()[0].toLatin1();
    const QChar size = m.captured(2).isEmpty() ? QLatin1Char('X') : m.captured(2).toUpper()[0];
    const std::uint32_t index = m.captured(3).toUInt();
    static const std::pair<char, Elem> sizes[] = {{'X', Elem::Bool}, {'B', Elem::Byte}, {'W', Elem::Word}, {'D', Elem::DWord}, {'L', Elem::LWord}};
    for (const auto &[letter, e] : sizes) {
        if (size == QLatin1Char(letter))
            ref.type = module.types->elementary(e);
    }
    if (size == QLatin1Char('X')) {
        ref.offset = index;
        ref.bit = m.captured(4).isEmpty() ? 0 : m.captured(4).toInt();
        if (ref.bit > 7)
            return std::nullopt;
    } else {
        ref.offset = index * ref.type->size;
    }
    const int area = ref.imageArea == 'I' ? 0 : ref.imageArea == 'Q' ? 1 : 2;
    if (ref.offset + (ref.bit >= 0 ? 1 : ref.type->size) > module.imageSizes[area])
        return std::nullopt;
    // Outputs and markers are read and written where the program has them, in the memory image;
    // inputs in the input image, which is copied in at the start of every cycle.
    if (ref.imageArea != 'I') {
        ref.offset += module.imageBase[area];
        ref.imageArea = 0;
    }
    return ref;
}

// The compiler names an enumeration declared inside a VAR section "enumeration".
bool isAnonymousEnum(const Type &type)
{
    return type.name == QLatin1String("enumeration");
}

QString formatElementary(const Type *type, const std::uint8_t *p)
{
    if (type->kind == TypeKind::Enum) {
        std::int64_t v = 0;
        std::memcpy(&v, p, type->size);
        if (type->size == 2)
            v = load<std::int16_t>(p);
        for (size_t i = 0; i < type->enumValues.size(); ++i) {
            if (type->enumValues[i] != v)
                continue;
            // An enumeration declared in place (x : (A, B)) has no name to qualify its values.
            if (isAnonymousEnum(*type))
                return type->enumNames[qsizetype(i)];
            return type->name + QLatin1Char('#') + type->enumNames[qsizetype(i)];
        }
        return QString::number(v);
    }
    switch (type->elem) {
    case Elem::Bool: return formatBool(*p != 0);
    case Elem::SInt: return formatInteger(load<std::int8_t>(p));
    case Elem::Int: return formatInteger(load<std::int16_t>(p));
    case Elem::DInt: return formatInteger(load<std::int32_t>(p));
    case Elem::LInt: return formatInteger(load<std::int64_t>(p));
    // CHAR and WCHAR as their literals: 'A', "A".
    case Elem::Char: return formatString(QString(windows1252Char(load<std::uint8_t>(p))));
    case Elem::WChar: return formatWString(QString(QChar(load<char16_t>(p))));
    case Elem::USInt: case Elem::Byte: return formatUnsigned(load<std::uint8_t>(p));
    case Elem::UInt: case Elem::Word: return formatUnsigned(load<std::uint16_t>(p));
    case Elem::UDInt: case Elem::DWord: return formatUnsigned(load<std::uint32_t>(p));
    case Elem::ULInt: case Elem::LWord: return formatUnsigned(load<std::uint64_t>(p));
    case Elem::Real: return formatReal(load<float>(p));
    case Elem::LReal: return formatReal(load<double>(p));
    case Elem::Time: return formatDuration(load<std::int64_t>(p));
    case Elem::LTime: return QStringLiteral("L") + formatDuration(load<std::int64_t>(p));
    case Elem::Date: case Elem::LDate: return formatDate(load<std::int64_t>(p));
    case Elem::Tod: case Elem::LTod: return formatTimeOfDay(load<std::int64_t>(p));
    case Elem::Dt: case Elem::Ldt: return formatDateAndTime(load<std::int64_t>(p));
    case Elem::Count: break;
    }
    return {};
}

QString formatAt(const Type *type, const std::uint8_t *p)
{
    switch (type->kind) {
    case TypeKind::Elementary:
    case TypeKind::Enum:
    case TypeKind::Pointer:   // the address, a UDINT
    case TypeKind::Reference:
    case TypeKind::Interface:
        return formatElementary(type, p);
    case TypeKind::String: {
        // As the VM reads it (vmoperations.h StringRef): up to the first NUL, within the capacity.
        QString text;
        for (std::uint32_t i = 0; i < type->capacity; ++i) {
            const char16_t c = type->wide ? load<char16_t>(p + 4 + 2 * i) : p[4 + i];
            if (c == 0)
                break;
            text += type->wide ? QChar(c) : windows1252Char(std::uint8_t(c));
        }
        return type->wide ? formatWString(text) : formatString(text);
    }
    case TypeKind::Array: {
        QStringList items;
        const std::uint32_t count = type->element->size ? type->size / type->element->size : 0;
        for (std::uint32_t i = 0; i < count; ++i)
            items << formatAt(type->element, p + i * type->element->size);
        return QLatin1Char('[') + items.join(QStringLiteral(", ")) + QLatin1Char(']');
    }
    case TypeKind::Struct:
    case TypeKind::FunctionBlock: {
        QStringList items;
        for (const Member &m : type->members) {
            if (!m.byReference && m.kind != ast::VarKind::Temp)
                items << m.name + QStringLiteral(" := ") + formatAt(m.type, p + m.offset);
        }
        return QLatin1Char('(') + items.join(QStringLiteral(", ")) + QLatin1Char(')');
    }
    }
    return {};
}

template<typename T>
void put(std::uint8_t *p, T v)
{
    std::memcpy(p, &v, sizeof v);
}

const Symbol *symbolNamed(const Module &module, const QString &name)
{
    const Symbol *found = nullptr;
    for (const Symbol &s : module.symbols) {
        if (s.name.compare(name, Qt::CaseInsensitive) == 0)
            found = &s; // the last one wins, as the compiler's scopes do
    }
    return found;
}

// The first part of a name: a global or a program instance (Main in PROGRAM Main WITH T : Prog),
// or else the name of the program's POU when exactly one instance runs it (Prog.Counter).
const Symbol *rootSymbol(const Module &module, const QString &name)
{
    if (const Symbol *symbol = symbolNamed(module, name))
        return symbol;
    const ProgramInstance *only = nullptr;
    for (const ProgramInstance &instance : module.programs) {
        if (module.pous[size_t(instance.pou)].name.compare(name, Qt::CaseInsensitive) != 0)
            continue;
        if (only)
            return nullptr; // two instances of the program: the instance name must be given
        only = &instance;
    }
    return only ? symbolNamed(module, only->name) : nullptr;
}

} // namespace

// IO.Valve: when `list` names a global variable list (and nothing else), the global after it.
// Consumes the ".Valve" from `parts`.
const Symbol *globalThroughList(const Module &module, const QString &list, QRegularExpressionMatchIterator &parts, qsizetype &pos)
{
    const auto found = std::find_if(module.globalLists.begin(), module.globalLists.end(),
                                    [&](const GlobalList &l) { return l.name.compare(list, Qt::CaseInsensitive) == 0; });
    if (found == module.globalLists.end() || !parts.hasNext() || parts.peekNext().captured(0) != QLatin1String("."))
        return nullptr;
    parts.next();
    if (!parts.hasNext())
        return nullptr;
    const auto match = parts.next();
    const QString variable = match.captured(1);
    if (!found->variables.contains(variable, Qt::CaseInsensitive))
        return nullptr;
    pos = match.capturedEnd();
    return rootSymbol(module, variable);
}

std::optional<VariableRef> resolveSymbol(const Module &module, const QString &name)
{
    if (name.startsWith(QLatin1Char('%')))
        return resolveAddress(module, name);
    // Split Main.Values[3].x into parts: names, [indices] and bit numbers.
    static const QRegularExpression part(QStringLiteral("([A-Za-z_][A-Za-z0-9_]*)|\\[([^\\]]*)\\]|\\.(\\d+)|\\."));
    VariableRef ref;
    bool first = true;
    qsizetype pos = 0;
    auto it = part.globalMatch(name);
    while (it.hasNext()) {
        const auto m = it.next();
        if (m.capturedStart() != pos)
            return std::nullopt;
        pos = m.capturedEnd();
        if (!m.captured(1).isEmpty()) {
            const QString n = m.captured(1);
            if (first) {
                first = false;
                const Symbol *root = rootSymbol(module, n);
                if (!root && (root = globalThroughList(module, n, it, pos)) == nullptr)
                    return std::nullopt;
                ref.type = root->type;
                ref.offset = root->offset;
                continue;
            }
            if (!ref.type || ref.bit >= 0 || (ref.type->kind != TypeKind::Struct && ref.type->kind != TypeKind::FunctionBlock))
                return std::nullopt;
            const Member *member = ref.type->member(n);
            if (!member || member->byReference)
                return std::nullopt;
            ref.offset += member->offset;
            ref.type = member->type;
        } else if (m.capturedLength(2) > 0 || m.captured(0).startsWith(QLatin1Char('['))) {
            if (!ref.type || ref.type->kind != TypeKind::Array)
                return std::nullopt;
            const QStringList indices = m.captured(2).split(QLatin1Char(','));
            if (indices.size() != qsizetype(ref.type->dims.size()))
                return std::nullopt;
            std::uint32_t stride = ref.type->element->size, offset = 0;
            for (qsizetype d = indices.size(); d-- > 0;) {
                bool ok = false;
                const std::int64_t i = indices[d].trimmed().toLongLong(&ok);
                const Dimension &dim = ref.type->dims[size_t(d)];
                if (!ok || i < dim.low || i > dim.high)
                    return std::nullopt;
                offset += static_cast<std::uint32_t>(i - dim.low) * stride;
                stride *= static_cast<std::uint32_t>(dim.count());
            }
            ref.offset += offset;
            ref.type = ref.type->element;
        } else if (!m.captured(3).isEmpty()) {
            const int bit = m.captured(3).toInt();
            if (!ref.type || ref.type->kind != TypeKind::Elementary || ref.type->elem == Elem::Bool || bit >= int(ref.type->size * 8))
                return std::nullopt;
            ref.offset += static_cast<std::uint32_t>(bit / 8);
            ref.bit = bit % 8;
            ref.type = module.types->elementary(Elem::Bool);
        }
    }
    if (first || pos != name.size())
        return std::nullopt;
    // A located variable (q AT %QW2) is the process image's: the program reads and writes it there.
    // At an input it is the input image (copied in at the start of every cycle), so --set
    // Main.start=TRUE reaches the program.
    for (const LocatedVar &l : module.located) {
        if (l.offset == ref.offset && ref.bit < 0 && ref.type && ref.type->isElementary()
            && (l.bit >= 0 ? ref.type->size == 1 : l.size == ref.type->size)) {
            const int area = l.area == 'I' ? 0 : l.area == 'Q' ? 1 : 2;
            ref.imageArea = l.area == 'I' ? 'I' : 0;
            ref.offset = l.byte + (l.area == 'I' ? 0 : module.imageBase[area]);
            ref.bit = l.bit;
            break;
        }
    }
    return ref;
}

QString formatValue(const VariableRef &ref, const std::uint8_t *memory, const std::uint8_t *image)
{
    const std::uint8_t *p = (ref.imageArea ? image : memory) + ref.offset;
    if (ref.bit >= 0)
        return formatBool(((*p >> ref.bit) & 1) != 0);
    return formatAt(ref.type, p);
}

namespace {

// The byte a STRING or CHAR keeps for a character typed or decoded: a decoded '...' text holds its
// bytes already (U+0000..U+00FF); a character beyond is looked up in Windows-1252 (€ is 16#80).
std::optional<std::uint8_t> stringByte(QChar c)
{
    return c.unicode() <= 0xFF ? std::optional<std::uint8_t>(std::uint8_t(c.unicode())) : windows1252Byte(c);
}

QString notInCodePage(QChar c)
{
    return QCoreApplication::translate("iec::interp::Runtime",
        "A STRING cannot hold %1 (it holds the characters of Windows-1252); use a WSTRING.")
        .arg(c);
}

// -1, 0 or 1 as `value` is below, at or above `bound`.
int compare(const IntegerValue &value, std::int64_t bound)
{
    if (value.negative && value.magnitude != 0) {
        if (bound >= 0)
            return -1;
        const std::uint64_t m = static_cast<std::uint64_t>(-(bound + 1)) + 1; // |bound|, also for INT64_MIN
        return value.magnitude > m ? -1 : value.magnitude < m ? 1 : 0;
    }
    if (bound < 0)
        return 1;
    const auto m = static_cast<std::uint64_t>(bound);
    return value.magnitude > m ? 1 : value.magnitude < m ? -1 : 0;
}

// Why `value` does not fit an integer variable of `type` (its size, signedness and subrange), or
// nullopt. A based literal (16#FFFF) may give the bit pattern of a signed variable.
std::optional<QString> outOfRange(const Type &type, const IntegerValue &value, bool based, const QString &text)
{
    if (type.subrange) {
        const auto [low, high] = *type.subrange;
        if (compare(value, low) >= 0 && compare(value, high) <= 0)
            return std::nullopt;
        return QCoreApplication::translate("iec::interp::Runtime", "%1 is out of the range of %2 (%3..%4).").arg(text, typeName(&type)).arg(low).arg(high);
    }
    const unsigned bits = std::min(8 * type.size, 64u);
    if (bits == 0)
        return std::nullopt;
    const bool isUnsigned = info(type.elem).isUnsigned || info(type.elem).isBit;
    const std::int64_t low = isUnsigned ? 0 : std::numeric_limits<std::int64_t>::min() >> (64 - bits);
    const unsigned highBits = isUnsigned || based ? bits : bits - 1;
    const std::uint64_t high = highBits >= 64 ? ~std::uint64_t(0) : (std::uint64_t(1) << highBits) - 1;
    const bool negative = value.negative && value.magnitude != 0;
    if (compare(value, low) >= 0 && (negative || value.magnitude <= high))
        return std::nullopt;
    if (based)
        return QCoreApplication::translate("iec::interp::Runtime", "%1 does not fit the %2 bits of %3.").arg(text).arg(bits).arg(typeName(&type));
    const std::uint64_t signedHigh = isUnsigned ? high : (std::uint64_t(1) << (bits - 1)) - 1;
    return QCoreApplication::translate("iec::interp::Runtime", "%1 is out of the range of %2 (%3..%4).").arg(text, typeName(&type)).arg(low).arg(signedHigh);
}

} // namespace

std::optional<QString> writeLiteral(const VariableRef &ref, const QString &input, std::uint8_t *memory, std::uint8_t *image)
{
    std::uint8_t *p = (ref.imageArea ? image : memory) + ref.offset;
    const Type *type = ref.type;
    const QString text = input.trimmed();
    const auto bad = [&] { return QCoreApplication::translate("iec::interp::Runtime", "'%1' is not a valid %2.").arg(text, typeName(type)); };
    if (type->kind == TypeKind::String) {
        QString value = text;
        if (text.startsWith(QLatin1Char('\'')) || text.startsWith(QLatin1Char('"'))) {
            const auto decoded = decodeString(text);
            if (!decoded)
                return bad();
            value = *decoded;
        }
        if (value.size() > qsizetype(type->capacity))
            return QCoreApplication::translate("iec::interp::Runtime", "The text is longer than the %1 characters of the string.").arg(type->capacity);
        QByteArray bytes;
        if (!type->wide) {
            for (const QChar c : value) {
                const std::optional<std::uint8_t> byte = stringByte(c);
                if (!byte)
                    return notInCodePage(c);
                bytes.append(char(*byte));
            }
        }
        put<std::uint16_t>(p + 2, static_cast<std::uint16_t>(value.size()));
        for (qsizetype i = 0; i < value.size(); ++i) {
            if (type->wide)
                put<char16_t>(p + 4 + 2 * i, value[i].unicode());
            else
                p[4 + i] = static_cast<std::uint8_t>(bytes[i]);
        }
        if (value.size() < qsizetype(type->capacity)) { // the NUL that ends it
            if (type->wide)
                put<char16_t>(p + 4 + 2 * value.size(), 0);
            else
                p[4 + value.size()] = 0;
        }
        return std::nullopt;
    }
    if (!type->isElementary())
        return QCoreApplication::translate("iec::interp::Runtime", "Only elementary variables and strings can be written.");
    const LiteralParts parts = splitTypedLiteral(text);
    const Elem e = type->elem;
    if (type->kind == TypeKind::Enum) {
        // Color#Red, Red or the value's number.
        if (parts.typePrefix.isEmpty() || parts.typePrefix.compare(type->name, Qt::CaseInsensitive) == 0) {
            for (size_t i = 0; i < type->enumValues.size(); ++i) {
                if (parts.body.compare(type->enumNames[qsizetype(i)], Qt::CaseInsensitive) == 0) {
                    const std::int64_t value = type->enumValues[i];
                    std::memcpy(p, &value, type->size); // little endian: the low bytes
                    return std::nullopt;
                }
            }
        }
        if (!parts.typePrefix.isEmpty() || !decodeInteger(parts.body))
            return bad();
    }
    if ((e == Elem::Char || e == Elem::WChar) && type->kind == TypeKind::Elementary && parts.body.startsWith(e == Elem::Char ? u'\'' : u'"')) {
        // 'A' (CHAR) or "A" (WCHAR): exactly one character.
        const auto decoded = decodeString(parts.body);
        if (!decoded || decoded->size() != 1)
            return bad();
        if (e == Elem::Char) {
            const std::optional<std::uint8_t> byte = stringByte(decoded->front());
            if (!byte)
                return notInCodePage(decoded->front());
            *p = *byte;
        } else
            put<char16_t>(p, decoded->front().unicode());
        return std::nullopt;
    }
    if (e == Elem::Bool) {
        const QString upper = parts.body.toString().toUpper();
        bool value = false;
        if (upper == QLatin1String("TRUE") || upper == QLatin1String("1"))
            value = true;
        else if (upper != QLatin1String("FALSE") && upper != QLatin1String("0"))
            return bad();
        if (ref.bit >= 0)
            *p = static_cast<std::uint8_t>(value ? (*p | (1u << ref.bit)) : (*p & ~(1u << ref.bit)));
        else
            *p = value ? 1 : 0;
        return std::nullopt;
    }
    if (info(e).isTimeLike) {
        std::optional<std::int64_t> ns;
        switch (e) {
        case Elem::Date: case Elem::LDate: ns = decodeDate(parts.body); break;
        case Elem::Tod: case Elem::LTod: ns = decodeTimeOfDay(parts.body); break;
        case Elem::Dt: case Elem::Ldt: ns = decodeDateAndTime(parts.body); break;
        default: ns = decodeDuration(parts.body); break;
        }
        if (!ns)
            return bad();
        put<std::int64_t>(p, *ns);
        return std::nullopt;
    }
    if (info(e).isReal) {
        const auto value = decodeReal(parts.body);
        if (!value)
            return bad();
        // A literal beyond the type's range would become infinity, which reads back as a text no
        // literal can give: refused like an integer out of range.
        if (e == Elem::Real && (!std::isfinite(*value) || std::fabs(*value) > double(std::numeric_limits<float>::max())))
            return QCoreApplication::translate("iec::interp::Runtime", "%1 is out of the range of REAL (about ±3.4E38).").arg(text);
        if (!std::isfinite(*value))
            return QCoreApplication::translate("iec::interp::Runtime", "%1 is out of the range of LREAL (about ±1.8E308).").arg(text);
        if (e == Elem::Real)
            put<float>(p, static_cast<float>(*value));
        else
            put<double>(p, *value);
        return std::nullopt;
    }
    const auto value = decodeInteger(parts.body);
    if (!value)
        return bad();
    if (auto problem = outOfRange(*type, *value, parts.body.contains(QLatin1Char('#')), text))
        return problem;
    const std::uint64_t bits = value->negative ? 0 - value->magnitude : value->magnitude;
    std::memcpy(p, &bits, type->size); // little endian: the low bytes
    return std::nullopt;
}

} // namespace iec::interp
