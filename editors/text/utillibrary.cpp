#include "editors/text/utillibrary.h"

#include "interpreter/compiler/ast.h"
#include "interpreter/compiler/compiler.h"
#include "interpreter/frontend/iecprinter.h"
#include "interpreter/frontend/iecreader.h"

#include <QCoreApplication>

namespace iec::editors {

namespace {

struct UtilEntry {
    const char *name;
    StdPou::Category category;
    const char *description;
    const char *library = "Util";
};

// Grouped as CODESYS's Util library groups them; descriptions follow docs/stdlib.md.
const UtilEntry *findEntry(const QString &name)
{
    using C = StdPou::Category;
    static const UtilEntry entries[] = {
        {"BCD_TO_INT", C::BcdConversion,
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "The two BCD digits of B as a number; -1 when a digit is not 0 to 9.")},
        {"INT_TO_BCD", C::BcdConversion,
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "I as two BCD digits; 255 when I is not 0 to 99.")},
        {"EXTRACT", C::BitByte, QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Bit N of X (bit 0 first).")},
        {"PACK", C::BitByte, QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "The eight inputs as the bits of a byte, B0 lowest.")},
        {"PUTBIT", C::BitByte, QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "X with bit N set to B.")},
        {"UNPACK", C::BitByte, QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "The eight bits of B as outputs B0 to B7.")},
        {"DERIVATIVE", C::MathAuxiliary,
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "The slope of IN per second; TM is the time since the last call in ms.")},
        {"INTEGRAL", C::MathAuxiliary,
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Sums IN over time; TM is the time since the last call in ms.")},
        {"LIN_TRAFO", C::MathAuxiliary,
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Maps IN linearly from IN_MIN..IN_MAX to OUT_MIN..OUT_MAX.")},
        {"STATISTICS_INT", C::MathAuxiliary,
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Minimum, maximum and average of the INT values since RESET.")},
        {"STATISTICS_REAL", C::MathAuxiliary,
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Minimum, maximum and average of the REAL values since RESET.")},
        {"VARIANCE", C::MathAuxiliary, QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "The variance of the values since RESET.")},
        {"PD", C::Controller, QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "PD controller: Y from the error SET_POINT - ACTUAL.")},
        {"PID", C::Controller, QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "PID controller: Y from the error SET_POINT - ACTUAL.")},
        {"PID_FIXCYCLE", C::Controller,
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "PID controller for a fixed cycle of CYCLE seconds.")},
        {"BLINK", C::SignalGenerator,
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "While ENABLE, OUT is TRUE for TIMEHIGH, then FALSE for TIMELOW, and so on.")},
        {"GEN", C::SignalGenerator,
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "A periodic signal of the shape MODE (triangle, sawtooth, rectangle, sine).")},
        {"CHARCURVE", C::FunctionManipulator,
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "OUT on the characteristic curve through the points P.")},
        {"RAMP_INT", C::FunctionManipulator,
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "OUT follows IN, rising by ASCEND and falling by DESCEND at most per TIMEBASE.")},
        {"RAMP_REAL", C::FunctionManipulator,
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "OUT follows IN, rising by ASCEND and falling by DESCEND at most per TIMEBASE.")},
        {"HYSTERESIS", C::AnalogValue,
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "OUT becomes TRUE below LOW and FALSE above HIGH.")},
        {"LIMITALARM", C::AnalogValue,
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "O when IN is above HIGH, U when below LOW, IL when in between.")},
        {"RTC", C::Timer, QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Real-time clock: CDT runs on from PDT while IN is TRUE."),
            "Beremiz"},
        {"LOGGER", C::Messages,
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "On a rising edge of TRIG, writes MSG to the messages pane."), "Beremiz"},
    };
    for (const UtilEntry &entry : entries) {
        if (name.compare(QLatin1String(entry.name), Qt::CaseInsensitive) == 0)
            return &entry;
    }
    return nullptr;
}

QString typeText(const interp::ast::TypeSpec &type)
{
    return interp::frontend::printDataType(interp::frontend::dataTypeFromAst(type));
}

StdPou fromDefinition(const interp::ast::Pou &pou, const UtilEntry &entry)
{
    StdPou result {pou.name, pou.kind == interp::ast::PouKind::Function ? StdPou::Kind::Function : StdPou::Kind::FunctionBlock,
        entry.category, {}, {}, {}, entry.description, QString::fromLatin1(entry.library)};
    for (const interp::ast::VarSection &section : pou.sections) {
        const bool input = section.kind == interp::ast::VarKind::Input || section.kind == interp::ast::VarKind::InOut;
        if (!input && section.kind != interp::ast::VarKind::Output)
            continue;
        for (const interp::ast::VarDecl &variable : section.vars)
            (input ? result.inputs : result.outputs).append({variable.name, typeText(variable.type)});
    }
    if (pou.returnType)
        result.returnType = typeText(*pou.returnType);
    return result;
}

} // namespace

QList<StdPou> utilLibraryPous()
{
    // Compiled inline (stdfunctions.cpp), so not among the definitions.
    const auto bcd = [](const QString &name, const QString &input, const QString &from, const QString &to) {
        const UtilEntry *entry = findEntry(name);
        return StdPou {name, StdPou::Kind::Function, entry->category, {{input, from}}, {}, to, entry->description,
            QString::fromLatin1(entry->library)};
    };
    QList<StdPou> pous = {bcd(QStringLiteral("BCD_TO_INT"), QStringLiteral("B"), QStringLiteral("BYTE"), QStringLiteral("INT")),
        bcd(QStringLiteral("INT_TO_BCD"), QStringLiteral("I"), QStringLiteral("INT"), QStringLiteral("BYTE"))};
    for (const interp::ast::Pou &pou : interp::utilLibrary().pous) {
        if (const UtilEntry *entry = findEntry(pou.name))
            pous.append(fromDefinition(pou, *entry));
    }
    return pous;
}

} // namespace iec::editors
