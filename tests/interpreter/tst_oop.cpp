// Object orientation as CODESYS 3.5 writes it (IEC 61131-3 ed.3): methods, properties, EXTENDS,
// interfaces with dynamic dispatch, THIS^ and SUPER^, access specifiers, ABSTRACT/FINAL; in .st
// text and in a PLCopen file with CODESYS's addData (which is written back unchanged).
#include "tracerunner.h"

#include "interpreter/frontend/projectsource.h"
#include "model/plcopen/reader.h"
#include "model/plcopen/writer.h"

#include <QTest>

using namespace iec;
using namespace iec::interp;
using namespace iec::interp::testing;
using namespace iec::interp::testing::table;

namespace {

// A counter with a method, a property and a derived block that overrides the method.
const char *const kCounters = R"(
INTERFACE ICount
METHOD Step : INT
VAR_INPUT amount : INT; END_VAR
END_METHOD
PROPERTY Value : INT
GET END_GET
END_PROPERTY
END_INTERFACE

FUNCTION_BLOCK Counter IMPLEMENTS ICount
VAR n : INT; END_VAR
VAR_OUTPUT calls : INT; END_VAR
calls := calls + 1;
METHOD Step : INT
VAR_INPUT amount : INT; END_VAR
n := n + amount;
Step := n;
END_METHOD
METHOD PRIVATE Secret : INT
Secret := 42;
END_METHOD
PROPERTY Value : INT
GET Value := n; END_GET
SET n := Value; END_SET
END_PROPERTY
END_FUNCTION_BLOCK

FUNCTION_BLOCK Double EXTENDS Counter
METHOD Step : INT
VAR_INPUT amount : INT; END_VAR
Step := SUPER^.Step(amount := 2 * amount);
END_METHOD
END_FUNCTION_BLOCK
)";

// A block with an INTERNAL method and a property that can only be written.
const char *const kGate = R"(
FUNCTION_BLOCK Gate
VAR lim : INT; END_VAR
METHOD INTERNAL Twice : INT
VAR_INPUT x : INT; END_VAR
Twice := 2 * x;
END_METHOD
PROPERTY Limit : INT
SET lim := Limit; END_SET
END_PROPERTY
METHOD Check : BOOL
VAR_INPUT x : INT; END_VAR
Check := x > lim;
END_METHOD
END_FUNCTION_BLOCK
)";

} // namespace

class TestOop : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void runs_data();
    void runs() { check(); }
    void errors_data();
    void errors();
    void plcopenAddData();
};

