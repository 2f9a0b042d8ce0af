#pragma once

// A generator of random, well-defined IEC 61131-3 programs written three ways that must compute
// the same values cycle by cycle:
//   - ST with the inputs as variables (the compiler cannot know them),
//   - ST with the inputs as VAR CONSTANT (the compiler folds what it can),
//   - IL with the inputs as variables (jumps over code, labels whose code reads the current
//     result, brackets, functions with the current result as first argument).
// "Well-defined": no integer division by zero (divisors are x MOD m + 8, m in 2..8), no loop without an end,
// untyped literals only where a typed operand or the target gives them their type and where they
// fit it. Everything else, including wraparound, REAL to integer conversions and NaN, is what
// the three forms must agree on.

#include <QRandomGenerator>
#include <QString>
#include <QStringList>

#include <memory>
#include <vector>

namespace iec::interp::testing {

class RandomProgram
{
public:
    struct Variable {
        QString name;
        QString type;
        QString initial;
    };

    explicit RandomProgram(quint32 seed)
        : m_random(seed)
    {
        build();
    }

    QString st(bool constantInputs) const { return text(constantInputs, m_st); }
    QString il() const { return text(false, m_il, m_ilTemps); }
    // The variables all three forms have and change: compared after every cycle.
    QStringList compared() const
    {
        QStringList names;
        for (const Variable &v : m_state)
            names << v.name;
        return names;
    }

private:
    enum class Kind { Leaf, Binary, Unary, Call };
    struct Node {
        Kind kind = Kind::Leaf;
        QString type;       // the IEC type of the value (empty: an untyped literal)
        QString text;       // Leaf: the variable or literal; Binary: the ST operator; Call: the function
        QString ilOp;       // Binary: the IL operator
        bool literal = false;
        std::vector<std::shared_ptr<Node>> args;
    };
    using NodePtr = std::shared_ptr<Node>;

    static const QStringList &integerTypes()
    {
        static const QStringList t{QStringLiteral("SINT"), QStringLiteral("INT"), QStringLiteral("DINT"), QStringLiteral("LINT"),
                                   QStringLiteral("USINT"), QStringLiteral("UINT"), QStringLiteral("UDINT"), QStringLiteral("ULINT")};
        return t;
    }
    static const QStringList &bitTypes()
    {
        static const QStringList t{QStringLiteral("BYTE"), QStringLiteral("WORD"), QStringLiteral("DWORD"), QStringLiteral("LWORD")};
        return t;
    }
    static const QStringList &realTypes()
    {
        static const QStringList t{QStringLiteral("REAL"), QStringLiteral("LREAL")};
        return t;
    }
    static bool isInteger(const QString &t) { return integerTypes().contains(t); }
    static bool isBits(const QString &t) { return bitTypes().contains(t); }
    static bool isRealType(const QString &t) { return realTypes().contains(t); }
    static bool isUnsigned(const QString &t) { return t.startsWith(QLatin1Char('U')) || isBits(t); }
    static int widthOf(const QString &t)
    {
        if (t == QLatin1String("SINT") || t == QLatin1String("USINT") || t == QLatin1String("BYTE"))
            return 8;
        if (t == QLatin1String("INT") || t == QLatin1String("UINT") || t == QLatin1String("WORD"))
            return 16;
        if (t == QLatin1String("DINT") || t == QLatin1String("UDINT") || t == QLatin1String("DWORD") || t == QLatin1String("REAL"))
            return 32;
        return 64;
    }

    int pick(int n) { return int(m_random.bounded(n)); }
    bool chance(int percent) { return pick(100) < percent; }

    QString anyType()
    {
        const int k = pick(20);
        if (k < 9)
            return integerTypes()[pick(8)];
        if (k < 13)
            return bitTypes()[pick(4)];
        if (k < 16)
            return realTypes()[pick(2)];
        return QStringLiteral("BOOL");
    }

