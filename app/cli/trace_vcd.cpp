#include "app/cli/trace_vcd.h"

#include "interpreter/compiler/types.h"

#include <cstring>

namespace iec::cli {

namespace {

enum class VcdKind { Bit, Vector, Real, None };

VcdKind kindOf(const interp::VariableRef &ref)
{
    const interp::Type *type = ref.type;
    if (ref.bit >= 0)
        return VcdKind::Bit;
    if (!type || !type->isElementary())
        return VcdKind::None;
    if (type->kind == interp::TypeKind::Elementary && type->elem == interp::Elem::Bool)
        return VcdKind::Bit;
    return interp::info(type->elem).isReal && type->kind == interp::TypeKind::Elementary ? VcdKind::Real
                                                                                         : VcdKind::Vector;
}

// Identifier codes: printable ASCII from '!' to '~', as short as possible.
QString identifier(size_t index)
{
    QString code;
    do {
        code += QChar(char('!' + index % 94));
        index /= 94;
    } while (index > 0);
    return code;
}

const std::uint8_t *addressOf(const interp::VariableRef &ref, interp::Runtime &runtime)
{
    const std::uint8_t *base = ref.imageArea ? runtime.image(ref.imageArea).data() : runtime.vm().memory().data();
    return base + ref.offset;
}

std::uint64_t rawBits(const interp::VariableRef &ref, interp::Runtime &runtime)
{
    const std::uint8_t *p = addressOf(ref, runtime);
    if (ref.bit >= 0)
        return (p[ref.bit / 8] >> (ref.bit % 8)) & 1U;
    std::uint64_t bits = 0;
    std::memcpy(&bits, p, std::min<std::size_t>(ref.type->size, sizeof bits)); // little endian, as the VM
    return bits;
}

QString binary(std::uint64_t bits)
{
    return QString::number(bits, 2);
}

QString vcdValue(const interp::VariableRef &ref, interp::Runtime &runtime)
{
    switch (kindOf(ref)) {
    case VcdKind::Bit:
        return QString::number(rawBits(ref, runtime));
    case VcdKind::Vector:
        return QLatin1Char('b') + binary(rawBits(ref, runtime)) + QLatin1Char(' ');
    case VcdKind::Real: {
        const std::uint8_t *p = addressOf(ref, runtime);
        double value = 0;
        if (ref.type->size == 4) {
            float f = 0;
            std::memcpy(&f, p, sizeof f);
            value = f;
        } else {
            std::memcpy(&value, p, sizeof value);
        }
        return QLatin1Char('r') + QString::number(value, 'g', 17) + QLatin1Char(' ');
    }
    case VcdKind::None:
        break;
    }
    return QString();
}

QString declaration(const TracedVariable &variable, size_t index)
{
    const VcdKind kind = kindOf(variable.ref);
    const QString type = kind == VcdKind::Real ? QStringLiteral("real") : QStringLiteral("wire");
    // Reals are written as doubles whatever their IEC size; GTKWave expects `real 64`.
    const unsigned width = kind == VcdKind::Bit ? 1 : kind == VcdKind::Real ? 64 : variable.ref.type->size * 8;
    QString reference = variable.name;
    reference.replace(QLatin1Char(' '), QLatin1Char('_'));
    // Main.a[2] would read as bit 2 of a vector Main.a: an escaped identifier (IEEE 1364) keeps
    // the brackets part of the name, which GTKWave then shows as written.
    if (reference.contains(QLatin1Char('[')))
        reference.prepend(QLatin1Char('\\'));
    return QStringLiteral("$var %1 %2 %3 %4 $end\n").arg(type).arg(width).arg(identifier(index), reference);
}

} // namespace

bool vcdCanHold(const std::vector<TracedVariable> &variables, QString &error)
{
    for (const TracedVariable &variable : variables) {
        if (kindOf(variable.ref) == VcdKind::None) {
            error = QStringLiteral("%1 is a %2, which a VCD trace cannot show; trace it to a .csv file instead.")
                        .arg(variable.name, interp::typeName(variable.ref.type));
            return false;
        }
    }
    return true;
}

void VcdTrace::begin(interp::Runtime &runtime)
{
    m_nsPerUnit = runtime.cycleNs() % 1000 == 0 ? 1000 : 1;
    out() << "$version iecstudio-cli run $end\n";
    out() << "$timescale 1 " << (m_nsPerUnit == 1000 ? "us" : "ns") << " $end\n";
    out() << "$scope module iecstudio $end\n";
    for (size_t i = 0; i < variables().size(); ++i)
        out() << declaration(variables()[i], i);
    out() << "$upscope $end\n$enddefinitions $end\n#0\n$dumpvars\n";
    m_last.assign(variables().size(), QString());
    writeChanges(runtime);
    out() << "$end\n";
}

void VcdTrace::sample(int, interp::Runtime &runtime)
{
    out() << '#' << runtime.timeNs() / m_nsPerUnit << '\n';
    writeChanges(runtime);
}

void VcdTrace::writeChanges(interp::Runtime &runtime)
{
    for (size_t i = 0; i < variables().size(); ++i) {
        const QString value = vcdValue(variables()[i].ref, runtime);
        if (value == m_last[i])
            continue;
        m_last[i] = value;
        out() << value << identifier(i) << '\n';
    }
}

} // namespace iec::cli