void TestOop::runs_data()
{
    columns();
    const QByteArray counters(kCounters);
    row("method on an instance", counters + "PROGRAM Main\nVAR c : Counter; r : INT; END_VAR\nr := c.Step(amount := 3);\n END_PROGRAM",
        {"=> r=3", "=> r=6"});
    row("property get and set", counters + "PROGRAM Main\nVAR c : Counter; r : INT; END_VAR\nc.Value := 10;\nr := c.Value + c.Step(1);\nEND_PROGRAM",
        {"=> r=21"});
    // Double's Step doubles, then runs Counter's through SUPER^.
    row("override and super", counters + "PROGRAM Main\nVAR d : Double; r : INT; END_VAR\nr := d.Step(amount := 3);\nEND_PROGRAM", {"=> r=6", "=> r=12"});
    // The same interface call reaches each object's own class.
    row("dynamic dispatch through an interface",
        counters + "PROGRAM Main\nVAR c : Counter; d : Double; i : ICount; a : INT; b : INT; v : INT; END_VAR\n"
                   "i := c; a := i.Step(1);\ni := d; b := i.Step(1);\nv := i.Value;\nEND_PROGRAM",
        {"=> a=1; b=2; v=2", "=> a=2; b=4; v=4"});
    row("this and methods inside the block",
        "FUNCTION_BLOCK Acc\nVAR total : INT; END_VAR\nVAR_OUTPUT last : INT; END_VAR\nlast := THIS^.Add(2) + Add(3);\n"
        "METHOD Add : INT\nVAR_INPUT x : INT; END_VAR\ntotal := total + x;\nAdd := total;\nEND_METHOD\nEND_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR a : Acc; END_VAR\na();\nEND_PROGRAM",
        {"=> a.last=7", "=> a.last=17"});
    // A base's method calling a method the derived block overrides runs the derived one.
    row("virtual call from the base",
        "FUNCTION_BLOCK Shape\nVAR_OUTPUT area : INT; END_VAR\narea := Size() * 10;\n"
        "METHOD Size : INT\nSize := 1;\nEND_METHOD\nEND_FUNCTION_BLOCK\n"
        "FUNCTION_BLOCK Big EXTENDS Shape\nSUPER^();\nMETHOD Size : INT\nSize := 5;\nEND_METHOD\nEND_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR s : Shape; b : Big; END_VAR\ns();\nb();\nEND_PROGRAM",
        {"=> s.area=10; b.area=50"});
    row("pointer to a base", counters + "PROGRAM Main\nVAR d : Double; p : POINTER TO Counter; r : INT; END_VAR\np := ADR(d);\nr := p^.Step(5);\nEND_PROGRAM",
        {"=> r=10"});
    row("method outputs and locals",
        "FUNCTION_BLOCK M\nMETHOD Split\nVAR_INPUT x : INT; END_VAR\nVAR_OUTPUT hi : INT; lo : INT; END_VAR\nVAR t : INT; END_VAR\n"
        "t := t + 1; hi := x / 10; lo := x MOD 10 + t;\nEND_METHOD\nEND_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR m : M; h : INT; l : INT; END_VAR\nm.Split(x := 42, hi => h, lo => l);\nEND_PROGRAM",
        {"=> h=4; l=3", "=> h=4; l=3"});
    // INTERNAL is callable anywhere in the project (CODESYS: within its namespace); a property
    // with only a SET is written, and read through the block's own method.
    row("internal method and a set-only property",
        QByteArray(kGate) + "PROGRAM Main\nVAR g : Gate; r : INT; o : BOOL; n : INT; END_VAR\nn := n + 1;\ng.Limit := 2;\nr := g.Twice(n);\no := g.Check(r);\nEND_PROGRAM",
        {"=> n=1; r=2; o=FALSE", "=> n=2; r=4; o=TRUE"});
}