    // A literal value of `type` as text, without the type prefix.
    QString literalValue(const QString &type, bool smallOnly = false)
    {
        if (type == QLatin1String("BOOL"))
            return chance(50) ? QStringLiteral("TRUE") : QStringLiteral("FALSE");
        if (isRealType(type)) {
            static const char *const reals[] = {"0.0", "1.5", "-2.25", "100.0", "0.1", "-1.0E3", "3.0E2", "7.75"};
            return QLatin1String(reals[pick(8)]);
        }
        const int width = widthOf(type);
        if (isBits(type)) {
            const quint64 mask = width == 64 ? ~quint64(0) : (quint64(1) << width) - 1;
            const quint64 v = (smallOnly ? quint64(pick(200)) : m_random.generate64()) & mask;
            return QStringLiteral("16#") + QString::number(v, 16).toUpper();
        }
        if (isUnsigned(type)) {
            const quint64 max = width == 64 ? ~quint64(0) : (quint64(1) << width) - 1;
            const quint64 v = smallOnly || chance(60) ? quint64(pick(120)) : m_random.generate64() % max;
            return QString::number(v);
        }
        const qint64 half = width == 64 ? INT64_MAX : (qint64(1) << (width - 1)) - 1;
        const qint64 v = smallOnly || chance(60) ? qint64(pick(240)) - 120 : qint64(m_random.generate64() % quint64(half)) * (chance(50) ? -1 : 1);
        return QString::number(width == 8 ? std::clamp<qint64>(v, -128, 127) : v);
    }

    NodePtr leaf(const QString &type, const QString &text, bool literal)
    {
        auto n = std::make_shared<Node>();
        n->type = type;
        n->text = text;
        n->literal = literal;
        return n;
    }
    NodePtr typedLiteral(const QString &type) { return leaf(type, type + QLatin1Char('#') + literalValue(type), true); }
    NodePtr untypedLiteral(const QString &type, bool smallOnly = false)
    {
        QString v = literalValue(type, smallOnly);
        if (v.startsWith(QLatin1Char('-')))
            v = v.mid(1); // a negative untyped literal is the unary minus of one
        return leaf(QString(), v, true);
    }
    NodePtr binaryNode(const QString &type, const QString &st, const QString &il, NodePtr a, NodePtr b)
    {
        auto n = std::make_shared<Node>();
        n->kind = Kind::Binary;
        n->type = type;
        n->text = st;
        n->ilOp = il;
        n->args = {a, b};
        return n;
    }
    NodePtr call(const QString &type, const QString &name, std::vector<NodePtr> args)
    {
        auto n = std::make_shared<Node>();
        n->kind = Kind::Call;
        n->type = type;
        n->text = name;
        n->args = std::move(args);
        return n;
    }
    NodePtr negation(const QString &type, NodePtr a)
    {
        auto n = std::make_shared<Node>();
        n->kind = Kind::Unary;
        n->type = type;
        n->text = QStringLiteral("-");
        n->args = {a};
        return n;
    }

    NodePtr variableOf(const QString &type)
    {
        std::vector<const Variable *> candidates;
        for (const Variable &v : m_inputs) {
            if (v.type == type)
                candidates.push_back(&v);
        }
        for (const Variable &v : m_state) {
            if (v.type == type)
                candidates.push_back(&v);
        }
        if (candidates.empty())
            return typedLiteral(type);
        return leaf(type, candidates[size_t(pick(int(candidates.size())))]->name, false);
    }

    // A MUX selector in 0..count-1: ABS(x) MOD count (x MOD count alone may be negative).
    NodePtr selectorOf(int count)
    {
        const QString dint = QStringLiteral("DINT");
        return binaryNode(dint, QStringLiteral("MOD"), QStringLiteral("MOD"), call(dint, QStringLiteral("ABS"), {variableOf(dint)}),
                          leaf(QString(), QString::number(count), true));
    }

    // A divisor that is never zero: x MOD m + 8 with m in 2..8 lies in 1..15.
    NodePtr divisor(const QString &type, int depth)
    {
        return binaryNode(type, QStringLiteral("+"), QStringLiteral("ADD"),
                          binaryNode(type, QStringLiteral("MOD"), QStringLiteral("MOD"), expression(type, depth + 1),
                                     leaf(QString(), QString::number(2 + pick(7)), true)),
                          leaf(QString(), QStringLiteral("8"), true));
    }

