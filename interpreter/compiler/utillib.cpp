// The CoDeSys 2.3 Util library blocks and functions students meet, and the two Beremiz blocks
// its own example projects use (RTC, LOGGER), written in ST with the names and pins of their
// originals (docs/stdlib.md gives the source of each definition and where ours is our own
// reading of a behaviour the documentation does not pin down). Time comes from the virtual clock
// (__SYSTIME). A project gets them only when it names one of them (utilNamesUsed), so projects
// without them compile no faster or slower than before.
#include "interpreter/compiler/astwalk.h"
#include "interpreter/compiler/compiler.h"
#include "interpreter/compiler/parser.h"

#include <QSet>

namespace iec::interp {

namespace {

const char *const kUtilTypes = R"(
TYPE GEN_MODE : (TRIANGLE, TRIANGLE_POS, SAWTOOTH_RISE, SAWTOOTH_FALL, RECTANGLE, SINUS, COSINUS); END_TYPE
TYPE POINT : STRUCT X : INT; Y : INT; END_STRUCT; END_TYPE
TYPE LOGLEVEL : (CRITICAL, WARNING, INFO, DEBUG) := INFO; END_TYPE
)";

const char *const kBits = R"(
FUNCTION EXTRACT : BOOL
VAR_INPUT X : DWORD; N : BYTE; END_VAR
EXTRACT := (SHR(X, N) AND DWORD#1) <> 0;
END_FUNCTION

FUNCTION PACK : BYTE
VAR_INPUT B0 : BOOL; B1 : BOOL; B2 : BOOL; B3 : BOOL; B4 : BOOL; B5 : BOOL; B6 : BOOL; B7 : BOOL; END_VAR
PACK := 0;
PACK.0 := B0; PACK.1 := B1; PACK.2 := B2; PACK.3 := B3;
PACK.4 := B4; PACK.5 := B5; PACK.6 := B6; PACK.7 := B7;
END_FUNCTION

FUNCTION PUTBIT : DWORD
VAR_INPUT X : DWORD; N : BYTE; B : BOOL; END_VAR
IF B THEN
    PUTBIT := X OR SHL(DWORD#1, N);
ELSE
    PUTBIT := X AND NOT SHL(DWORD#1, N);
END_IF;
END_FUNCTION

FUNCTION_BLOCK UNPACK
VAR_INPUT B : BYTE; END_VAR
VAR_OUTPUT B0 : BOOL; B1 : BOOL; B2 : BOOL; B3 : BOOL; B4 : BOOL; B5 : BOOL; B6 : BOOL; B7 : BOOL; END_VAR
B0 := B.0; B1 := B.1; B2 := B.2; B3 := B.3; B4 := B.4; B5 := B.5; B6 := B.6; B7 := B.7;
END_FUNCTION_BLOCK
)";

const char *const kSignals = R"(
FUNCTION_BLOCK HYSTERESIS
VAR_INPUT IN : INT; HIGH : INT; LOW : INT; END_VAR
VAR_OUTPUT OUT : BOOL; END_VAR
IF IN < LOW THEN
    OUT := TRUE;
ELSIF IN > HIGH THEN
    OUT := FALSE;
END_IF;
END_FUNCTION_BLOCK

FUNCTION_BLOCK LIMITALARM
VAR_INPUT IN : INT; HIGH : INT; LOW : INT; END_VAR
VAR_OUTPUT O : BOOL; U : BOOL; IL : BOOL; END_VAR
O := IN > HIGH;
U := IN < LOW;
IL := NOT (O OR U);
END_FUNCTION_BLOCK

(* OUT is TRUE for TIMEHIGH from the call in which ENABLE becomes TRUE, then FALSE for TIMELOW,
   and so on; with ENABLE FALSE it keeps its value. *)
FUNCTION_BLOCK BLINK
VAR_INPUT ENABLE : BOOL; TIMELOW : TIME; TIMEHIGH : TIME; END_VAR
VAR_OUTPUT OUT : BOOL; END_VAR
VAR RUNNING : BOOL; PHASE_START : TIME; NOW : TIME; END_VAR
IF ENABLE THEN
    NOW := __SYSTIME();
    IF NOT RUNNING THEN
        RUNNING := TRUE;
        OUT := TRUE;
        PHASE_START := NOW;
    ELSIF OUT AND NOW - PHASE_START >= TIMEHIGH THEN
        OUT := FALSE;
        PHASE_START := NOW;
    ELSIF NOT OUT AND NOW - PHASE_START >= TIMELOW THEN
        OUT := TRUE;
        PHASE_START := NOW;
    END_IF;
ELSE
    RUNNING := FALSE;
END_IF;
END_FUNCTION_BLOCK

(* A period of PERIOD (BASE TRUE) or of CYCLES calls (BASE FALSE), from -AMPLITUDE to AMPLITUDE
   (TRIANGLE_POS: 0 to AMPLITUDE); RESET starts a new period. *)
FUNCTION_BLOCK GEN
VAR_INPUT MODE : GEN_MODE; BASE : BOOL; PERIOD : TIME := T#1s; CYCLES : INT := 10; AMPLITUDE : INT := 100; RESET : BOOL; END_VAR
VAR_OUTPUT OUT : INT; END_VAR
VAR START : TIME; CALLS : DINT; STARTED : BOOL; PHASE : LREAL; A : LREAL; END_VAR
IF RESET OR NOT STARTED THEN
    START := __SYSTIME();
    CALLS := 0;
    STARTED := TRUE;
END_IF;
IF BASE THEN
    IF PERIOD > T#0s THEN
        PHASE := LINT_TO_LREAL(TIME_TO_LINT(__SYSTIME() - START) MOD TIME_TO_LINT(PERIOD)) / TIME_TO_LREAL(PERIOD);
    ELSE
        PHASE := 0.0;
    END_IF;
ELSIF CYCLES > 0 THEN
    PHASE := DINT_TO_LREAL(CALLS MOD CYCLES) / INT_TO_LREAL(CYCLES);
ELSE
    PHASE := 0.0;
END_IF;
CALLS := CALLS + 1;
A := INT_TO_LREAL(AMPLITUDE);
CASE MODE OF
TRIANGLE:
    IF PHASE < 0.5 THEN OUT := LREAL_TO_INT(-A + 4.0 * A * PHASE); ELSE OUT := LREAL_TO_INT(3.0 * A - 4.0 * A * PHASE); END_IF;
TRIANGLE_POS:
    IF PHASE < 0.5 THEN OUT := LREAL_TO_INT(2.0 * A * PHASE); ELSE OUT := LREAL_TO_INT(2.0 * A * (1.0 - PHASE)); END_IF;
SAWTOOTH_RISE:
    OUT := LREAL_TO_INT(-A + 2.0 * A * PHASE);
SAWTOOTH_FALL:
    OUT := LREAL_TO_INT(A - 2.0 * A * PHASE);
RECTANGLE:
    IF PHASE < 0.5 THEN OUT := AMPLITUDE; ELSE OUT := -AMPLITUDE; END_IF;
SINUS:
    OUT := LREAL_TO_INT(A * SIN(6.283185307179586 * PHASE));
COSINUS:
    OUT := LREAL_TO_INT(A * COS(6.283185307179586 * PHASE));
END_CASE;
END_FUNCTION_BLOCK
)";

const char *const kMath = R"(
FUNCTION_BLOCK LIN_TRAFO
VAR_INPUT IN : REAL; IN_MIN : REAL; IN_MAX : REAL; OUT_MIN : REAL; OUT_MAX : REAL; END_VAR
VAR_OUTPUT OUT : REAL; ERROR : BOOL; END_VAR
IF IN_MIN = IN_MAX THEN
    ERROR := TRUE;
    OUT := OUT_MIN;
ELSE
    ERROR := FALSE;
    OUT := (IN - IN_MIN) * (OUT_MAX - OUT_MIN) / (IN_MAX - IN_MIN) + OUT_MIN;
END_IF;
END_FUNCTION_BLOCK

(* TM: milliseconds since the last call. The slope over the last four values (x0 newest):
   (x0 + 3 x1 - 3 x2 - x3) / (6 h), h the mean of the last three intervals, in units per second. *)
FUNCTION_BLOCK DERIVATIVE
VAR_INPUT IN : REAL; TM : DWORD; RESET : BOOL; END_VAR
VAR_OUTPUT OUT : REAL; END_VAR
VAR X1 : REAL; X2 : REAL; X3 : REAL; T1 : DWORD; T2 : DWORD; INIT : BOOL; SPAN : REAL; END_VAR
IF RESET OR NOT INIT THEN
    X1 := IN; X2 := IN; X3 := IN;
    T1 := TM; T2 := TM;
    OUT := 0.0;
    INIT := TRUE;
ELSE
    SPAN := DWORD_TO_REAL(TM) + DWORD_TO_REAL(T1) + DWORD_TO_REAL(T2);
    IF SPAN > 0.0 THEN
        OUT := (IN + 3.0 * X1 - 3.0 * X2 - X3) * 1000.0 / (2.0 * SPAN);
    END_IF;
    X3 := X2; X2 := X1; X1 := IN;
    T2 := T1; T1 := TM;
END_IF;
END_FUNCTION_BLOCK

(* TM: milliseconds since the last call; OUT is the integral over time in seconds. *)
FUNCTION_BLOCK INTEGRAL
VAR_INPUT IN : REAL; TM : DWORD; RESET : BOOL; END_VAR
VAR_OUTPUT OUT : REAL; OVERFLOW : BOOL; END_VAR
VAR NEXT : LREAL; END_VAR
IF RESET THEN
    OUT := 0.0;
    OVERFLOW := FALSE;
ELSIF NOT OVERFLOW THEN
    NEXT := REAL_TO_LREAL(OUT) + REAL_TO_LREAL(IN) * DWORD_TO_LREAL(TM) / 1000.0;
    IF ABS(NEXT) > 3.402823466E38 THEN
        OVERFLOW := TRUE;
    ELSE
        OUT := LREAL_TO_REAL(NEXT);
    END_IF;
END_IF;
END_FUNCTION_BLOCK

FUNCTION_BLOCK STATISTICS_INT
VAR_INPUT IN : INT; RESET : BOOL; END_VAR
VAR_OUTPUT MN : INT := 32767; MX : INT := -32768; AVG : INT; END_VAR
VAR SUM : LINT; COUNT : LINT; END_VAR
IF RESET THEN
    SUM := 0; COUNT := 0; MN := 32767; MX := -32768; AVG := 0;
ELSE
    IF IN < MN THEN MN := IN; END_IF;
    IF IN > MX THEN MX := IN; END_IF;
    SUM := SUM + IN;
    COUNT := COUNT + 1;
    AVG := LINT_TO_INT(SUM / COUNT);
END_IF;
END_FUNCTION_BLOCK

FUNCTION_BLOCK STATISTICS_REAL
VAR_INPUT IN : REAL; RESET : BOOL; END_VAR
VAR_OUTPUT MN : REAL := 3.402823466E38; MX : REAL := -3.402823466E38; AVG : REAL; END_VAR
VAR SUM : LREAL; COUNT : LINT; END_VAR
IF RESET THEN
    SUM := 0.0; COUNT := 0; MN := 3.402823466E38; MX := -3.402823466E38; AVG := 0.0;
ELSE
    IF IN < MN THEN MN := IN; END_IF;
    IF IN > MX THEN MX := IN; END_IF;
    SUM := SUM + REAL_TO_LREAL(IN);
    COUNT := COUNT + 1;
    AVG := LREAL_TO_REAL(SUM / LINT_TO_LREAL(COUNT));
END_IF;
END_FUNCTION_BLOCK

(* The variance of the values since RESET: the mean of their squared distances to their mean. *)
FUNCTION_BLOCK VARIANCE
VAR_INPUT IN : REAL; RESET : BOOL; END_VAR
VAR_OUTPUT OUT : REAL; END_VAR
VAR COUNT : LINT; MEAN : LREAL; M2 : LREAL; DELTA : LREAL; END_VAR
IF RESET THEN
    COUNT := 0; MEAN := 0.0; M2 := 0.0; OUT := 0.0;
ELSE
    COUNT := COUNT + 1;
    DELTA := REAL_TO_LREAL(IN) - MEAN;
    MEAN := MEAN + DELTA / LINT_TO_LREAL(COUNT);
    M2 := M2 + DELTA * (REAL_TO_LREAL(IN) - MEAN);
    OUT := LREAL_TO_REAL(M2 / LINT_TO_LREAL(COUNT));
END_IF;
END_FUNCTION_BLOCK

(* A characteristic curve through N points P[0..N-1] (X rising): OUT on the line between the two
   points around IN. ERR 1: the X values do not rise; 2: IN outside P[0].X .. P[N-1].X (OUT is the
   nearest end); 4: N outside 2..11. *)
FUNCTION_BLOCK CHARCURVE
VAR_INPUT IN : INT; N : BYTE; END_VAR
VAR_IN_OUT P : ARRAY[0..10] OF POINT; END_VAR
VAR_OUTPUT OUT : INT; ERR : BYTE; END_VAR
VAR I : INT; LAST : INT; END_VAR
ERR := 0;
IF N < 2 OR N > 11 THEN
    ERR := 4;
    RETURN;
END_IF;
LAST := BYTE_TO_INT(N) - 1;
FOR I := 1 TO LAST DO
    IF P[I].X <= P[I - 1].X THEN
        ERR := 1;
        RETURN;
    END_IF;
END_FOR;
IF IN < P[0].X THEN
    ERR := 2;
    OUT := P[0].Y;
ELSIF IN > P[LAST].X THEN
    ERR := 2;
    OUT := P[LAST].Y;
ELSE
    I := 1;
    WHILE I < LAST AND IN > P[I].X DO
        I := I + 1;
    END_WHILE;
    OUT := DINT_TO_INT(INT_TO_DINT(P[I - 1].Y) + (INT_TO_DINT(IN) - INT_TO_DINT(P[I - 1].X)) * (INT_TO_DINT(P[I].Y) - INT_TO_DINT(P[I - 1].Y))
        / (INT_TO_DINT(P[I].X) - INT_TO_DINT(P[I - 1].X)));
END_IF;
END_FUNCTION_BLOCK
)";

// The ramps follow IN, rising by at most ASCEND and falling by at most DESCEND per TIMEBASE (per
// call when TIMEBASE is T#0s). %1 is the suffix, %2 the value type.
const char *const kRamp = R"(
FUNCTION_BLOCK RAMP_%1
VAR_INPUT IN : %2; ASCEND : %2; DESCEND : %2; TIMEBASE : TIME; RESET : BOOL; END_VAR
VAR_OUTPUT OUT : %2; END_VAR
VAR VALUE : LREAL; LAST : TIME; STARTED : BOOL; STEPS : LREAL; TARGET : LREAL; END_VAR
IF RESET OR NOT STARTED THEN
    VALUE := TO_LREAL(IN);
    STARTED := TRUE;
ELSE
    IF TIMEBASE > T#0s THEN
        STEPS := TIME_TO_LREAL(__SYSTIME() - LAST) / TIME_TO_LREAL(TIMEBASE);
    ELSE
        STEPS := 1.0;
    END_IF;
    TARGET := TO_LREAL(IN);
    IF TARGET > VALUE THEN
        VALUE := MIN(TARGET, VALUE + TO_LREAL(ASCEND) * STEPS);
    ELSIF TARGET < VALUE THEN
        VALUE := MAX(TARGET, VALUE - TO_LREAL(DESCEND) * STEPS);
    END_IF;
END_IF;
LAST := __SYSTIME();
OUT := LREAL_TO_%1(VALUE);
END_FUNCTION_BLOCK
)";