void TestOop::errors_data()
{
    QTest::addColumn<QString>("source");
    QTest::addColumn<QString>("message");
    const QString counters = QString::fromUtf8(kCounters);
    QTest::newRow("private method") << counters + "PROGRAM Main\nVAR c : Counter; r : INT; END_VAR\nr := c.Secret();\nEND_PROGRAM"
                                    << "Main:37:6: error: Counter.Secret is PRIVATE and cannot be called from here.";
    QTest::newRow("protected method from outside, callable in a derived block")
        << QStringLiteral("FUNCTION_BLOCK A\nMETHOD PROTECTED P : INT\nP := 1;\nEND_METHOD\nEND_FUNCTION_BLOCK\n"
                          "FUNCTION_BLOCK B EXTENDS A\nVAR r : INT; END_VAR\nr := THIS^.P();\nEND_FUNCTION_BLOCK\n"
                          "PROGRAM Main\nVAR a : A; b : B; r : INT; END_VAR\nb();\nr := a.P();\nEND_PROGRAM")
        << "Main:13:6: error: A.P is PROTECTED and cannot be called from here.";
    QTest::newRow("set-only property read") << QString::fromLatin1(kGate) + "PROGRAM Main\nVAR g : Gate; r : INT; END_VAR\nr := g.Limit;\nEND_PROGRAM"
                                            << "Main:18:6: error: The property Limit has no GET and cannot be read.";
    QTest::newRow("abstract instance") << "FUNCTION_BLOCK ABSTRACT A\nEND_FUNCTION_BLOCK\nPROGRAM Main\nVAR a : A; END_VAR\nEND_PROGRAM"
                                       << "Main:4:5: error: A is ABSTRACT; declare an instance of a function block that extends it.";
    QTest::newRow("final base") << "FUNCTION_BLOCK FINAL A\nEND_FUNCTION_BLOCK\nFUNCTION_BLOCK B EXTENDS A\nEND_FUNCTION_BLOCK\nPROGRAM Main\nEND_PROGRAM"
                                << "B:3:1: error: A is FINAL; no function block can extend it.";
    QTest::newRow("not implemented") << counters + "FUNCTION_BLOCK Other\nEND_FUNCTION_BLOCK\nPROGRAM Main\nVAR o : Other; i : ICount; END_VAR\ni := o;\nEND_PROGRAM"
                                     << "Main:39:1: error: Other does not implement ICount.";
    const QString shape = QStringLiteral("INTERFACE IShape\nMETHOD Area : INT\nEND_METHOD\nPROPERTY Name : INT\nGET\nEND_GET\nEND_PROPERTY\nEND_INTERFACE\n"
                                         "INTERFACE ISolid EXTENDS IShape\nMETHOD Volume : INT\nEND_METHOD\nEND_INTERFACE\n");
    const QString main = QStringLiteral("PROGRAM Main\nEND_PROGRAM");
    QTest::newRow("method missing") << shape + "FUNCTION_BLOCK Sq IMPLEMENTS IShape\nPROPERTY Name : INT\nGET\nName := 1;\nEND_GET\nEND_PROPERTY\nEND_FUNCTION_BLOCK\n" + main
                                    << "Sq:13:1: error: Sq must implement the method Area of IShape.";
    QTest::newRow("getter missing") << shape + "FUNCTION_BLOCK Sq IMPLEMENTS IShape\nMETHOD Area : INT\nArea := 1;\nEND_METHOD\nEND_FUNCTION_BLOCK\n" + main
                                    << "Sq:13:1: error: Sq must implement the GET of the property Name of IShape.";
    QTest::newRow("missing from the interface it extends")
        << shape + "FUNCTION_BLOCK Cube IMPLEMENTS ISolid\nMETHOD Volume : INT\nVolume := 1;\nEND_METHOD\nMETHOD Area : INT\nArea := 1;\nEND_METHOD\nEND_FUNCTION_BLOCK\n" + main
        << "Cube:13:1: error: Cube must implement the GET of the property Name of IShape.";
    QTest::newRow("inherited from the base counts, abstract may leave out")
        << shape + "FUNCTION_BLOCK ABSTRACT Base IMPLEMENTS IShape\nMETHOD Area : INT\nArea := 1;\nEND_METHOD\nEND_FUNCTION_BLOCK\n"
               "FUNCTION_BLOCK Sq EXTENDS Base IMPLEMENTS IShape\nEND_FUNCTION_BLOCK\n" + main
        << "Sq:18:1: error: Sq must implement the GET of the property Name of IShape.";
    QTest::newRow("final method overridden")
        << "FUNCTION_BLOCK A\nMETHOD FINAL M : INT\nM := 1;\nEND_METHOD\nEND_FUNCTION_BLOCK\n"
           "FUNCTION_BLOCK B EXTENDS A\nMETHOD M : INT\nM := 2;\nEND_METHOD\nEND_FUNCTION_BLOCK\n" + main
        << "B:7:1: error: B.M cannot override A.M: it is FINAL.";
    QTest::newRow("abstract method left without code")
        << "FUNCTION_BLOCK ABSTRACT A\nMETHOD ABSTRACT M : INT\nEND_METHOD\nEND_FUNCTION_BLOCK\n"
           "FUNCTION_BLOCK B EXTENDS A\nEND_FUNCTION_BLOCK\n" + main
        << "B:5:1: error: B must implement the ABSTRACT A.M, or be ABSTRACT itself.";
    QTest::newRow("abstract method implemented, abstract block may leave it")
        << "FUNCTION_BLOCK ABSTRACT A\nMETHOD ABSTRACT M : INT\nEND_METHOD\nEND_FUNCTION_BLOCK\n"
           "FUNCTION_BLOCK ABSTRACT B EXTENDS A\nEND_FUNCTION_BLOCK\n"
           "FUNCTION_BLOCK C EXTENDS B\nMETHOD M : INT\nM := 3;\nEND_METHOD\nEND_FUNCTION_BLOCK\n" + main
        << QString();
    QTest::newRow("unknown interface") << "FUNCTION_BLOCK Sq IMPLEMENTS INope\nEND_FUNCTION_BLOCK\n" + main
                                       << "Sq:1:1: error: Sq implements INope, which is no interface of the project.";
}

