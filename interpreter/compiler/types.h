#pragma once

#include "interpreter/compiler/ast.h"

#include <QHash>
#include <QString>
#include <QStringList>

#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

namespace iec::interp {

// Elementary IEC types. Order matters: the tables in types.cpp follow it.
enum class Elem : std::uint8_t {
    Bool, SInt, Int, DInt, LInt, USInt, UInt, UDInt, ULInt, Byte, Word, DWord, LWord, Real, LReal,
    Time, LTime, Date, LDate, Tod, LTod, Dt, Ldt, Char, WChar,
    Count
};

// How the VM stores and computes a value: the machine type behind an IEC type. TIME, DATE, TOD
// and DT (and their L forms) are all 64-bit nanoseconds; BOOL is a byte holding 0 or 1.
enum class VT : std::uint8_t { I8, I16, I32, I64, U8, U16, U32, U64, F32, F64, Count };
constexpr int kVtCount = static_cast<int>(VT::Count);

// Pointer (CODESYS POINTER TO, IEC REF_TO) and Reference (CODESYS REFERENCE TO) hold the image
// address of what they point to (4 bytes, 0 = nowhere); `element` is that type. A reference is
// read and written as what it refers to; a pointer through ^.
// Interface: a variable of an INTERFACE type holds the address of a function block instance
// that implements it (4 bytes, 0 = none); `pou` is the interface.
enum class TypeKind : std::uint8_t { Elementary, String, Array, Struct, Enum, FunctionBlock, Pointer, Reference, Interface };

struct Type;

struct Member {
    QString name;
    const Type *type = nullptr;
    std::uint32_t offset = 0;
    ast::VarKind kind = ast::VarKind::Local;
    bool retain = false;
    bool constant = false;
    QString address; // AT %QX0.1
    SourceLocation location;
    const ast::Initializer *init = nullptr; // owned by the AST; valid while compiling only
    bool byReference = false; // VAR_IN_OUT: the member holds the address of the variable
};

struct Dimension {
    std::int64_t low = 0;
    std::int64_t high = 0;
    std::int64_t count() const { return high - low + 1; }
};

struct Type {
    TypeKind kind = TypeKind::Elementary;
    QString name;
    std::uint32_t size = 0;
    std::uint32_t align = 1;
    Elem elem = Elem::Int;           // Elementary; Enum: its base
    std::uint32_t capacity = 0;      // String: characters
    bool wide = false;               // String: WSTRING
    const Type *element = nullptr;   // Array
    std::vector<Dimension> dims;     // Array
    std::vector<Member> members;     // Struct, FunctionBlock (all its variables)
    QHash<QString, int> memberIndex; // upper-case name -> position in members, built by layout()
    QStringList enumNames;           // Enum
    std::vector<std::int64_t> enumValues;
    int pou = -1;                    // FunctionBlock: the POU that implements it
    std::optional<std::pair<std::int64_t, std::int64_t>> subrange;
    const ast::Initializer *init = nullptr; // TYPE ... := default; valid while compiling only

    const Member *member(const QString &name) const;
    bool isElementary() const { return kind == TypeKind::Elementary || kind == TypeKind::Enum; }
};

// Properties of elementary types, from one table.
struct ElemInfo {
    const char *name;
    VT vt;
    std::uint32_t size;
    bool isInt, isUnsigned, isReal, isBit, isTimeLike;
};
const ElemInfo &info(Elem e);
VT vtOf(const Type &t); // elementary and enum types only
std::optional<Elem> elemByName(QStringView name); // accepts the short forms T, TOD, DT, D too

// Whether a value of `from` may be used where `to` is expected without a conversion function
// (IEC 61131-3 ed.3 implicit conversions: widening within a family, integers to reals that hold them).
bool implicitlyConvertible(Elem from, Elem to);

// What CODESYS does with a conversion IEC 61131-3 does not make implicitly: accepts it silently
// (WORD to UINT), accepts it with a warning (narrowing, REAL to an integer, a change of sign; the
// value wraps or is rounded like the *_TO_* function), or refuses it (BOOL, TIME, CHAR ...).
enum class ImplicitConversion { Widening, Silent, LossOfInformation, SignedToUnsigned, UnsignedToSigned, Refused };
ImplicitConversion implicitConversion(Elem from, Elem to);

// Owns every type of one compilation; pointers stay valid while it lives.
class TypeTable
{
public:
    TypeTable();
    const Type *elementary(Elem e) const { return m_elementary[static_cast<size_t>(e)]; }
    const Type *string(bool wide, std::uint32_t capacity);
    const Type *pointer(const Type *element, bool reference = false);
    const Type *interfaceType(int pou, const QString &name);
    Type *create(TypeKind kind, const QString &name);
    // Natural alignment layout of a struct/FB's members; sets size and align.
    static void layout(Type &type);
    static void finishArray(Type &type);

private:
    std::deque<Type> m_types;
    std::vector<const Type *> m_elementary;
    std::vector<const Type *> m_strings;
    std::vector<const Type *> m_pointers;
};

QString typeName(const Type *t);

} // namespace iec::interp