// PD, PID and PID_FIXCYCLE: Y = KP * (E + 1/TN * integral of E dt + TV * dE/dt) + Y_OFFSET with
// E = SET_POINT - ACTUAL and t in seconds, limited to Y_MIN..Y_MAX (when Y_MIN < Y_MAX; the
// integral then stops growing, LIMITS_ACTIVE is TRUE). MANUAL: Y := Y_MANUAL. RESET clears the
// integral. %1: name, %2: extra inputs, %3: how dt is found, %4: the integral part, %5 and %6:
// where OVERFLOW is declared (an output of PID and PID_FIXCYCLE; PD has no such pin), %7: inputs
// after RESET (PID_FIXCYCLE's CYCLE is its last pin, as in CODESYS).
const char *const kController = R"(
FUNCTION_BLOCK %1
VAR_INPUT ACTUAL : REAL; SET_POINT : REAL; KP : REAL; %2 TV : REAL; Y_MANUAL : REAL; Y_OFFSET : REAL;
    Y_MIN : REAL; Y_MAX : REAL; MANUAL : BOOL; RESET : BOOL; %7 END_VAR
VAR_OUTPUT Y : REAL; LIMITS_ACTIVE : BOOL := FALSE; %5 END_VAR
VAR %6 I : LREAL; NEXT_I : LREAL; LAST_E : LREAL; E : LREAL; DTS : LREAL; DPART : LREAL; OUTV : LREAL; LAST : TIME; STARTED : BOOL; END_VAR
E := REAL_TO_LREAL(SET_POINT) - REAL_TO_LREAL(ACTUAL);
IF RESET OR NOT STARTED THEN
    I := 0.0;
    LAST_E := E;
    OVERFLOW := FALSE;
    STARTED := TRUE;
    DTS := 0.0;
