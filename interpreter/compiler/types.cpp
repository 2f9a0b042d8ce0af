#include "interpreter/compiler/types.h"

#include <array>

namespace iec::interp {

namespace {

// name, vt, size, int, unsigned, real, bit, time-like
constexpr std::array<ElemInfo, static_cast<size_t>(Elem::Count)> kElems{{
    {"BOOL", VT::U8, 1, false, true, false, true, false},
    {"SINT", VT::I8, 1, true, false, false, false, false},
    {"INT", VT::I16, 2, true, false, false, false, false},
    {"DINT", VT::I32, 4, true, false, false, false, false},
    {"LINT", VT::I64, 8, true, false, false, false, false},
    {"USINT", VT::U8, 1, true, true, false, false, false},
    {"UINT", VT::U16, 2, true, true, false, false, false},
    {"UDINT", VT::U32, 4, true, true, false, false, false},
    {"ULINT", VT::U64, 8, true, true, false, false, false},
    {"BYTE", VT::U8, 1, false, true, false, true, false},
    {"WORD", VT::U16, 2, false, true, false, true, false},
    {"DWORD", VT::U32, 4, false, true, false, true, false},
    {"LWORD", VT::U64, 8, false, true, false, true, false},
    {"REAL", VT::F32, 4, false, false, true, false, false},
    {"LREAL", VT::F64, 8, false, false, true, false, false},
    {"TIME", VT::I64, 8, false, false, false, false, true},
    {"LTIME", VT::I64, 8, false, false, false, false, true},
    {"DATE", VT::I64, 8, false, false, false, false, true},
    {"LDATE", VT::I64, 8, false, false, false, false, true},
    {"TIME_OF_DAY", VT::I64, 8, false, false, false, false, true},
    {"LTIME_OF_DAY", VT::I64, 8, false, false, false, false, true},
    {"DATE_AND_TIME", VT::I64, 8, false, false, false, false, true},
    {"LDATE_AND_TIME", VT::I64, 8, false, false, false, false, true},
    {"CHAR", VT::U8, 1, false, true, false, false, false},
    {"WCHAR", VT::U16, 2, false, true, false, false, false},
}};

struct Widening {
    Elem from, to;
};
// The direct implicit conversions of IEC 61131-3 ed.3 (figure 11); the closure is taken below.
constexpr Widening kWidenings[] = {
    {Elem::SInt, Elem::Int},    {Elem::Int, Elem::DInt},     {Elem::DInt, Elem::LInt},   {Elem::USInt, Elem::UInt},
    {Elem::UInt, Elem::UDInt},  {Elem::UDInt, Elem::ULInt},  {Elem::USInt, Elem::Int},   {Elem::UInt, Elem::DInt},
    {Elem::UDInt, Elem::LInt},  {Elem::SInt, Elem::Real},    {Elem::Int, Elem::Real},    {Elem::USInt, Elem::Real},
    {Elem::UInt, Elem::Real},   {Elem::DInt, Elem::LReal},   {Elem::UDInt, Elem::LReal}, {Elem::Real, Elem::LReal},
    {Elem::Bool, Elem::Byte},   {Elem::Byte, Elem::Word},    {Elem::Word, Elem::DWord},  {Elem::DWord, Elem::LWord},
    {Elem::Time, Elem::LTime},  {Elem::Date, Elem::LDate},   {Elem::Tod, Elem::LTod},    {Elem::Dt, Elem::Ldt},
    {Elem::Char, Elem::WChar},
};

struct Alias {
    const char *name;
    Elem elem;
};
constexpr Alias kAliases[] = {
    {"T", Elem::Time}, {"LT", Elem::LTime}, {"D", Elem::Date}, {"LD", Elem::LDate}, {"TOD", Elem::Tod},
    {"LTOD", Elem::LTod}, {"DT", Elem::Dt}, {"LDT", Elem::Ldt},
};

} // namespace

const ElemInfo &info(Elem e)
{
    return kElems[static_cast<size_t>(e)];
}

VT vtOf(const Type &t)
{
    return info(t.elem).vt;
}

std::optional<Elem> elemByName(QStringView name)
{
    for (size_t i = 0; i < kElems.size(); ++i) {
        if (name.compare(QLatin1String(kElems[i].name), Qt::CaseInsensitive) == 0)
            return static_cast<Elem>(i);
    }
    for (const Alias &a : kAliases) {
        if (name.compare(QLatin1String(a.name), Qt::CaseInsensitive) == 0)
            return a.elem;
    }
    return std::nullopt;
}

bool implicitlyConvertible(Elem from, Elem to)
{
    if (from == to)
        return true;
    // Depth-first over the widening graph; it has no cycles and a dozen edges.
    for (const Widening &w : kWidenings) {
        if (w.from == from && implicitlyConvertible(w.to, to))
            return true;
    }
    return false;
}

ImplicitConversion implicitConversion(Elem from, Elem to)
{
    if (implicitlyConvertible(from, to))
        return ImplicitConversion::Widening;
    const ElemInfo &f = info(from), &t = info(to);
    const auto integerLike = [](Elem e, const ElemInfo &i) { return e != Elem::Bool && (i.isInt || i.isBit); };
    if (integerLike(from, f) && integerLike(to, t)) {
        if (t.size < f.size)
            return ImplicitConversion::LossOfInformation;
        const bool fromSigned = f.isInt && !f.isUnsigned, toSigned = t.isInt && !t.isUnsigned;
        if (fromSigned && !toSigned)
            return ImplicitConversion::SignedToUnsigned;
        if (!fromSigned && toSigned && t.size == f.size)
            return ImplicitConversion::UnsignedToSigned;
        return ImplicitConversion::Silent; // WORD to UINT, BYTE to INT, UINT to DWORD
    }
    if (f.isReal && (integerLike(to, t) || t.isReal))
        return ImplicitConversion::LossOfInformation; // REAL to INT rounds, LREAL to REAL
    if (integerLike(from, f) && t.isReal) // DINT to REAL: more digits than a REAL holds
        return f.size >= t.size ? ImplicitConversion::LossOfInformation : ImplicitConversion::Silent;
    return ImplicitConversion::Refused;
}

const Member *Type::member(const QString &name) const
{
    // A program with 40,000 variables is looked up 40,000 times: by hash once laid out.
    if (memberIndex.size() == qsizetype(members.size()) && !members.empty()) {
        const int i = memberIndex.value(name.toUpper(), -1);
        return i < 0 ? nullptr : &members[size_t(i)];
    }
    for (const Member &m : members) {
        if (m.name.compare(name, Qt::CaseInsensitive) == 0)
            return &m;
    }
    return nullptr;
}

TypeTable::TypeTable()
{
    for (size_t i = 0; i < kElems.size(); ++i) {
        Type *t = create(TypeKind::Elementary, QString::fromLatin1(kElems[i].name));
        t->elem = static_cast<Elem>(i);
        t->size = kElems[i].size;
        t->align = kElems[i].size;
        m_elementary.push_back(t);
    }
}

Type *TypeTable::create(TypeKind kind, const QString &name)
{
    Type &t = m_types.emplace_back();
    t.kind = kind;
    t.name = name;
    return &t;
}

const Type *TypeTable::string(bool wide, std::uint32_t capacity)
{
    for (const Type *t : m_strings) {
        if (t->wide == wide && t->capacity == capacity)
            return t;
    }
    // Layout: capacity (uint16), length (uint16), then the characters and room for the NUL that
    // ends them, as in CODESYS (a program that builds a string through a pointer writes it after
    // the last character, even of a full string: OSCAT's BYTE_TO_STRH into its STRING(2)).
    Type *t = create(TypeKind::String, QStringLiteral("%1[%2]").arg(wide ? QStringLiteral("WSTRING") : QStringLiteral("STRING")).arg(capacity));
    t->wide = wide;
    t->capacity = capacity;
    t->size = 4 + (capacity + 1) * (wide ? 2 : 1);
    t->size = (t->size + 1) & ~1u;
    t->align = 2;
    m_strings.push_back(t);
    return t;
}

const Type *TypeTable::pointer(const Type *element, bool reference)
{
    const TypeKind kind = reference ? TypeKind::Reference : TypeKind::Pointer;
    for (const Type *t : m_pointers) {
        if (t->kind == kind && t->element == element)
            return t;
    }
    Type *t = create(kind, QStringLiteral("%1 %2").arg(reference ? QStringLiteral("REFERENCE TO") : QStringLiteral("POINTER TO"), typeName(element)));
    t->element = element;
    t->elem = Elem::UDInt; // computed with as an address: a UDINT offset into the image
    t->size = 4;
    t->align = 4;
    m_pointers.push_back(t);
    return t;
}

const Type *TypeTable::interfaceType(int pou, const QString &name)
{
    for (const Type *t : m_pointers) {
        if (t->kind == TypeKind::Interface && t->pou == pou)
            return t;
    }
    Type *t = create(TypeKind::Interface, name);
    t->pou = pou;
    t->elem = Elem::UDInt;
    t->size = 4;
    t->align = 4;
    m_pointers.push_back(t);
    return t;
}

void TypeTable::layout(Type &type)
{
    std::uint32_t offset = 0;
    std::uint32_t align = 1;
    for (Member &m : type.members) {
        const std::uint32_t a = m.byReference ? 4 : m.type->align;
        offset = (offset + a - 1) / a * a;
        m.offset = offset;
        offset += m.byReference ? 4 : m.type->size;
        align = std::max(align, a);
    }
    type.align = align;
    type.size = std::max<std::uint32_t>(1, (offset + align - 1) / align * align);
    type.memberIndex.clear();
    for (size_t i = 0; i < type.members.size(); ++i)
        type.memberIndex.insert(type.members[i].name.toUpper(), static_cast<int>(i));
}

void TypeTable::finishArray(Type &type)
{
    std::uint64_t count = 1;
    for (const Dimension &d : type.dims)
        count *= static_cast<std::uint64_t>(std::max<std::int64_t>(0, d.count()));
    type.size = static_cast<std::uint32_t>(count * type.element->size);
    type.align = type.element->align;
}

QString typeName(const Type *t)
{
    if (!t)
        return QStringLiteral("?");
    if (t->kind == TypeKind::String && t->capacity == 80)
        return t->wide ? QStringLiteral("WSTRING") : QStringLiteral("STRING");
    if (t->kind == TypeKind::Array && t->name.isEmpty()) {
        QStringList dims;
        for (const Dimension &d : t->dims)
            dims << QStringLiteral("%1..%2").arg(d.low).arg(d.high);
        return QStringLiteral("ARRAY[%1] OF %2").arg(dims.join(QLatin1Char(',')), typeName(t->element));
    }
    return t->name;
}

} // namespace iec::interp
