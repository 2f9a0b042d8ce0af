#include "interpreter/compiler/lexer.h"
#include "interpreter/compiler/literals.h"

#include <QTest>

using namespace iec::interp;

namespace {

QString kindName(TokenKind kind)
{
    switch (kind) {
    case TokenKind::Identifier: return QStringLiteral("Id");
    case TokenKind::Keyword: return QStringLiteral("Kw");
    case TokenKind::TypeName: return QStringLiteral("Type");
    case TokenKind::IntegerLiteral: return QStringLiteral("Int");
    case TokenKind::RealLiteral: return QStringLiteral("Real");
    case TokenKind::TimeLiteral: return QStringLiteral("Time");
    case TokenKind::DateTimeLiteral: return QStringLiteral("Date");
    case TokenKind::StringLiteral: return QStringLiteral("Str");
    case TokenKind::WStringLiteral: return QStringLiteral("WStr");
    case TokenKind::DirectAddress: return QStringLiteral("Addr");
    case TokenKind::Operator: return QStringLiteral("Op");
    case TokenKind::Comment: return QStringLiteral("Com");
    case TokenKind::Pragma: return QStringLiteral("Prag");
    case TokenKind::Error: return QStringLiteral("Err");
    }
    return {};
}

// "Kind:text" for each token, joined with spaces: compact enough to read the tables below.
QString describe(QStringView text, const std::vector<Token> &tokens)
{
    QStringList parts;
    for (const Token &t : tokens)
        parts << kindName(t.kind) + QLatin1Char(':') + text.mid(t.offset, t.length).toString();
    return parts.join(QLatin1Char(' '));
}

} // namespace

class TestLexer : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void identifiers_data();
    void identifiers();
    void tokens_data();
    void tokens();
    void lineStates_data();
    void lineStates();
    void integers_data();
    void integers();
    void reals_data();
    void reals();
    void durations_data();
    void durations();
    void dates_data();
    void dates();
    void strings_data();
    void strings();
    void wordClasses();
};