ELSE
    %3
END_IF;
LAST := __SYSTIME();
IF MANUAL THEN
    Y := Y_MANUAL;
    LIMITS_ACTIVE := FALSE;
ELSIF NOT OVERFLOW THEN
    DPART := 0.0;
    IF DTS > 0.0 THEN
        DPART := REAL_TO_LREAL(TV) * (E - LAST_E) / DTS;
    END_IF;
    NEXT_I := I;
    %4
    IF ABS(NEXT_I) > 3.402823466E38 THEN
        OVERFLOW := TRUE;
    ELSE
        OUTV := REAL_TO_LREAL(KP) * (E + NEXT_I + DPART) + REAL_TO_LREAL(Y_OFFSET);
        LIMITS_ACTIVE := FALSE;
        IF Y_MIN < Y_MAX THEN
            IF OUTV > REAL_TO_LREAL(Y_MAX) THEN
                OUTV := REAL_TO_LREAL(Y_MAX);
                LIMITS_ACTIVE := TRUE;
            ELSIF OUTV < REAL_TO_LREAL(Y_MIN) THEN
                OUTV := REAL_TO_LREAL(Y_MIN);
                LIMITS_ACTIVE := TRUE;
            END_IF;
        END_IF;
        IF NOT LIMITS_ACTIVE THEN
            I := NEXT_I;
        END_IF;
        Y := LREAL_TO_REAL(OUTV);
    END_IF;
