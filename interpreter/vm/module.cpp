#include "interpreter/vm/bytecode.h"

#include <QCoreApplication>

namespace iec::interp {

QString faultMessage(FaultKind kind)
{
    switch (kind) {
    case FaultKind::None: return {};
    case FaultKind::DivisionByZero: return QCoreApplication::translate("iec::interp::Runtime", "Integer division by zero.");
    case FaultKind::IndexOutOfRange: return QCoreApplication::translate("iec::interp::Runtime", "Array index out of range.");
    case FaultKind::StringOverflow: return QCoreApplication::translate("iec::interp::Runtime", "The text does not fit into the string variable.");
    case FaultKind::BudgetExceeded:
        return QCoreApplication::translate("iec::interp::Runtime", "The program ran too long in one cycle; is there an endless loop?");
    case FaultKind::CallDepthExceeded: return QCoreApplication::translate("iec::interp::Runtime", "Calls are nested too deeply.");
    case FaultKind::InvalidProgram: return QCoreApplication::translate("iec::interp::Runtime", "The program cannot run (it did not compile).");
    case FaultKind::OutOfSubrange:
        return QCoreApplication::translate("iec::interp::Runtime", "A value outside the subrange of its type was assigned.");
    case FaultKind::NullPointer:
        return QCoreApplication::translate("iec::interp::Runtime", "A pointer or reference that points nowhere (0) was used.");
    case FaultKind::InvalidAddress:
        return QCoreApplication::translate("iec::interp::Runtime", "A pointer that points outside the program's memory was used.");
    case FaultKind::Halted: return QCoreApplication::translate("iec::interp::Runtime", "The program halted.");
    }
    return {};
}

LineEntry Module::lineAt(std::uint32_t pc) const
{
    LineEntry found;
    // Entries are in pc order; the last one at or before pc is the line of pc.
    size_t lo = 0, hi = lines.size();
    while (lo < hi) {
        const size_t mid = (lo + hi) / 2;
        if (lines[mid].pc <= pc)
            lo = mid + 1;
        else
            hi = mid;
    }
    if (lo > 0)
        found = lines[lo - 1];
    return found;
}

} // namespace iec::interp