    // The second operand of an operator: sometimes a literal the first operand types.
    NodePtr operand(const QString &type, int depth)
    {
        if (type != QLatin1String("BOOL") && chance(20)) {
            NodePtr lit = untypedLiteral(type);
            if (lit->text == QLatin1String("0") && !isRealType(type))
                lit->text = QStringLiteral("3");
            return lit;
        }
        if (isBits(type) && chance(10)) {
            // Untyped bit patterns that take this type: NOT 16#0159, SHL(507, 9), SEL(b, 0, 16#08).
            switch (pick(3)) {
            case 0: {
                auto n = std::make_shared<Node>();
                n->kind = Kind::Unary;
                n->text = QStringLiteral("NOT");
                n->args = {untypedLiteral(type, true)};
                return n;
            }
            case 1: return call(QString(), QStringLiteral("SHL"), {untypedLiteral(type, true), leaf(QString(), QString::number(pick(9)), true)});
            default: return call(QString(), QStringLiteral("SEL"), {expression(QStringLiteral("BOOL"), depth + 1), untypedLiteral(type, true), untypedLiteral(type, true)});
            }
        }
        return expression(type, depth + 1);
    }

    NodePtr conversionInto(const QString &type, int depth)
    {
        QString from = anyType();
        if (from == type)
            return variableOf(type);
        return call(type, from + QStringLiteral("_TO_") + type, {expression(from, depth + 1)});
    }

    NodePtr expression(const QString &type, int depth)
    {
        if (depth > 3 || chance(30))
            return chance(25) ? typedLiteral(type) : variableOf(type);
        if (type == QLatin1String("BOOL")) {
            switch (pick(5)) {
            case 0:
            case 1: {
                const QString t = anyType();
                static const char *const st[] = {"<", "<=", ">", ">=", "=", "<>"};
                static const char *const il[] = {"LT", "LE", "GT", "GE", "EQ", "NE"};
                const int k = pick(t == QLatin1String("BOOL") ? 2 : 6) + (t == QLatin1String("BOOL") ? 4 : 0);
                return binaryNode(type, QLatin1String(st[k]), QLatin1String(il[k]), expression(t, depth + 1), operand(t, depth));
            }
            case 2: return binaryNode(type, QStringLiteral("AND"), QStringLiteral("AND"), expression(type, depth + 1), expression(type, depth + 1));
            case 3: return binaryNode(type, QStringLiteral("OR"), QStringLiteral("OR"), expression(type, depth + 1), expression(type, depth + 1));
            default: return binaryNode(type, QStringLiteral("XOR"), QStringLiteral("XOR"), expression(type, depth + 1), expression(type, depth + 1));
            }
        }
        if (isBits(type)) {
            switch (pick(8)) {
            case 0: return binaryNode(type, QStringLiteral("AND"), QStringLiteral("AND"), expression(type, depth + 1), operand(type, depth));
            case 1: return binaryNode(type, QStringLiteral("OR"), QStringLiteral("OR"), expression(type, depth + 1), operand(type, depth));
            case 2: return binaryNode(type, QStringLiteral("XOR"), QStringLiteral("XOR"), expression(type, depth + 1), operand(type, depth));
            case 3: {
                static const char *const shifts[] = {"SHL", "SHR", "ROL", "ROR"};
                return call(type, QLatin1String(shifts[pick(4)]), {expression(type, depth + 1), leaf(QString(), QString::number(pick(widthOf(type) + 3)), true)});
            }
            case 4: return call(type, QStringLiteral("NOT"), {expression(type, depth + 1)});
            case 5: return call(type, QStringLiteral("SEL"), {expression(QStringLiteral("BOOL"), depth + 1), expression(type, depth + 1), operand(type, depth)});
            case 6: return call(type, chance(50) ? QStringLiteral("MAX") : QStringLiteral("MIN"), {expression(type, depth + 1), operand(type, depth)});
            default: return conversionInto(type, depth);
            }
        }
        const bool real = isRealType(type);
        switch (pick(real ? 10 : 11)) {
        case 0: return binaryNode(type, QStringLiteral("+"), QStringLiteral("ADD"), expression(type, depth + 1), operand(type, depth));
        case 1: return binaryNode(type, QStringLiteral("-"), QStringLiteral("SUB"), expression(type, depth + 1), operand(type, depth));
        case 2: return binaryNode(type, QStringLiteral("*"), QStringLiteral("MUL"), expression(type, depth + 1), operand(type, depth));
        case 3:
            return binaryNode(type, QStringLiteral("/"), QStringLiteral("DIV"), expression(type, depth + 1), real ? operand(type, depth) : divisor(type, depth));
        case 4: return conversionInto(type, depth);
        case 5:
            return call(type, QStringLiteral("MUX"), {selectorOf(3), expression(type, depth + 1), operand(type, depth), operand(type, depth)});
        case 6: return call(type, QStringLiteral("LIMIT"), {expression(type, depth + 1), expression(type, depth + 1), expression(type, depth + 1)});
        case 7:
            if (isUnsigned(type))
                return call(type, QStringLiteral("MAX"), {expression(type, depth + 1), operand(type, depth)});
            return negation(type, expression(type, depth + 1));
        case 8: return isUnsigned(type) ? call(type, QStringLiteral("MIN"), {expression(type, depth + 1), operand(type, depth)})
                                        : call(type, QStringLiteral("ABS"), {expression(type, depth + 1)});
        case 9:
            if (real) {
                static const char *const math[] = {"SQRT", "SIN", "COS", "EXP", "LN", "ATAN"};
                return call(type, QLatin1String(math[pick(6)]), {expression(type, depth + 1)});
            }
            return binaryNode(type, QStringLiteral("MOD"), QStringLiteral("MOD"), expression(type, depth + 1), divisor(type, depth));
        default: return call(type, QStringLiteral("SEL"), {expression(QStringLiteral("BOOL"), depth + 1), expression(type, depth + 1), operand(type, depth)});
        }
    }