void TestOop::errors()
{
    QFETCH(QString, source);
    QFETCH(QString, message);
    Diagnostics diagnostics;
    compileText(source, diagnostics);
    QCOMPARE(errorsOf(diagnostics), message);
}

void TestOop::plcopenAddData()
{
    // What CODESYS 3.5 exports: the method and the property in the block's addData, EXTENDS in its
    // interface's addData.
    const QByteArray file = R"(<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0200">
  <fileHeader companyName="" productName="CODESYS" productVersion="CODESYS V3.5 SP16" creationDateTime="2024-01-01T00:00:00" />
  <contentHeader name="oop"><coordinateInfo><fbd><scaling x="1" y="1" /></fbd><ld><scaling x="1" y="1" /></ld><sfc><scaling x="1" y="1" /></sfc></coordinateInfo></contentHeader>
  <types><dataTypes />
    <pous>
      <pou name="Base" pouType="functionBlock">
        <interface><localVars><variable name="n"><type><INT /></type></variable></localVars></interface>
        <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml"></xhtml></ST></body>
        <addData>
          <data name="http://www.3s-software.com/plcopenxml/method" handleUnknown="implementation">
            <Method name="Add" ObjectId="1">
              <interface><returnType><INT /></returnType><inputVars><variable name="x"><type><INT /></type></variable></inputVars></interface>
              <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">n := n + x;
Add := n;</xhtml></ST></body>
              <addData />
            </Method>
          </data>
          <data name="http://www.3s-software.com/plcopenxml/property" handleUnknown="implementation">
            <Property name="Count" ObjectId="2">
              <interface><returnType><INT /></returnType></interface>
              <SetAccessor><interface /><body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">n := Count;</xhtml></ST></body><addData /></SetAccessor>
              <GetAccessor><interface /><body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">Count := n;</xhtml></ST></body><addData /></GetAccessor>
              <addData />
            </Property>
          </data>
        </addData>
      </pou>
      <pou name="Derived" pouType="functionBlock">
        <interface>
          <addData>
            <data name="http://www.3s-software.com/plcopenxml/pouinheritance" handleUnknown="implementation">
              <Inheritance><Extends>Base</Extends></Inheritance>
            </data>
          </addData>
        </interface>
        <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml"></xhtml></ST></body>
      </pou>
      <pou name="PLC_PRG" pouType="program">
        <interface><localVars>
          <variable name="d"><type><derived name="Derived" /></type></variable>
          <variable name="r"><type><INT /></type></variable>
        </localVars></interface>
        <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">d.Count := 5;
r := d.Add(2) + d.Count;</xhtml></ST></body>
      </pou>
    </pous>
  </types>
  <instances><configurations /></instances>
</project>
)";
    const auto read = model::plcopen::readProject(file);
    QVERIFY(read.ok);
    Diagnostics diagnostics;
    const auto module = frontend::compileProject(read.project, diagnostics);
    QVERIFY2(module, qPrintable(errorsOf(diagnostics)));
    Runtime runtime(module);
    QCOMPARE(runSteps(runtime, {"=> PLC_PRG.r=14", "=> PLC_PRG.r=14"}), QString());
    // Read and written back: the vendor content is the same.
    const QByteArray written = model::plcopen::writeProject(read.project);
    const auto again = model::plcopen::readProject(written);
    QVERIFY(again.ok);
    QCOMPARE(again.project.types.pous.front().addData, read.project.types.pous.front().addData);
    QCOMPARE(again.project.types.pous[1].pouInterface->addData, read.project.types.pous[1].pouInterface->addData);
}

QTEST_GUILESS_MAIN(TestOop)
#include "tst_oop.moc"