END_IF;
LAST_E := E;
END_FUNCTION_BLOCK
)";

// Beremiz: RTC gives the date and time of the (virtual) clock, which starts at DT#1970-01-01-00:00:00;
// while IN is TRUE it counts on from PDT, set on IN's rising edge. LOGGER writes MSG on a rising
// edge of TRIG to the messages pane and the command line's stderr.
const char *const kBeremiz = R"(
FUNCTION_BLOCK RTC
VAR_INPUT IN : BOOL; PDT : DT; END_VAR
VAR_OUTPUT Q : BOOL; CDT : DT; END_VAR
VAR PREV_IN : BOOL; OFFSET : TIME; NOW : DT; END_VAR
NOW := DT#1970-01-01-00:00:00 + __SYSTIME();
IF IN THEN
    IF NOT PREV_IN THEN
        OFFSET := PDT - NOW;
    END_IF;
    CDT := NOW + OFFSET;
ELSE
    CDT := NOW;
END_IF;
Q := IN;
PREV_IN := IN;
END_FUNCTION_BLOCK

FUNCTION_BLOCK LOGGER
VAR_INPUT TRIG : BOOL; MSG : STRING; LEVEL : LOGLEVEL := INFO; END_VAR
VAR TRIG0 : BOOL; END_VAR
IF TRIG AND NOT TRIG0 THEN
    __LOG(LEVEL, MSG);
