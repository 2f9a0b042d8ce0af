#pragma once

#include "interpreter/compiler/ast.h"
#include "interpreter/compiler/diagnostics.h"
#include "interpreter/vm/bytecode.h"

#include <QStringView>

#include <memory>
#include <vector>

class QRegularExpression;

namespace iec::interp {

struct CompileOptions {
    // The program a project without a configuration runs as its one cyclic task; empty: the only
    // PROGRAM, else PLC_PRG or Main, else the first.
    QString program;
    std::int64_t cycleNs = 10'000'000;
    // TON, TOF and TP run as C++ (op::NativeFb) instead of their ST code; both behave the same.
    bool nativeStandardBlocks = true;
};

// Compiles units of POUs, types, globals and configurations (the standard library is added) to
// bytecode. Returns nullptr when there are errors; every problem is in `diagnostics`.
std::shared_ptr<const Module> compile(const std::vector<const ast::CompilationUnit *> &units,
                                      Diagnostics &diagnostics, const CompileOptions &options = {});

// Parses and compiles IEC textual source.
std::shared_ptr<const Module> compileText(QStringView source, Diagnostics &diagnostics,
                                          const CompileOptions &options = {});

// The standard function blocks (SR, RS, R_TRIG, F_TRIG, CTU..., TP, TON, TOF), written in ST.
const ast::CompilationUnit &standardLibrary();

// The CoDeSys 2.3 Util blocks (BLINK, PID, ...) and Beremiz's RTC and LOGGER, written in ST; a
// project gets them when it names one (utilNamesUsed).
const ast::CompilationUnit &utilLibrary();
bool isUtilName(const QString &name);
bool utilNamesUsed(const std::vector<const ast::CompilationUnit *> &units);

// Whether `name` (any case) is a standard function the compiler knows: one of its table or a
// type conversion such as INT_TO_REAL or BCD_TO_WORD. Graphical blocks of these are called
// with positional arguments, as vendors name their pins differently.
bool isStandardFunctionName(const QString &name);
// The names of type conversions, upper case: FROM_TO_TO, TO_TO, FROM_TO_BCD, BCD_TO_TO, FROM_TRUNC_TO
// (captures: 1 the source type or empty, 2 the kind, 3 the target type).
const QRegularExpression &conversionNamePattern();

} // namespace iec::interp