    // ---- printing

    static QString stOf(const NodePtr &n)
    {
        switch (n->kind) {
        case Kind::Leaf: return n->text;
        case Kind::Binary: return QStringLiteral("(%1 %2 %3)").arg(stOf(n->args[0]), n->text, stOf(n->args[1]));
        case Kind::Unary: return n->text == QLatin1String("NOT") ? QStringLiteral("(NOT %1)").arg(stOf(n->args[0])) : QStringLiteral("(-%1)").arg(stOf(n->args[0]));
        case Kind::Call: {
            QStringList args;
            for (const NodePtr &a : n->args)
                args << stOf(a);
            return n->text + QLatin1Char('(') + args.join(QStringLiteral(", ")) + QLatin1Char(')');
        }
        }
        return {};
    }

    // IL that leaves the node's value as the current result. Operands of IL instructions are
    // variables or literals: anything else is computed first into a temporary of its type.
    QString ilOf(const NodePtr &n, QString &before)
    {
        switch (n->kind) {
        case Kind::Leaf: return QStringLiteral(" LD %1\n").arg(n->text);
        case Kind::Unary:
            if (n->text == QLatin1String("NOT"))
                return ilOf(n->args[0], before) + QStringLiteral(" NOT\n");
            return ilOf(n->args[0], before) + QStringLiteral(" MUL -1\n"); // -x, also for -0.0
        case Kind::Binary: {
            const QString left = ilOf(n->args[0], before);
            const NodePtr &right = n->args[1];
            if (right->kind == Kind::Leaf)
                return left + QStringLiteral(" %1 %2\n").arg(n->ilOp, right->text);
            return left + QStringLiteral(" %1(\n").arg(n->ilOp) + ilOf(right, before) + QStringLiteral(" )\n");
        }
        case Kind::Call: {
            QStringList operands;
            for (size_t i = 1; i < n->args.size(); ++i)
                operands << ilOperand(n->args[i], n->type, before);
            const QString first = ilOf(n->args[0], before);
            return first + QStringLiteral(" %1 %2\n").arg(n->text, operands.join(QStringLiteral(", ")));
        }
        }
        return {};
    }

    // A further operand of a function (SEL G, IN0, IN1): a variable or literal, or a temporary of
    // the type the function gives it (an untyped bit pattern takes the function's type).
    QString ilOperand(const NodePtr &n, const QString &contextType, QString &before)
    {
        if (n->kind == Kind::Leaf)
            return n->text;
        const QString temp = QStringLiteral("t%1").arg(m_ilTemps.size());
        m_ilTemps.push_back({temp, n->type.isEmpty() ? contextType : n->type, QString()});
        QString inner;
        const QString value = ilOf(n, inner);
        before += inner + value + QStringLiteral(" ST %1\n").arg(temp);
        return temp;
    }