END_IF;
TRIG0 := TRIG;
END_FUNCTION_BLOCK
)";

QString utilSource()
{
    QString text = QLatin1String(kUtilTypes) + QLatin1String(kBits) + QLatin1String(kSignals) + QLatin1String(kMath);
    text += QString::fromLatin1(kRamp).arg(QStringLiteral("INT"), QStringLiteral("INT"));
    text += QString::fromLatin1(kRamp).arg(QStringLiteral("REAL"), QStringLiteral("REAL"));
    const QString measured = QStringLiteral("DTS := TIME_TO_LREAL(__SYSTIME() - LAST) / 1000.0;");
    const QString integral = QStringLiteral("IF TN > 0.0 THEN NEXT_I := I + E * DTS / REAL_TO_LREAL(TN); END_IF;");
    const QString overflow = QStringLiteral("OVERFLOW : BOOL := FALSE;");
    text += QString::fromLatin1(kController).arg(QStringLiteral("PD"), QString(), measured, QString(), QString(), overflow, QString());
    text += QString::fromLatin1(kController)
                .arg(QStringLiteral("PID"), QStringLiteral("TN : REAL;"), measured, integral, overflow, QString(), QString());
    text += QString::fromLatin1(kController)
                .arg(QStringLiteral("PID_FIXCYCLE"), QStringLiteral("TN : REAL;"), QStringLiteral("DTS := REAL_TO_LREAL(CYCLE);"),
                    integral, overflow, QString(), QStringLiteral("CYCLE : REAL;"));
    return text + QLatin1String(kBeremiz);
}

} // namespace

