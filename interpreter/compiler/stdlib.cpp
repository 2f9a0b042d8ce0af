// The standard function blocks, written in ST and compiled with the user's program. Timers
// read the virtual clock through the intrinsic __SYSTIME(); the counters come in one version
// per integer type from one template. The bistables and counters also take the input names of
// CODESYS V2.3 (SR: SET1, RESET; RS: SET, RESET1; CTU/CTUD: RESET; CTD/CTUD: LOAD), which the
// editors propose, after the IEC inputs so positional calls keep the IEC order.
#include "interpreter/compiler/compiler.h"
#include "interpreter/compiler/parser.h"

namespace iec::interp {

namespace {

const char *const kBistables = R"(
FUNCTION_BLOCK SR
VAR_INPUT S1 : BOOL; R : BOOL; SET1 : BOOL; RESET : BOOL; END_VAR
VAR_OUTPUT Q1 : BOOL; END_VAR
Q1 := S1 OR SET1 OR (NOT (R OR RESET) AND Q1);
END_FUNCTION_BLOCK

FUNCTION_BLOCK RS
VAR_INPUT S : BOOL; R1 : BOOL; SET : BOOL; RESET1 : BOOL; END_VAR
VAR_OUTPUT Q1 : BOOL; END_VAR
Q1 := NOT (R1 OR RESET1) AND (S OR SET OR Q1);
END_FUNCTION_BLOCK

FUNCTION_BLOCK R_TRIG
VAR_INPUT CLK : BOOL; END_VAR
VAR_OUTPUT Q : BOOL; END_VAR
VAR M : BOOL; END_VAR
Q := CLK AND NOT M;
M := CLK;
END_FUNCTION_BLOCK

FUNCTION_BLOCK F_TRIG
VAR_INPUT CLK : BOOL; END_VAR
VAR_OUTPUT Q : BOOL; END_VAR
VAR M : BOOL := TRUE; END_VAR
Q := NOT CLK AND NOT M;
M := NOT CLK;
END_FUNCTION_BLOCK
)";

// Counters: %1 is the name suffix ("" or "_DINT"...), %2 the counter type, %3 its maximum,
// %4 its minimum. CU and CD count on rising edges (R_EDGE in the standard): in CTUD, a rising
// edge on both in the same call leaves CV unchanged, even while the other input stays TRUE.
const char *const kCounters = R"(
FUNCTION_BLOCK CTU%1
VAR_INPUT CU : BOOL; R : BOOL; PV : %2; RESET : BOOL; END_VAR
VAR_OUTPUT Q : BOOL; CV : %2; END_VAR
VAR M : BOOL; END_VAR
IF R OR RESET THEN
    CV := 0;
ELSIF CU AND NOT M AND CV < %3 THEN
    CV := CV + 1;
END_IF;
M := CU;
Q := CV >= PV;
END_FUNCTION_BLOCK

FUNCTION_BLOCK CTD%1
VAR_INPUT CD : BOOL; LD : BOOL; PV : %2; LOAD : BOOL; END_VAR
VAR_OUTPUT Q : BOOL; CV : %2; END_VAR
VAR M : BOOL; END_VAR
IF LD OR LOAD THEN
    CV := PV;
ELSIF CD AND NOT M AND CV > %4 THEN
    CV := CV - 1;
END_IF;
M := CD;
Q := CV <= 0;
END_FUNCTION_BLOCK

FUNCTION_BLOCK CTUD%1
VAR_INPUT CU : BOOL; CD : BOOL; R : BOOL; LD : BOOL; PV : %2; RESET : BOOL; LOAD : BOOL; END_VAR
VAR_OUTPUT QU : BOOL; QD : BOOL; CV : %2; END_VAR
VAR MU : BOOL; MD : BOOL; UP : BOOL; DOWN : BOOL; END_VAR
UP := CU AND NOT MU;
DOWN := CD AND NOT MD;
IF R OR RESET THEN
    CV := 0;
ELSIF LD OR LOAD THEN
    CV := PV;
ELSIF NOT (UP AND DOWN) THEN
    IF UP AND CV < %3 THEN
        CV := CV + 1;
    ELSIF DOWN AND CV > %4 THEN
        CV := CV - 1;
    END_IF;
END_IF;
MU := CU;
MD := CD;
QU := CV >= PV;
QD := CV <= 0;
END_FUNCTION_BLOCK
)";