    // An assignment in IL, sometimes over a jump: "JMP L / LD junk / L: ST x" stores the value
    // computed before the jump.
    QString ilAssign(const QString &target, const QString &type, const NodePtr &value)
    {
        QString before;
        const QString body = ilOf(value, before);
        QString text = before + body;
        if (chance(35)) {
            const QString label = QStringLiteral("Over%1").arg(m_labels++);
            const QString junk = type == QLatin1String("BOOL") ? QStringLiteral("TRUE") : type + QLatin1Char('#') + literalValue(type);
            text += QStringLiteral(" JMP %1\n LD %2\n%1: ST %3\n").arg(label, junk, target);
        } else {
            text += QStringLiteral(" ST %1\n").arg(target);
        }
        return text;
    }

    // ---- statements

    void statement(int depth, QString &st, QString &il)
    {
        const int kind = depth >= 2 ? 0 : pick(10);
        if (kind == 1 || kind == 2) {
            const NodePtr condition = expression(QStringLiteral("BOOL"), 1);
            const int k = m_labels++;
            QString before;
            const QString test = ilOf(condition, before);
            QString thenSt, thenIl, elseSt, elseIl;
            statement(depth + 1, thenSt, thenIl);
            statement(depth + 1, elseSt, elseIl);
            st += QStringLiteral("IF %1 THEN\n%2ELSE\n%3END_IF;\n").arg(stOf(condition), thenSt, elseSt);
            il += before + test + QStringLiteral(" JMPCN Else%1\n").arg(k) + thenIl + QStringLiteral(" JMP End%1\nElse%1:\n").arg(k) + elseIl
                + QStringLiteral("End%1:\n").arg(k);
            return;
        }
        if (kind == 3) {
            caseStatement(depth, st, il);
            return;
        }
        if (kind == 4 && depth == 0) {
            const QString counter = QStringLiteral("k%1").arg(depth + 1);
            const int low = pick(4) - 1, high = pick(6);
            QString bodySt, bodyIl;
            statement(depth + 1, bodySt, bodyIl);
            const int k = m_labels++;
            st += QStringLiteral("FOR %1 := %2 TO %3 DO\n%4END_FOR;\n").arg(counter).arg(low).arg(high).arg(bodySt);
            il += QStringLiteral(" LD %1\n ST %2\nTop%3:\n LD %2\n GT %4\n JMPC Done%3\n").arg(low).arg(counter).arg(k).arg(high) + bodyIl
                + QStringLiteral(" LD %1\n ADD 1\n ST %1\n JMP Top%2\nDone%2:\n").arg(counter).arg(k);
            return;
        }
        const Variable &target = m_state[size_t(pick(int(m_state.size())))];
        const NodePtr value = chance(15) && target.type != QLatin1String("BOOL") ? literalsOnly(target.type) : expression(target.type, 0);
        st += QStringLiteral("%1 := %2;\n").arg(target.name, stOf(value));
        il += ilAssign(target.name, target.type, value);
    }

    // A selection of literals only, typed by the variable it is assigned to (s := MUX(k, 10, -99)).
    NodePtr literalsOnly(const QString &type)
    {
        if (isRealType(type) || isUnsigned(type))
            return call(type, QStringLiteral("SEL"), {expression(QStringLiteral("BOOL"), 2), untypedLiteral(type), untypedLiteral(type)});
        QString low = literalValue(type, true);
        return call(type, QStringLiteral("MUX"), {selectorOf(2), untypedLiteral(type, true), leaf(QString(), low, true)});
    }