void TestLexer::tokens_data()
{
    QTest::addColumn<QString>("source");
    QTest::addColumn<QString>("expected");
    auto row = [](const char *name, const char *source, const char *expected) {
        QTest::newRow(name) << QString::fromUtf8(source) << QString::fromUtf8(expected);
    };
    row("assignment", "x := y + 1;", "Id:x Op::= Id:y Op:+ Int:1 Op:;");
    row("keywords any case", "if a then END_IF", "Kw:if Id:a Kw:then Kw:END_IF");
    row("type names", "x : INT; y: Time_Of_Day;", "Id:x Op:: Type:INT Op:; Id:y Op:: Type:Time_Of_Day Op:;");
    row("underscored integer", "1_000_000", "Int:1_000_000");
    row("binary", "2#1010_0101", "Int:2#1010_0101");
    row("octal", "8#777", "Int:8#777");
    row("hex", "16#FF_ff", "Int:16#FF_ff");
    row("bad binary digit", "2#102", "Err:2#102");
    row("bad base", "3#12", "Err:3#12");
    row("number glued to letters", "12ab", "Err:12ab");
    row("typed int", "INT#5", "Int:INT#5");
    row("typed negative int", "INT#-5", "Int:INT#-5");
    row("typed hex word", "WORD#16#FFFF", "Int:WORD#16#FFFF");
    row("bool one", "BOOL#1", "Int:BOOL#1");
    row("bool true", "BOOL#TRUE", "Int:BOOL#TRUE");
    row("bool bad", "BOOL#maybe", "Err:BOOL#maybe");
    row("typed int with fraction", "INT#1.5", "Err:INT#1.5");
    row("real", "1.5", "Real:1.5");
    // After a member's dot, a bit number (found by fuzz_typetext: "L1.0 .25" printed as L1.0.25).
    row("bit of a bit", "x.0.25", "Id:x Op:. Int:0 Op:. Int:25");
    row("bit after space", "x. 3", "Id:x Op:. Int:3");
    row("bit glued to letters", "x.0ab", "Id:x Op:. Err:0ab");
    row("real exponent", "1.0E-3", "Real:1.0E-3");
    row("real exponent plus", "2.5e+10", "Real:2.5e+10");
    row("integer exponent", "1e6", "Real:1e6");
    row("typed real", "REAL#2.5", "Real:REAL#2.5");
    row("typed lreal from int", "LREAL#2", "Real:LREAL#2");
    row("range is not a real", "1..10", "Int:1 Op:.. Int:10");
    row("bit access", "w.3", "Id:w Op:. Int:3");
    row("time", "T#1h2m3.5s", "Time:T#1h2m3.5s");
    row("time lower case", "t#10s", "Time:t#10s");
    row("time negative", "TIME#-5ms", "Time:TIME#-5ms");
    row("time underscores", "T#1d_2h_3m", "Time:T#1d_2h_3m");
    row("time all units", "T#1d2h3m4s5ms6us7ns", "Time:T#1d2h3m4s5ms6us7ns");
    row("ltime", "LTIME#1ns", "Time:LTIME#1ns");
    row("lt short", "LT#5us", "Time:LT#5us");
    row("time units out of order", "T#1s2h", "Err:T#1s2h");
    row("time unknown unit", "T#5x", "Err:T#5x");
    row("date", "D#2024-01-01", "Date:D#2024-01-01");
    row("date long", "DATE#2024-02-29", "Date:DATE#2024-02-29");
    row("ldate", "LDATE#2000-12-31", "Date:LDATE#2000-12-31");
    row("date not leap", "D#2023-02-29", "Err:D#2023-02-29");
    row("tod", "TOD#12:00:00", "Date:TOD#12:00:00");
    row("tod fraction", "TIME_OF_DAY#23:59:59.5", "Date:TIME_OF_DAY#23:59:59.5");
    row("tod bad hour", "TOD#24:00:00", "Err:TOD#24:00:00");
    row("dt", "DT#2024-01-01-12:00:00", "Date:DT#2024-01-01-12:00:00");
    row("date and time long", "DATE_AND_TIME#1970-01-01-00:00:01.25",
        "Date:DATE_AND_TIME#1970-01-01-00:00:01.25");
    row("string", "'it$'s'", "Str:'it$'s'");
    row("string escapes", "'$$$L$N$P$R$T$0A'", "Str:'$$$L$N$P$R$T$0A'");
    row("string bad escape", "'$Z'", "Err:'$Z'");
    row("unterminated string", "'abc\nx", "Err:'abc Id:x");
    row("wide string", "\"wide $\"q$\" $00E4\"", "WStr:\"wide $\"q$\" $00E4\"");
    row("typed string", "STRING#'a'", "Str:STRING#'a'");
    row("empty string", "''", "Str:''");
    row("string keeps comment marks", "'(* no *)'", "Str:'(* no *)'");
    row("input bit", "%IX0.0", "Addr:%IX0.0");
    row("output word", "%QW3", "Addr:%QW3");
    row("memory dword", "%MD10", "Addr:%MD10");
    row("lower case address", "%qx1.7", "Addr:%qx1.7");
    row("unlocated", "%I*", "Addr:%I*");
    row("no size prefix", "%I1.2", "Addr:%I1.2");
    row("multi level", "%IW1.2.3", "Addr:%IW1.2.3");
    row("bad area", "%Z1.2 x", "Err:%Z1.2 Id:x");
    row("address then semicolon", "AT %QX0.1 : BOOL;", "Kw:AT Addr:%QX0.1 Op:: Type:BOOL Op:;");
    row("comment", "a (* note *) b", "Id:a Com:(* note *) Id:b");
    row("nested comment", "(* a (* b *) c *) d", "Com:(* a (* b *) c *) Id:d");
    row("line comment", "a // rest (* \nb", "Id:a Com:// rest (*  Id:b");
    row("pragma", "{attribute 'x'} a", "Prag:{attribute 'x'} Id:a");
    row("operators", ":= => ** <> <= >= = < > & ( ) [ ] , ; : . .. + - * /",
        "Op::= Op:=> Op:** Op:<> Op:<= Op:>= Op:= Op:< Op:> Op:& Op:( Op:) Op:[ Op:] Op:, Op:; Op:: Op:. Op:.. "
        "Op:+ Op:- Op:* Op:/");
    row("power without spaces", "a**2", "Id:a Op:** Int:2");
    row("il operators", "LD 5\nMUL (6\nADD 7\n)\nST ERG",
        "Kw:LD Int:5 Kw:MUL Op:( Int:6 Kw:ADD Int:7 Op:) Kw:ST Id:ERG");
    row("il conditional", "JMPC next JMPCN x CALC t RETCN ANDN b XORN c LDN d STN e",
        "Kw:JMPC Id:next Kw:JMPCN Id:x Kw:CALC Id:t Kw:RETCN Kw:ANDN Id:b Kw:XORN Id:c Kw:LDN Id:d Kw:STN Id:e");
    row("sfc", "INITIAL_STEP s1: ACTION_1(L, T#10s, DN1); END_STEP",
        "Kw:INITIAL_STEP Id:s1 Op:: Id:ACTION_1 Op:( Id:L Op:, Time:T#10s Op:, Id:DN1 Op:) Op:; Kw:END_STEP");
    row("enum qualified", "Color#Red", "Id:Color#Red");
    row("ld date is not the il operator", "LD#2024-01-01", "Date:LD#2024-01-01");
    row("unknown character", "a ? b", "Id:a Err:? Id:b");
    row("non ascii letter", "a := \u00e4;", "Id:a Op::= Err:\u00e4 Op:;");
    row("chinese comment", "x (* \u5f00\u5173 *)", "Id:x Com:(* \u5f00\u5173 *)");
    row("var sections", "VAR_INPUT RETAIN CONSTANT NON_RETAIN END_VAR",
        "Kw:VAR_INPUT Kw:RETAIN Kw:CONSTANT Kw:NON_RETAIN Kw:END_VAR");
    row("array init with repetition", "ARRAY[1..3] OF INT := [3(0)]",
        "Kw:ARRAY Op:[ Int:1 Op:.. Int:3 Op:] Kw:OF Type:INT Op::= Op:[ Int:3 Op:( Int:0 Op:) Op:]");
    row("configuration", "TASK t1(INTERVAL := T#10ms, PRIORITY := 1);",
        "Kw:TASK Id:t1 Op:( Kw:INTERVAL Op::= Time:T#10ms Op:, Kw:PRIORITY Op::= Int:1 Op:) Op:;");
}

