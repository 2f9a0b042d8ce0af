// The process image: %I, %Q and %M are three byte areas of the memory image that every located
// variable shares, as on a real PLC: %QW2 is the bytes %QB4 and %QB5 (low byte first, as CODESYS
// on x86) and the bits %QX4.0 .. %QX5.7. A program reads and writes them in place; the runtime
// copies the input area in before each cycle and the output area out after it. The areas are
// sized before any code is compiled, from every address the units mention.
#include "interpreter/compiler/astwalk.h"
#include "interpreter/compiler/codegen.h"

#include <QCoreApplication>

#include <cstring>

namespace iec::interp::detail {

using namespace ast;

std::optional<ImageAddress> parseImageAddress(const QString &address)
{
    const QString body = address.toUpper().mid(1);
    if (!address.startsWith(QLatin1Char('%')) || body.size() < 2 || body.endsWith(QLatin1Char('*')))
        return std::nullopt; // %I* is assigned in the configuration: no place of its own
    ImageAddress a;
    a.area = body[0].toLatin1();
    if (a.area != 'I' && a.area != 'Q' && a.area != 'M')
        return std::nullopt;
    int pos = 1;
    char size = 'X';
    if (body[pos].isLetter())
        size = body[pos++].toLatin1();
    const QStringList parts = body.mid(pos).split(QLatin1Char('.'));
    bool ok = !parts.isEmpty() && parts.size() <= 2;
    if (size == 'X') {
        a.byte = parts[0].toUInt(&ok);
        a.bit = ok && parts.size() > 1 ? parts[1].toInt(&ok) : 0;
        a.size = 1;
    } else {
        static const std::pair<char, std::uint32_t> sizes[] = {{'B', 1}, {'W', 2}, {'D', 4}, {'L', 8}};
        a.size = 0;
        for (const auto &[letter, bytes] : sizes) {
            if (size == letter)
                a.size = bytes;
        }
        // %QW3 is the 4th word: bytes 6 and 7 (CODESYS numbering). Parts after a '.' (%MW1.2) are
        // not a byte address.
        a.byte = parts[0].toUInt(&ok) * a.size;
        ok = ok && a.size != 0 && parts.size() == 1;
    }
    if (!ok || a.bit > 7 || a.byte > 16u * 1024 * 1024)
        return std::nullopt;
    return a;
}

namespace {

// Every %-address the units mention: in declarations (AT) and in code.
struct AddressScan {
    std::uint32_t sizes[3] = {0, 0, 0};

    void address(const QString &text)
    {
        if (const auto a = parseImageAddress(text)) {
            std::uint32_t &size = sizes[a->area == 'I' ? 0 : a->area == 'Q' ? 1 : 2];
            size = std::max(size, a->byte + a->size);
        }
    }
    void expr(const Expr &e)
    {
        if (e.kind == ExprKind::DirectAddress)
            address(e.text);
    }
    void decl(const VarDecl &v) { address(v.address); }
};

} // namespace

void Codegen::reserveProcessImage(const std::vector<const CompilationUnit *> &units)
{
    AddressScan scan;
    for (const CompilationUnit *u : units)
        walk(*u, scan);
    for (int area = 0; area < 3; ++area) {
        m_module->imageSizes[area] = scan.sizes[area];
        m_module->imageBase[area] = allocate(std::max<std::uint32_t>(scan.sizes[area], 1), 8);
    }
}

// The place of a located variable in the process image: the bytes at its address, or one bit.
Place Codegen::imagePlace(const ImageAddress &address, const Type *type, const QString &text)
{
    Place p;
    p.text = text;
    p.operand = m_module->imageBase[address.area == 'I' ? 0 : address.area == 'Q' ? 1 : 2] + address.byte;
    if (address.bit >= 0) {
        p.kind = Place::Kind::Bit;
        p.type = elem(Elem::Byte); // the byte that holds the bit, as for w.3
        p.bit = address.bit;
    } else {
        p.kind = Place::Kind::Direct;
        p.type = type;
    }
    return p;
}

// A located variable's initial value (q AT %QW0 : INT := 5) is the image's: copied there from
// the variable's own slot, where writeInitial put it.
void Codegen::initialiseImage(const ImageAddress &address, std::uint32_t slot, const Type *type)
{
    auto &image = m_module->initialImage;
    const std::uint32_t at = m_module->imageBase[address.area == 'I' ? 0 : address.area == 'Q' ? 1 : 2] + address.byte;
    if (address.bit >= 0) {
        if (image[slot] != 0)
            image[at] = static_cast<std::uint8_t>(image[at] | (1u << address.bit));
    } else if (type->size == address.size) {
        std::memcpy(image.data() + at, image.data() + slot, address.size);
    }
}

} // namespace iec::interp::detail