    void caseStatement(int depth, QString &st, QString &il)
    {
        static const char *const selectorTypes[] = {"SINT", "INT", "DINT", "USINT", "UINT"};
        const QString type = QLatin1String(selectorTypes[pick(5)]);
        const NodePtr selector = chance(50) ? binaryNode(type, QStringLiteral("MOD"), QStringLiteral("MOD"), expression(type, 1), leaf(QString(), QStringLiteral("6"), true))
                                            : variableOf(type);
        const int k = m_labels++;
        const QString temp = QStringLiteral("c%1").arg(k);
        m_ilTemps.push_back({temp, type, QString()});
        QString before;
        const QString value = ilOf(selector, before);
        QString ilTests = before + value + QStringLiteral(" ST %1\n").arg(temp);
        QString stText = QStringLiteral("CASE %1 OF\n").arg(stOf(selector));
        QString ilBodies;
        const bool isSigned = !isUnsigned(type);
        for (int b = 0, n = 1 + pick(3); b < n; ++b) {
            QStringList labels;
            for (int l = 0, m = 1 + pick(2); l < m; ++l) {
                const int low = isSigned ? pick(12) - 5 : pick(8);
                if (chance(30)) {
                    const int high = low + pick(3);
                    labels << QStringLiteral("%1..%2").arg(low).arg(high);
                    ilTests += QStringLiteral(" LD %1\n GE %2\n AND(\n LD %1\n LE %3\n )\n JMPC Case%4_%5\n").arg(temp).arg(low).arg(high).arg(k).arg(b);
                } else {
                    labels << QString::number(low);
                    ilTests += QStringLiteral(" LD %1\n EQ %2\n JMPC Case%3_%4\n").arg(temp).arg(low).arg(k).arg(b);
                }
            }
            QString bodySt, bodyIl;
            statement(depth + 1, bodySt, bodyIl);
            stText += labels.join(QStringLiteral(", ")) + QStringLiteral(":\n") + bodySt;
            ilBodies += QStringLiteral("Case%1_%2:\n").arg(k).arg(b) + bodyIl + QStringLiteral(" JMP Esac%1\n").arg(k);
        }
        QString elseSt, elseIl;
        statement(depth + 1, elseSt, elseIl);
        st += stText + QStringLiteral("ELSE\n") + elseSt + QStringLiteral("END_CASE;\n");
        il += ilTests + QStringLiteral(" JMP Else%1\n").arg(k) + ilBodies + QStringLiteral("Else%1:\n").arg(k) + elseIl + QStringLiteral("Esac%1:\n").arg(k);
    }

    void build()
    {
        // Inputs: one or two of most types; state: what the statements write.
        int n = 0;
        for (const QString &t : integerTypes() + bitTypes() + realTypes() + QStringList{QStringLiteral("BOOL"), QStringLiteral("DINT")}) {
            m_inputs.push_back({QStringLiteral("in%1").arg(n++), t, t == QLatin1String("BOOL") ? literalValue(t) : t + QLatin1Char('#') + literalValue(t)});
            if (chance(50))
                m_state.push_back({QStringLiteral("v%1").arg(n++), t, t == QLatin1String("BOOL") ? literalValue(t) : t + QLatin1Char('#') + literalValue(t)});
        }
        if (m_state.empty())
            m_state.push_back({QStringLiteral("v%1").arg(n++), QStringLiteral("INT"), QStringLiteral("INT#1")});
        for (int i = 0, count = 2 + pick(5); i < count; ++i)
            statement(0, m_st, m_il);
    }

    QString text(bool constantInputs, const QString &body, const std::vector<Variable> &extra = {}) const
    {
        QString declarations = constantInputs ? QStringLiteral("VAR CONSTANT\n") : QStringLiteral("VAR\n");
        for (const Variable &v : m_inputs)
            declarations += QStringLiteral("%1 : %2 := %3;\n").arg(v.name, v.type, v.initial);
        declarations += QStringLiteral("END_VAR\nVAR\nk1 : DINT; k2 : DINT;\n");
        for (const Variable &v : m_state)
            declarations += QStringLiteral("%1 : %2 := %3;\n").arg(v.name, v.type, v.initial);
        for (const Variable &v : extra)
            declarations += QStringLiteral("%1 : %2;\n").arg(v.name, v.type);
        return QStringLiteral("PROGRAM Main\n%1END_VAR\n%2END_PROGRAM\n").arg(declarations, body);
    }

    QRandomGenerator m_random;
    std::vector<Variable> m_inputs;
    std::vector<Variable> m_state;
    std::vector<Variable> m_ilTemps;
    QString m_st;
    QString m_il;
    int m_labels = 0;
};

} // namespace iec::interp::testing