// TON and TOF set their output in the call where the elapsed time reaches PT; TP's pulse lasts
// PT. ET counts from the call in which IN changed, so it is T#0s in that first call.
const char *const kTimers = R"(
FUNCTION_BLOCK TP
VAR_INPUT IN : BOOL; PT : TIME; END_VAR
VAR_OUTPUT Q : BOOL; ET : TIME; END_VAR
VAR START : TIME; TRIGGERED : BOOL; END_VAR
IF IN AND NOT Q AND NOT TRIGGERED THEN
    Q := TRUE;
    TRIGGERED := TRUE;
    START := __SYSTIME();
END_IF;
IF Q THEN
    ET := __SYSTIME() - START;
    IF ET >= PT THEN
        ET := PT;
        Q := FALSE;
    END_IF;
END_IF;
IF NOT IN AND NOT Q THEN
    ET := T#0s;
    TRIGGERED := FALSE;
END_IF;
END_FUNCTION_BLOCK

FUNCTION_BLOCK TON
VAR_INPUT IN : BOOL; PT : TIME; END_VAR
VAR_OUTPUT Q : BOOL; ET : TIME; END_VAR
VAR START : TIME; RUNNING : BOOL; END_VAR
IF IN THEN
    IF NOT RUNNING THEN
        RUNNING := TRUE;
        START := __SYSTIME();
    END_IF;
    IF NOT Q THEN
        ET := __SYSTIME() - START;
        IF ET >= PT THEN
            ET := PT;
            Q := TRUE;
        END_IF;
    END_IF;
ELSE
    RUNNING := FALSE;
    Q := FALSE;
    ET := T#0s;
END_IF;
END_FUNCTION_BLOCK

FUNCTION_BLOCK TOF
VAR_INPUT IN : BOOL; PT : TIME; END_VAR
VAR_OUTPUT Q : BOOL; ET : TIME; END_VAR
VAR START : TIME; RUNNING : BOOL; END_VAR
IF IN THEN
    Q := TRUE;
    ET := T#0s;
    RUNNING := FALSE;
ELSIF Q THEN
    IF NOT RUNNING THEN
        RUNNING := TRUE;
        START := __SYSTIME();
    END_IF;
    ET := __SYSTIME() - START;
    IF ET >= PT THEN
        ET := PT;
        Q := FALSE;
    END_IF;
END_IF;
END_FUNCTION_BLOCK
)";

QString librarySource()
{
    QString source = QLatin1String(kBistables) + QLatin1String(kTimers);
    struct Counter {
        const char *suffix, *type, *max, *min;
    };
    static const Counter counters[] = {
        {"", "INT", "32767", "-32768"},
        {"_INT", "INT", "32767", "-32768"}, // the typed names of IEC 61131-3 ed. 3
        {"_DINT", "DINT", "2147483647", "-2147483648"},
        {"_LINT", "LINT", "9223372036854775807", "-9223372036854775807"},
        {"_UDINT", "UDINT", "4294967295", "0"},
        {"_ULINT", "ULINT", "18446744073709551615", "0"},
    };
    for (const Counter &c : counters)
        source += QString::fromLatin1(kCounters).arg(QLatin1String(c.suffix), QLatin1String(c.type), QLatin1String(c.max), QLatin1String(c.min));
    return source;
}

} // namespace

const ast::CompilationUnit &standardLibrary()
{
    static const ast::CompilationUnit unit = [] {
        Diagnostics diagnostics;
        const QString source = librarySource();
        ast::CompilationUnit parsed = parseUnit(source, diagnostics);
        Q_ASSERT(!diagnostics.hasErrors());
        return parsed;
    }();
    return unit;
}

} // namespace iec::interp