void TestLexer::tokens()
{
    QFETCH(QString, source);
    QFETCH(QString, expected);
    QCOMPARE(describe(source, tokenize(source)), expected);
}

void TestLexer::lineStates_data()
{
    // Lines lexed one by one, as the highlighter does, with the state carried between them.
    QTest::addColumn<QStringList>("lines");
    QTest::addColumn<QStringList>("expected");
    QTest::addColumn<QList<int>>("depths");
    QTest::addColumn<QList<bool>>("pragmas");
    QTest::newRow("comment over lines")
        << QStringList{QStringLiteral("a (* one"), QStringLiteral("two"), QStringLiteral("three *) b")}
        << QStringList{QStringLiteral("Id:a Com:(* one"), QStringLiteral("Com:two"), QStringLiteral("Com:three *) Id:b")}
        << QList<int>{1, 1, 0} << QList<bool>{false, false, false};
    QTest::newRow("nested over lines")
        << QStringList{QStringLiteral("(* (*"), QStringLiteral("*)"), QStringLiteral(""), QStringLiteral("*) x")}
        << QStringList{QStringLiteral("Com:(* (*"), QStringLiteral("Com:*)"), QString(), QStringLiteral("Com:*) Id:x")}
        << QList<int>{2, 1, 1, 0} << QList<bool>{false, false, false, false};
    QTest::newRow("pragma over lines")
        << QStringList{QStringLiteral("{ pragma"), QStringLiteral("} y")}
        << QStringList{QStringLiteral("Prag:{ pragma"), QStringLiteral("Prag:} Id:y")}
        << QList<int>{0, 0} << QList<bool>{true, false};
    QTest::newRow("line comment does not carry")
        << QStringList{QStringLiteral("// (*"), QStringLiteral("z")}
        << QStringList{QStringLiteral("Com:// (*"), QStringLiteral("Id:z")}
        << QList<int>{0, 0} << QList<bool>{false, false};
}

void TestLexer::lineStates()
{
    QFETCH(QStringList, lines);
    QFETCH(QStringList, expected);
    QFETCH(QList<int>, depths);
    QFETCH(QList<bool>, pragmas);
    LexState state;
    for (qsizetype i = 0; i < lines.size(); ++i) {
        const auto tokens = tokenize(lines[i], state);
        QCOMPARE(describe(lines[i], tokens), expected[i]);
        QCOMPARE(state.commentDepth, depths[i]);
        QCOMPARE(state.inPragma, pragmas[i]);
    }
}