const ast::CompilationUnit &utilLibrary()
{
    static const ast::CompilationUnit unit = [] {
        Diagnostics diagnostics;
        ast::CompilationUnit parsed = parseUnit(utilSource(), diagnostics);
        Q_ASSERT_X(!diagnostics.hasErrors(), "utilLibrary", qPrintable(diagnostics.all().front().toString()));
        return parsed;
    }();
    return unit;
}

namespace {

// The names a unit gives types and calls: enough to tell whether it uses a library block.
struct NameScan {
    bool (*wanted)(const QString &);
    bool found = false;
    void expr(const ast::Expr &e)
    {
        found = found || ((e.kind == ast::ExprKind::Call || e.kind == ast::ExprKind::Name) && wanted(e.text));
    }
    void decl(const ast::VarDecl &v) { found = found || (v.type.kind == ast::TypeSpec::Kind::Named && wanted(v.type.name)); }
};

} // namespace

bool utilNamesUsed(const std::vector<const ast::CompilationUnit *> &units)
{
    NameScan scan {&isUtilName};
    for (const ast::CompilationUnit *u : units)
        ast::walk(*u, scan);
    return scan.found;
}

bool isUtilName(const QString &name)
{
    static const QSet<QString> names = [] {
        QSet<QString> all;
        for (const ast::Pou &p : utilLibrary().pous)
            all.insert(p.name.toUpper());
        for (const ast::TypeDecl &t : utilLibrary().types)
            all.insert(t.name.toUpper());
        return all;
    }();
    return names.contains(name.toUpper());
}

} // namespace iec::interp
