#pragma once

// The deep and the long programs of issue 17 as IEC text, for the library tests
// (tst_robustness) and the command-line tests (tst_cli_robustness). A deep one must give exactly
// the one message below at the place named; a long one must compile and compute its value.
#include <QString>

#include <vector>

namespace deepinputs {

// The limits of interpreter/compiler/limits.h as the messages state them.
inline constexpr int kMaxNesting = 1000;
inline constexpr int kMaxTypeNesting = 40;

inline QString expressionTooDeep()
{
    return QStringLiteral("This expression is nested too deeply (more than 1000 levels).");
}

inline QString statementsTooDeep()
{
    return QStringLiteral("These statements are nested too deeply (more than 1000 levels).");
}

inline QString typeTooDeep()
{
    return QStringLiteral("This type is nested too deeply (more than 40 levels).");
}

// PROGRAM Main with these variables and this body; the body starts on line 4.
inline QString program(const QString &variables, const QString &body)
{
    return QStringLiteral("PROGRAM Main\nVAR\n%1\nEND_VAR\n%2\nEND_PROGRAM\n").arg(variables, body);
}

inline QString repeated(const QString &text, int times)
{
    return text.repeated(times);
}

struct Deep {
    const char *name;
    QString variables;
    QString body;
    int line; // where the one message is, in program(variables, body)
    int column;
    QString message;

    QString source() const { return program(variables, body); }
};

// Column of the k-th (1-based) repetition of a `width`-character piece after `prefix` characters.
inline int columnOf(int prefix, int width, int k)
{
    return prefix + width * (k - 1) + 1;
}

inline std::vector<Deep> deepPrograms()
{
    const QString x = QStringLiteral("x : DINT; b : BOOL; a : ARRAY[0..1] OF DINT;");
    std::vector<Deep> list;
    // x := ((((...1...)))); the expression inside parenthesis 1001 is level 1001.
    list.push_back({"20000 nested parentheses", x,
        QStringLiteral("x := ") + repeated(QStringLiteral("("), 20000) + QStringLiteral("1") + repeated(QStringLiteral(")"), 20000)
            + QStringLiteral(";"),
        5, columnOf(5, 1, kMaxNesting + 2), expressionTooDeep()});
    list.push_back({"50000 NOTs", x, QStringLiteral("b := ") + repeated(QStringLiteral("NOT "), 50000) + QStringLiteral("TRUE;"),
        5, columnOf(5, 4, kMaxNesting + 1), expressionTooDeep()});
    list.push_back({"50000 unary minus", x, QStringLiteral("x := ") + repeated(QStringLiteral("- "), 50000) + QStringLiteral("x;"),
        5, columnOf(5, 2, kMaxNesting + 1), expressionTooDeep()});
    // IF b THEN, one per line from line 5 on.
    list.push_back({"10000 nested IFs", x,
        repeated(QStringLiteral("IF b THEN\n"), 10000) + QStringLiteral("x := 1;\n") + repeated(QStringLiteral("END_IF;\n"), 10000),
        5 + kMaxNesting, 1, statementsTooDeep()});
    list.push_back({"5000 nested FOR, WHILE, REPEAT and CASE", x + QStringLiteral(" i : INT;"),
        repeated(QStringLiteral("FOR i := 1 TO 2 DO\nWHILE b DO\nREPEAT\nCASE x OF 1:\n"), 1250) + QStringLiteral("x := 1;\n")
            + repeated(QStringLiteral("END_CASE;\nUNTIL b END_REPEAT;\nEND_WHILE;\nEND_FOR;\n"), 1250),
        5 + kMaxNesting, 1, statementsTooDeep()});
    // ABS( is a call and its argument list: two levels each.
    list.push_back({"5000 nested calls", x,
        QStringLiteral("x := ") + repeated(QStringLiteral("ABS("), 5000) + QStringLiteral("x") + repeated(QStringLiteral(")"), 5000)
            + QStringLiteral(";"),
        5, columnOf(5, 4, kMaxNesting / 2 + 1) + 3, expressionTooDeep()});
    list.push_back({"5000 nested indices", x,
        QStringLiteral("x := ") + repeated(QStringLiteral("a["), 5000) + QStringLiteral("0") + repeated(QStringLiteral("]"), 5000)
            + QStringLiteral(";"),
        5, columnOf(5, 2, kMaxNesting / 2 + 1) + 1, expressionTooDeep()});
    list.push_back({"100 nested ARRAY OF", QStringLiteral("m : ") + repeated(QStringLiteral("ARRAY[0..1] OF "), 100) + QStringLiteral("INT;"),
        QString(),
        3, columnOf(4, 15, kMaxTypeNesting + 1), typeTooDeep()});
    return list;
}

// x := 1 + 1 + ... + 1 (n terms), x a DINT.
inline QString sumOfOnes(int n)
{
    QString sum = QStringLiteral("1");
    sum.reserve(4 * n);
    for (int i = 1; i < n; ++i)
        sum += QStringLiteral(" + 1");
    return program(QStringLiteral("x : DINT;"), QStringLiteral("x := ") + sum + QStringLiteral(";"));
}

} // namespace deepinputs