void TestLexer::integers_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<bool>("valid");
    QTest::addColumn<bool>("negative");
    QTest::addColumn<quint64>("magnitude");
    QTest::newRow("decimal") << QStringLiteral("1_000") << true << false << quint64{1000};
    QTest::newRow("negative") << QStringLiteral("-42") << true << true << quint64{42};
    QTest::newRow("binary") << QStringLiteral("2#1010") << true << false << quint64{10};
    QTest::newRow("octal") << QStringLiteral("8#17") << true << false << quint64{15};
    QTest::newRow("hex") << QStringLiteral("16#FF_FF") << true << false << quint64{65535};
    QTest::newRow("max") << QStringLiteral("16#FFFF_FFFF_FFFF_FFFF") << true << false << ~quint64{0};
    QTest::newRow("too big") << QStringLiteral("18446744073709551616") << false << false << quint64{0};
    QTest::newRow("double underscore") << QStringLiteral("1__0") << false << false << quint64{0};
    QTest::newRow("trailing underscore") << QStringLiteral("10_") << false << false << quint64{0};
}

void TestLexer::integers()
{
    QFETCH(QString, text);
    QFETCH(bool, valid);
    QFETCH(bool, negative);
    QFETCH(quint64, magnitude);
    const auto value = decodeInteger(text);
    QCOMPARE(value.has_value(), valid);
    if (valid) {
        QCOMPARE(value->negative, negative);
        QCOMPARE(value->magnitude, magnitude);
    }
}

void TestLexer::reals_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<double>("value");
    QTest::newRow("plain") << QStringLiteral("1.5") << 1.5;
    QTest::newRow("exponent") << QStringLiteral("1.0E-3") << 1.0e-3;
    QTest::newRow("negative") << QStringLiteral("-2.5e2") << -250.0;
    QTest::newRow("underscores") << QStringLiteral("1_000.5") << 1000.5;
    QTest::newRow("integer body") << QStringLiteral("2") << 2.0;
    QTest::newRow("nearest double") << QStringLiteral("1.1E-3") << 1.1e-3;
}

void TestLexer::reals()
{
    QFETCH(QString, text);
    QFETCH(double, value);
    const auto decoded = decodeReal(text);
    QVERIFY(decoded.has_value());
    QCOMPARE(*decoded, value);
}

void TestLexer::durations_data()
{
    QTest::addColumn<QString>("literal");
    QTest::addColumn<qint64>("nanoseconds");
    constexpr qint64 ms = 1'000'000;
    QTest::newRow("1h2m3.5s") << QStringLiteral("T#1h2m3.5s") << (3723 * 1000 + 500) * ms;
    QTest::newRow("negative") << QStringLiteral("T#-5ms") << -5 * ms;
    QTest::newRow("fraction of ms") << QStringLiteral("T#1.5ms") << qint64{1'500'000};
    QTest::newRow("days") << QStringLiteral("TIME#1d_2h") << 26 * 3600 * 1000 * ms;
    QTest::newRow("ns") << QStringLiteral("LTIME#1us1ns") << qint64{1001};
    QTest::newRow("minutes overflow allowed") << QStringLiteral("T#90m") << 90 * 60 * 1000 * ms;
    QTest::newRow("bare number is ms") << QStringLiteral("T#100") << 100 * ms;
}

void TestLexer::durations()
{
    QFETCH(QString, literal);
    QFETCH(qint64, nanoseconds);
    const auto value = decodeDuration(splitTypedLiteral(literal).body);
    QVERIFY(value.has_value());
    QCOMPARE(*value, nanoseconds);
}

