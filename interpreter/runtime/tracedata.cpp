#include "interpreter/runtime/tracedata.h"

#include "interpreter/compiler/types.h"
#include "interpreter/runtime/runtime.h"

#include <QCoreApplication>

#include <cstring>

namespace iec::interp {

namespace {

// The ref as it reads a row's slot: the value at offset 0, a bit within the slot's first byte.
VariableRef slotRef(const VariableRef &ref)
{
    VariableRef slot = ref;
    slot.offset = 0;
    slot.imageArea = 0;
    if (ref.bit >= 0)
        slot.bit = ref.bit % 8;
    return slot;
}

const std::uint8_t *slotOf(const TraceRow &row, std::size_t index)
{
    return row.bytes.data() + index * TraceRow::kTraceSlot;
}

} // namespace

bool isTraceable(const VariableRef &ref)
{
    if (ref.bit >= 0)
        return true;
    return ref.type && ref.type->isElementary() && ref.type->size <= TraceRow::kTraceSlot;
}

bool isBoolean(const VariableRef &ref)
{
    return ref.bit >= 0 || (ref.type && ref.type->kind == TypeKind::Elementary && ref.type->elem == Elem::Bool);
}

QString notTraceableReason(const TraceVariable &variable)
{
    return QCoreApplication::translate("iec::interp::Trace",
                                       "%1 is a %2: only BOOL, numbers, bit strings, enumerations, times and dates "
                                       "can be traced. Trace its elements or members instead.")
        .arg(variable.name, typeName(variable.ref.type));
}

TraceRow captureRow(const Runtime &runtime, const std::vector<TraceVariable> &variables)
{
    TraceRow row;
    row.cycle = runtime.cycle();
    row.timeNs = runtime.timeNs();
    row.bytes.assign(variables.size() * TraceRow::kTraceSlot, 0);
    for (std::size_t i = 0; i < variables.size(); ++i) {
        const VariableRef &ref = variables[i].ref;
        const std::vector<std::uint8_t> &source = ref.imageArea ? runtime.image(ref.imageArea) : runtime.vm().memory();
        const std::size_t offset = ref.offset + (ref.bit >= 0 ? std::size_t(ref.bit / 8) : 0);
        const std::size_t size = ref.bit >= 0 ? 1 : std::min<std::size_t>(ref.type->size, TraceRow::kTraceSlot);
        if (offset + size <= source.size())
            std::memcpy(row.bytes.data() + i * TraceRow::kTraceSlot, source.data() + offset, size);
    }
    return row;
}

QString rowLiteral(const TraceRow &row, std::size_t index, const VariableRef &ref)
{
    const std::uint8_t *slot = slotOf(row, index);
    return formatValue(slotRef(ref), slot, slot);
}

std::uint64_t rowBits(const TraceRow &row, std::size_t index, const VariableRef &ref)
{
    const std::uint8_t *slot = slotOf(row, index);
    if (ref.bit >= 0)
        return (slot[0] >> (ref.bit % 8)) & 1U;
    std::uint64_t bits = 0;
    std::memcpy(&bits, slot, std::min<std::size_t>(ref.type->size, sizeof bits));
    return bits;
}

double rowNumber(const TraceRow &row, std::size_t index, const VariableRef &ref)
{
    const std::uint64_t bits = rowBits(row, index, ref);
    if (ref.bit >= 0)
        return double(bits);
    const ElemInfo &elem = info(ref.type->elem);
    if (elem.isReal && ref.type->kind == TypeKind::Elementary) {
        if (ref.type->size == 4) {
            float f = 0;
            std::memcpy(&f, &bits, sizeof f);
            return f;
        }
        double d = 0;
        std::memcpy(&d, &bits, sizeof d);
        return d;
    }
    const unsigned width = ref.type->size * 8;
    if (elem.isTimeLike)
        return double(std::int64_t(bits)) / 1e6;
    if (elem.isUnsigned || elem.isBit || width >= 64)
        return width >= 64 && !elem.isUnsigned && !elem.isBit ? double(std::int64_t(bits)) : double(bits);
    // Signed: extend the sign of the value's width.
    const std::uint64_t sign = std::uint64_t(1) << (width - 1);
    return double(std::int64_t((bits ^ sign) - sign));
}

} // namespace iec::interp
