#include "editors/text/standardlibrary.h"

#include "editors/text/utillibrary.h"

#include <QCoreApplication>
#include <QHash>

namespace iec::editors {

namespace {

const char *const kContext = "iec::editors::StandardLibrary";

QString trLib(const char *text)
{
    return QCoreApplication::translate(kContext, text);
}

QList<StdParameter> params(std::initializer_list<std::pair<const char *, const char *>> list)
{
    QList<StdParameter> result;
    for (const auto &[name, type] : list)
        result.append({QString::fromLatin1(name), QString::fromLatin1(type)});
    return result;
}

StdPou fn(const char *name, StdPou::Category category, std::initializer_list<std::pair<const char *, const char *>> in,
    const char *returnType, const char *description)
{
    return {QString::fromLatin1(name), StdPou::Kind::Function, category, params(in), {},
        QString::fromLatin1(returnType), description};
}

StdPou fb(const char *name, StdPou::Category category, std::initializer_list<std::pair<const char *, const char *>> in,
    std::initializer_list<std::pair<const char *, const char *>> out, const char *description)
{
    return {QString::fromLatin1(name), StdPou::Kind::FunctionBlock, category, params(in), params(out), {}, description};
}

QList<StdPou> buildStandardPous()
{
    using C = StdPou::Category;
    QList<StdPou> pous = {
        fn("ADD", C::Arithmetic, {{"IN1", "ANY_NUM"}, {"IN2", "ANY_NUM"}}, "ANY_NUM",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Adds the inputs.")),
        fn("SUB", C::Arithmetic, {{"IN1", "ANY_NUM"}, {"IN2", "ANY_NUM"}}, "ANY_NUM",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Subtracts IN2 from IN1.")),
        fn("MUL", C::Arithmetic, {{"IN1", "ANY_NUM"}, {"IN2", "ANY_NUM"}}, "ANY_NUM",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Multiplies the inputs.")),
        fn("DIV", C::Arithmetic, {{"IN1", "ANY_NUM"}, {"IN2", "ANY_NUM"}}, "ANY_NUM",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Divides IN1 by IN2.")),
        fn("MOD", C::Arithmetic, {{"IN1", "ANY_INT"}, {"IN2", "ANY_INT"}}, "ANY_INT",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "The remainder of IN1 divided by IN2.")),
        fn("MOVE", C::Arithmetic, {{"IN", "ANY"}}, "ANY",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Copies the input to the output.")),
        fn("EXPT", C::Arithmetic, {{"IN1", "ANY_REAL"}, {"IN2", "ANY_NUM"}}, "ANY_REAL",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "IN1 raised to the power IN2.")),
        fn("ABS", C::Numeric, {{"IN", "ANY_NUM"}}, "ANY_NUM",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "The absolute value.")),
        fn("SQRT", C::Numeric, {{"IN", "ANY_REAL"}}, "ANY_REAL",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "The square root.")),
        fn("LN", C::Numeric, {{"IN", "ANY_REAL"}}, "ANY_REAL",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "The natural logarithm.")),
        fn("LOG", C::Numeric, {{"IN", "ANY_REAL"}}, "ANY_REAL",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "The logarithm to base 10.")),
        fn("EXP", C::Numeric, {{"IN", "ANY_REAL"}}, "ANY_REAL",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "e raised to the power IN.")),
        fn("SIN", C::Numeric, {{"IN", "ANY_REAL"}}, "ANY_REAL",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "The sine (IN in radians).")),
        fn("COS", C::Numeric, {{"IN", "ANY_REAL"}}, "ANY_REAL",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "The cosine (IN in radians).")),
        fn("TAN", C::Numeric, {{"IN", "ANY_REAL"}}, "ANY_REAL",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "The tangent (IN in radians).")),
        fn("ASIN", C::Numeric, {{"IN", "ANY_REAL"}}, "ANY_REAL",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "The arc sine, in radians.")),
        fn("ACOS", C::Numeric, {{"IN", "ANY_REAL"}}, "ANY_REAL",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "The arc cosine, in radians.")),
        fn("ATAN", C::Numeric, {{"IN", "ANY_REAL"}}, "ANY_REAL",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "The arc tangent, in radians.")),
        fn("TRUNC", C::Numeric, {{"IN", "ANY_REAL"}}, "DINT",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "The whole-number part of a REAL.")),
        fn("SHL", C::BitShift, {{"IN", "ANY_BIT"}, {"N", "INT"}}, "ANY_BIT",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Shifts the bits N places to the left.")),
        fn("SHR", C::BitShift, {{"IN", "ANY_BIT"}, {"N", "INT"}}, "ANY_BIT",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Shifts the bits N places to the right.")),
        fn("ROL", C::BitShift, {{"IN", "ANY_BIT"}, {"N", "INT"}}, "ANY_BIT",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Rotates the bits N places to the left.")),
        fn("ROR", C::BitShift, {{"IN", "ANY_BIT"}, {"N", "INT"}}, "ANY_BIT",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Rotates the bits N places to the right.")),
        fn("SEL", C::Selection, {{"G", "BOOL"}, {"IN0", "ANY"}, {"IN1", "ANY"}}, "ANY",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "IN0 when G is FALSE, IN1 when G is TRUE.")),
        fn("MAX", C::Selection, {{"IN1", "ANY"}, {"IN2", "ANY"}}, "ANY",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "The larger input.")),
        fn("MIN", C::Selection, {{"IN1", "ANY"}, {"IN2", "ANY"}}, "ANY",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "The smaller input.")),
        fn("LIMIT", C::Selection, {{"MN", "ANY"}, {"IN", "ANY"}, {"MX", "ANY"}}, "ANY",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "IN limited to the range MN..MX.")),
        fn("MUX", C::Selection, {{"K", "INT"}, {"IN0", "ANY"}, {"IN1", "ANY"}}, "ANY",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Input number K (IN0, IN1, ...).")),
        fn("GT", C::Comparison, {{"IN1", "ANY"}, {"IN2", "ANY"}}, "BOOL",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "TRUE when IN1 > IN2.")),
        fn("GE", C::Comparison, {{"IN1", "ANY"}, {"IN2", "ANY"}}, "BOOL",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "TRUE when IN1 >= IN2.")),
        fn("EQ", C::Comparison, {{"IN1", "ANY"}, {"IN2", "ANY"}}, "BOOL",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "TRUE when IN1 = IN2.")),
        fn("NE", C::Comparison, {{"IN1", "ANY"}, {"IN2", "ANY"}}, "BOOL",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "TRUE when IN1 <> IN2.")),
        fn("LE", C::Comparison, {{"IN1", "ANY"}, {"IN2", "ANY"}}, "BOOL",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "TRUE when IN1 <= IN2.")),
        fn("LT", C::Comparison, {{"IN1", "ANY"}, {"IN2", "ANY"}}, "BOOL",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "TRUE when IN1 < IN2.")),
        fn("LEN", C::String, {{"STR", "STRING"}}, "INT",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "The number of characters of STR.")),
        fn("LEFT", C::String, {{"STR", "STRING"}, {"SIZE", "INT"}}, "STRING",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "The first SIZE characters of STR.")),
        fn("RIGHT", C::String, {{"STR", "STRING"}, {"SIZE", "INT"}}, "STRING",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "The last SIZE characters of STR.")),
        fn("MID", C::String, {{"STR", "STRING"}, {"LEN", "INT"}, {"POS", "INT"}}, "STRING",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "LEN characters of STR from position POS.")),
        fn("CONCAT", C::String, {{"STR1", "STRING"}, {"STR2", "STRING"}}, "STRING",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "STR1 followed by STR2.")),
        fn("INSERT", C::String, {{"STR1", "STRING"}, {"STR2", "STRING"}, {"POS", "INT"}}, "STRING",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "STR2 inserted into STR1 after position POS.")),
        fn("DELETE", C::String, {{"STR", "STRING"}, {"LEN", "INT"}, {"POS", "INT"}}, "STRING",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "STR without LEN characters from position POS.")),
        fn("REPLACE", C::String, {{"STR1", "STRING"}, {"STR2", "STRING"}, {"L", "INT"}, {"P", "INT"}}, "STRING",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "STR1 with L characters from position P replaced by STR2.")),
        fn("FIND", C::String, {{"STR1", "STRING"}, {"STR2", "STRING"}}, "INT",
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "The position of STR2 in STR1 (0: not found).")),
        fb("SR", C::Bistable, {{"SET1", "BOOL"}, {"RESET", "BOOL"}}, {{"Q1", "BOOL"}},
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Bistable, set dominant: Q1 stays TRUE from SET1 until RESET.")),
        fb("RS", C::Bistable, {{"SET", "BOOL"}, {"RESET1", "BOOL"}}, {{"Q1", "BOOL"}},
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Bistable, reset dominant: Q1 stays TRUE from SET until RESET1.")),
        fb("R_TRIG", C::Edge, {{"CLK", "BOOL"}}, {{"Q", "BOOL"}},
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Q is TRUE for one cycle when CLK rises.")),
        fb("F_TRIG", C::Edge, {{"CLK", "BOOL"}}, {{"Q", "BOOL"}},
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Q is TRUE for one cycle when CLK falls.")),
        fb("CTU", C::Counter, {{"CU", "BOOL"}, {"RESET", "BOOL"}, {"PV", "WORD"}}, {{"Q", "BOOL"}, {"CV", "WORD"}},
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Counts rising edges of CU up; Q when CV reaches PV.")),
        fb("CTD", C::Counter, {{"CD", "BOOL"}, {"LOAD", "BOOL"}, {"PV", "WORD"}}, {{"Q", "BOOL"}, {"CV", "WORD"}},
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Counts rising edges of CD down from PV; Q when CV reaches 0.")),
        fb("CTUD", C::Counter, {{"CU", "BOOL"}, {"CD", "BOOL"}, {"RESET", "BOOL"}, {"LOAD", "BOOL"}, {"PV", "WORD"}},
            {{"QU", "BOOL"}, {"QD", "BOOL"}, {"CV", "WORD"}},
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Counts up (CU) and down (CD); QU when CV reaches PV, QD at 0.")),
        fb("TP", C::Timer, {{"IN", "BOOL"}, {"PT", "TIME"}}, {{"Q", "BOOL"}, {"ET", "TIME"}},
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Pulse: Q is TRUE for PT after IN rises.")),
        fb("TON", C::Timer, {{"IN", "BOOL"}, {"PT", "TIME"}}, {{"Q", "BOOL"}, {"ET", "TIME"}},
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "On delay: Q follows IN after it was TRUE for PT.")),
        fb("TOF", C::Timer, {{"IN", "BOOL"}, {"PT", "TIME"}}, {{"Q", "BOOL"}, {"ET", "TIME"}},
            QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Off delay: Q stays TRUE for PT after IN falls.")),
    };
    // The conversion operators X_TO_Y between the elementary types, as CODESYS V2.3 offers them.
    static const char *const convertible[] = {"BOOL", "BYTE", "WORD", "DWORD", "SINT", "USINT", "INT", "UINT", "DINT",
        "UDINT", "REAL", "LREAL", "TIME", "TOD", "DATE", "DT", "STRING"};
    for (const char *from : convertible) {
        for (const char *to : convertible) {
            if (qstrcmp(from, to) == 0)
                continue;
            const QString name = QString::fromLatin1(from) + QLatin1String("_TO_") + QString::fromLatin1(to);
            pous.append({name, StdPou::Kind::Function, C::TypeConversion,
                {{QStringLiteral("IN"), QString::fromLatin1(from)}}, {}, QString::fromLatin1(to),
                QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Converts %1 to %2.")});
        }
    }
    pous.append(utilLibraryPous());
    return pous;
}

QString joinParams(const QList<StdParameter> &list)
{
    QStringList parts;
    for (const StdParameter &p : list)
        parts.append(p.name + QLatin1String(": ") + p.type);
    return parts.join(QLatin1String(", "));
}

} // namespace

QString StdPou::signature() const
{
    QString text = name + QLatin1Char('(') + joinParams(inputs) + QLatin1Char(')');
    if (kind == Kind::Function)
        return text + QLatin1String(" : ") + returnType;
    return outputs.isEmpty() ? text : text + QLatin1String(" => ") + joinParams(outputs);
}

QString StdPou::translatedDescription() const
{
    if (!description)
        return {};
    const QString text = trLib(description);
    return category == Category::TypeConversion ? text.arg(inputs.value(0).type, returnType) : text;
}

QString stdCategoryName(StdPou::Category category)
{
    using C = StdPou::Category;
    switch (category) {
    case C::Arithmetic:
        return trLib(QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Arithmetic"));
    case C::Numeric:
        return trLib(QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Numeric"));
    case C::BitShift:
        return trLib(QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Bit shift"));
    case C::Selection:
        return trLib(QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Selection"));
    case C::Comparison:
        return trLib(QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Comparison"));
    case C::String:
        return trLib(QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "String"));
    case C::TypeConversion:
        return trLib(QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Type conversion"));
    case C::Bistable:
        return trLib(QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Bistable"));
    case C::Edge:
        return trLib(QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Edge detection"));
    case C::Counter:
        return trLib(QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Counters"));
    case C::Timer:
        return trLib(QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Timers"));
    case C::BcdConversion:
        return trLib(QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "BCD conversion"));
    case C::BitByte:
        return trLib(QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Bit and byte functions"));
    case C::MathAuxiliary:
        return trLib(QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Mathematical helpers"));
    case C::Controller:
        return trLib(QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Controllers"));
    case C::SignalGenerator:
        return trLib(QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Signal generators"));
    case C::FunctionManipulator:
        return trLib(QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Function manipulators"));
    case C::AnalogValue:
        return trLib(QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Analog values"));
    case C::Messages:
        return trLib(QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Messages"));
    }
    return {};
}

const QList<StdPou> &standardPous()
{
    static const QList<StdPou> pous = buildStandardPous();
    return pous;
}

const StdPou *findStandardPou(QStringView name)
{
    static const QHash<QString, int> index = [] {
        QHash<QString, int> result;
        const QList<StdPou> &pous = standardPous();
        for (int i = 0; i < pous.size(); ++i)
            result.insert(pous[i].name, i);
        return result;
    }();
    const auto it = index.constFind(name.toString().toUpper());
    return it == index.constEnd() ? nullptr : &standardPous()[*it];
}

QList<IlOperator> ilOperators()
{
    struct Base {
        const char *name;
        const char *description;
        const char *modifiers; // "N", "N(", "(", "CN", ""
    };
    static const Base bases[] = {
        {"LD", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Load the operand into the current result"), "N"},
        {"ST", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Store the current result in the operand"), "N"},
        {"S",
            QT_TRANSLATE_NOOP(
                "iec::editors::StandardLibrary", "Set the Boolean operand to TRUE if the current result is TRUE"),
            ""},
        {"R",
            QT_TRANSLATE_NOOP(
                "iec::editors::StandardLibrary", "Reset the Boolean operand to FALSE if the current result is TRUE"),
            ""},
        {"AND", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Bitwise AND"), "N("},
        {"OR", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Bitwise OR"), "N("},
        {"XOR", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Bitwise exclusive OR"), "N("},
        {"ADD", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Addition"), "("},
        {"SUB", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Subtraction"), "("},
        {"MUL", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Multiplication"), "("},
        {"DIV", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Division"), "("},
        {"GT", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Greater than (>)"), "("},
        {"GE", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Greater than or equal (>=)"), "("},
        {"EQ", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Equal (=)"), "("},
        {"NE", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Not equal (<>)"), "("},
        {"LE", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Less than or equal (<=)"), "("},
        {"LT", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Less than (<)"), "("},
        {"JMP", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Jump to the label"), "CN"},
        {"CAL", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Call a function block instance"), "CN"},
        {"RET", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Return to the calling POU"), "CN"},
        {")", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Evaluate the deferred operation"), ""},
    };
    const QString negated = trLib(QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "negated operand"));
    const QString deferred = trLib(QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "deferred until )"));
    const QString ifTrue
        = trLib(QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "only if the current result is TRUE"));
    const QString ifFalse
        = trLib(QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "only if the current result is FALSE"));

    QList<IlOperator> result;
    for (const Base &b : bases) {
        const QString base = QString::fromLatin1(b.name);
        const QString description = trLib(b.description);
        const QString modifiers = QString::fromLatin1(b.modifiers);
        auto add = [&](const QString &suffix, const QString &note) {
            result.append({base + suffix, base,
                note.isEmpty() ? description : description + QLatin1String(" (") + note + QLatin1Char(')')});
        };
        add({}, {});
        if (modifiers.contains(QLatin1Char('N')) && !modifiers.contains(QLatin1Char('C')))
            add(QStringLiteral("N"), negated);
        if (modifiers.contains(QLatin1Char('('))) {
            add(QStringLiteral("("), deferred);
            if (modifiers.contains(QLatin1Char('N')))
                add(QStringLiteral("N("), negated + QLatin1String(", ") + deferred);
        }
        if (modifiers.contains(QLatin1Char('C'))) {
            add(QStringLiteral("C"), ifTrue);
            add(QStringLiteral("CN"), ifFalse);
        }
    }
    return result;
}

QList<IlOperator> stOperators()
{
    struct Op {
        const char *text;
        const char *description;
    };
    static const Op ops[] = {
        {":=", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Assignment")},
        {"+", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Addition")},
        {"-", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Subtraction")},
        {"*", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Multiplication")},
        {"/", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Division")},
        {"MOD", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Modulo")},
        {"NOT", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Negation")},
        {"AND", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Bitwise AND")},
        {"OR", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Bitwise OR")},
        {"XOR", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Bitwise exclusive OR")},
        {"=", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Equal (=)")},
        {"<>", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Not equal (<>)")},
        {"<", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Less than (<)")},
        {"<=", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Less than or equal (<=)")},
        {">", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Greater than (>)")},
        {">=", QT_TRANSLATE_NOOP("iec::editors::StandardLibrary", "Greater than or equal (>=)")},
    };
    QList<IlOperator> result;
    for (const Op &op : ops)
        result.append({QString::fromLatin1(op.text), QString::fromLatin1(op.text), trLib(op.description)});
    return result;
}

const QStringList &elementaryTypeNames()
{
    static const QStringList types = {QStringLiteral("BOOL"), QStringLiteral("BYTE"), QStringLiteral("WORD"),
        QStringLiteral("DWORD"), QStringLiteral("LWORD"), QStringLiteral("SINT"), QStringLiteral("USINT"),
        QStringLiteral("INT"), QStringLiteral("UINT"), QStringLiteral("DINT"), QStringLiteral("UDINT"),
        QStringLiteral("LINT"), QStringLiteral("ULINT"), QStringLiteral("REAL"), QStringLiteral("LREAL"),
        QStringLiteral("TIME"), QStringLiteral("DATE"), QStringLiteral("TIME_OF_DAY"), QStringLiteral("TOD"),
        QStringLiteral("DATE_AND_TIME"), QStringLiteral("DT"), QStringLiteral("STRING"), QStringLiteral("WSTRING")};
    return types;
}

const QStringList &completionKeywords(TextLanguage language)
{
    static const QStringList declarations
        = {QStringLiteral("VAR"), QStringLiteral("VAR_INPUT"), QStringLiteral("VAR_OUTPUT"),
            QStringLiteral("VAR_IN_OUT"), QStringLiteral("VAR_GLOBAL"), QStringLiteral("VAR_EXTERNAL"),
            QStringLiteral("VAR_TEMP"), QStringLiteral("END_VAR"), QStringLiteral("CONSTANT"), QStringLiteral("RETAIN"),
            QStringLiteral("PERSISTENT"), QStringLiteral("AT"), QStringLiteral("ARRAY"), QStringLiteral("STRUCT"),
            QStringLiteral("END_STRUCT"), QStringLiteral("TRUE"), QStringLiteral("FALSE")};
    static const QStringList st = [] {
        QStringList list = {QStringLiteral("IF"), QStringLiteral("THEN"), QStringLiteral("ELSIF"),
            QStringLiteral("ELSE"), QStringLiteral("END_IF"), QStringLiteral("CASE"), QStringLiteral("OF"),
            QStringLiteral("END_CASE"), QStringLiteral("FOR"), QStringLiteral("TO"), QStringLiteral("BY"),
            QStringLiteral("DO"), QStringLiteral("END_FOR"), QStringLiteral("WHILE"), QStringLiteral("END_WHILE"),
            QStringLiteral("REPEAT"), QStringLiteral("UNTIL"), QStringLiteral("END_REPEAT"), QStringLiteral("EXIT"),
            QStringLiteral("RETURN"), QStringLiteral("AND"), QStringLiteral("OR"), QStringLiteral("XOR"),
            QStringLiteral("NOT"), QStringLiteral("MOD")};
        list += declarations;
        list += elementaryTypeNames();
        return list;
    }();
    static const QStringList il = [] {
        QStringList list;
        for (const IlOperator &op : ilOperators()) {
            if (op.text.back().isLetter()) // LD, ANDN, JMPC; not AND( or )
                list.append(op.text);
        }
        list += declarations;
        list += elementaryTypeNames();
        return list;
    }();
    return language == TextLanguage::IL ? il : st;
}

} // namespace iec::editors