void TestLexer::dates_data()
{
    QTest::addColumn<QString>("literal");
    QTest::addColumn<qint64>("nanoseconds");
    constexpr qint64 s = 1'000'000'000;
    QTest::newRow("epoch") << QStringLiteral("D#1970-01-01") << qint64{0};
    QTest::newRow("2024") << QStringLiteral("D#2024-01-01") << 19723 * 86400 * s;
    QTest::newRow("before epoch") << QStringLiteral("D#1969-12-31") << -86400 * s;
    QTest::newRow("tod") << QStringLiteral("TOD#12:00:00.5") << 12 * 3600 * s + s / 2;
    QTest::newRow("tod without seconds") << QStringLiteral("TOD#01:02") << 3720 * s;
    QTest::newRow("dt") << QStringLiteral("DT#2024-01-01-12:00:00") << (19723 * 86400 + 12 * 3600) * s;
}

void TestLexer::dates()
{
    QFETCH(QString, literal);
    QFETCH(qint64, nanoseconds);
    const LiteralParts parts = splitTypedLiteral(literal);
    std::optional<std::int64_t> value;
    switch (literalFamilyOfPrefix(parts.typePrefix)) {
    case LiteralFamily::Date: value = decodeDate(parts.body); break;
    case LiteralFamily::TimeOfDay: value = decodeTimeOfDay(parts.body); break;
    case LiteralFamily::DateAndTime: value = decodeDateAndTime(parts.body); break;
    default: QFAIL("not a date literal");
    }
    QVERIFY(value.has_value());
    QCOMPARE(*value, nanoseconds);
}

void TestLexer::strings_data()
{
    QTest::addColumn<QString>("literal");
    QTest::addColumn<QString>("value");
    QTest::newRow("plain") << QStringLiteral("'abc'") << QStringLiteral("abc");
    QTest::newRow("quote") << QStringLiteral("'it$'s'") << QStringLiteral("it's");
    QTest::newRow("dollar") << QStringLiteral("'5$$'") << QStringLiteral("5$");
    QTest::newRow("controls") << QStringLiteral("'$L$N$P$R$T'") << QStringLiteral("\n\n\f\r\t");
    QTest::newRow("hex") << QStringLiteral("'$41$0a'") << QStringLiteral("A\n");
    QTest::newRow("wide hex") << QStringLiteral("\"$00E4\"") << QString(QChar(0xe4));
    QTest::newRow("wide quote") << QStringLiteral("\"$\"\"") << QStringLiteral("\"");
    QTest::newRow("lower case escape") << QStringLiteral("'$n'") << QStringLiteral("\n");
}

void TestLexer::strings()
{
    QFETCH(QString, literal);
    QFETCH(QString, value);
    const auto decoded = decodeString(literal);
    QVERIFY(decoded.has_value());
    QCOMPARE(*decoded, value);
}

void TestLexer::wordClasses()
{
    QVERIFY(isKeyword(u"end_if"));
    QVERIFY(isKeyword(u"JMPCN"));
    QVERIFY(!isKeyword(u"Counter"));
    QVERIFY(isTypeName(u"lreal"));
    QVERIFY(!isTypeName(u"TON"));
    QVERIFY(isIlOperator(u"ST"));
    QVERIFY(isIlOperator(u"r"));
    QVERIFY(!isIlOperator(u"IF"));
}

void TestLexer::identifiers_data()
{
    QTest::addColumn<QString>("word");
    QTest::addColumn<bool>("shape");
    QTest::addColumn<bool>("identifier");
    QTest::newRow("plain") << QStringLiteral("Motor1") << true << true;
    QTest::newRow("leading underscore") << QStringLiteral("_x") << true << true;
    QTest::newRow("single underscores") << QStringLiteral("a_b_c") << true << true;
    QTest::newRow("double underscore") << QStringLiteral("a__b") << false << false;
    QTest::newRow("trailing underscore") << QStringLiteral("a_") << false << false;
    QTest::newRow("digit first") << QStringLiteral("1a") << false << false;
    QTest::newRow("non-ASCII") << QStringLiteral("Motör") << false << false;
    QTest::newRow("empty") << QString() << false << false;
    QTest::newRow("keyword") << QStringLiteral("end_if") << true << false;
    QTest::newRow("type name") << QStringLiteral("INT") << true << false;
}

void TestLexer::identifiers()
{
    QFETCH(QString, word);
    QFETCH(bool, shape);
    QFETCH(bool, identifier);
    QCOMPARE(iec::interp::hasIdentifierShape(word), shape);
    QCOMPARE(iec::interp::isIecIdentifier(word), identifier);
}

QTEST_GUILESS_MAIN(TestLexer)
#include "tst_lexer.moc"
