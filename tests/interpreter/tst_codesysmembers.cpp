// Methods and properties as text (interpreter/frontend/codesysmembers.h): printed from CODESYS's
// addData, read back into it exactly, edited so that the program computes something else, and
// kept when a .st file goes through the project model.
#include "tracerunner.h"

#include "interpreter/frontend/codesysmembers.h"
#include "interpreter/frontend/iecprinter.h"
#include "interpreter/frontend/iecreader.h"
#include "interpreter/frontend/projectsource.h"
#include "model/plcopen/codesysoop.h"
#include "model/plcopen/reader.h"
#include "model/plcopen/writer.h"

#include <QTest>

using namespace iec;
using namespace iec::interp;
using namespace iec::interp::frontend;
using namespace iec::interp::testing;
using namespace iec::interp::testing::table;

// Declared before the test data: moc does not read raw string literals.
class TestCodesysMembers : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void printsMembersAsEditionThreeText();
    void printedTextReadsBackToTheSameMembers();
    void editedMethodRunsAndKeepsWhatItHad_data();
    void editedMethodRunsAndKeepsWhatItHad();
    void newMemberIsWrittenInCodesysForm();
    void textThatIsNotOneMemberIsRefused_data();
    void textThatIsNotOneMemberIsRefused();
    void removedMemberGoes();
    void stFileKeepsMembersThroughTheModel();
    void stInterfacesGoToTheProjectsAddData();
    void editedInterfaceStaysWhereItStood();
    void textThatIsNotOneInterfaceIsRefused_data();
    void textThatIsNotOneInterfaceIsRefused();
};

namespace {

// Base.Add(x) adds to n and returns it; the property Count reads and writes n.
QByteArray projectXml()
{
    return R"(<?xml version="1.0" encoding="utf-8"?>
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
            <Method name="Add" ObjectId="7f3c">
              <interface><returnType><INT /></returnType><inputVars><variable name="x"><type><INT /></type></variable></inputVars></interface>
              <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">n := n + x;
Add := n;</xhtml></ST></body>
              <addData><data name="urn:other-tool" handleUnknown="preserve"><Note>kept</Note></data></addData>
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
      <pou name="PLC_PRG" pouType="program">
        <interface><localVars>
          <variable name="b"><type><derived name="Base" /></type></variable>
          <variable name="r"><type><INT /></type></variable>
        </localVars></interface>
        <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">b.Count := 5;
r := b.Add(2) + b.Count;</xhtml></ST></body>
      </pou>
    </pous>
  </types>
  <instances><configurations /></instances>
</project>
)";
}

const QString kAddText = QStringLiteral("METHOD Add : INT\n"
                                        "VAR_INPUT\n"
                                        "    x : INT;\n"
                                        "END_VAR\n"
                                        "n := n + x;\n"
                                        "Add := n;\n"
                                        "END_METHOD\n");

const QString kCountText = QStringLiteral("PROPERTY Count : INT\n"
                                          "GET\n"
                                          "Count := n;\n"
                                          "END_GET\n"
                                          "SET\n"
                                          "n := Count;\n"
                                          "END_SET\n"
                                          "END_PROPERTY\n");

model::Project loaded()
{
    const auto read = model::plcopen::readProject(projectXml());
    if (!read.ok)
        qFatal("the test project does not load");
    return read.project;
}

// Member `name` of Base replaced by `text`; the messages when it does not read.
QString replaced(model::Project &project, const QString &name, const QString &text)
{
    model::Pou &base = project.types.pous.front();
    const CodesysMemberText read = readCodesysMemberText(text, base.name);
    if (!read.definition)
        return read.diagnostics.all().empty() ? QStringLiteral("no definition") : read.diagnostics.all().front().toString();
    base.addData = model::plcopen::addDataWithMember(base.addData, name, *read.definition);
    return {};
}

QString runTwoCycles(const model::Project &project)
{
    Diagnostics diagnostics;
    const auto module = compileProject(project, diagnostics);
    if (!module)
        return errorsOf(diagnostics);
    Runtime runtime(module);
    QStringList values;
    for (int cycle = 0; cycle < 2; ++cycle) {
        runtime.runCycle();
        values << runtime.read(*runtime.find(QStringLiteral("PLC_PRG.r")));
    }
    return values.join(QLatin1Char(' '));
}

} // namespace


void TestCodesysMembers::printsMembersAsEditionThreeText()
{
    const model::Project project = loaded();
    const model::Pou &base = project.types.pous.front();
    const std::vector<CodesysMemberSummary> members = codesysMembers(base);
    QCOMPARE(members.size(), size_t(2));
    QCOMPARE(members[0].name, QStringLiteral("Add"));
    QVERIFY(!members[0].property);
    QCOMPARE(members[1].name, QStringLiteral("Count"));
    QVERIFY(members[1].property);
    bool editable = false;
    QCOMPARE(printCodesysMember(base, QStringLiteral("add"), &editable), kAddText);
    QVERIFY(editable);
    QCOMPARE(printCodesysMember(base, QStringLiteral("Count")), kCountText);
    QCOMPARE(printCodesysMember(base, QStringLiteral("Missing")), QString());
}

void TestCodesysMembers::printedTextReadsBackToTheSameMembers()
{
    model::Project project = loaded();
    const model::plcopen::CodesysClass before = model::plcopen::readCodesysClass(project.types.pous.front());
    QCOMPARE(replaced(project, QStringLiteral("Add"), kAddText), QString());
    QCOMPARE(replaced(project, QStringLiteral("Count"), kCountText), QString());
    const model::Pou &base = project.types.pous.front();
    const model::plcopen::CodesysClass after = model::plcopen::readCodesysClass(base);
    QCOMPARE(after.members.size(), before.members.size());
    for (size_t i = 0; i < after.members.size(); ++i) {
        QCOMPARE(after.members[i].name, before.members[i].name);
        QCOMPARE(after.members[i].kind, before.members[i].kind);
        QCOMPARE(after.members[i].interface.varLists, before.members[i].interface.varLists);
        QCOMPARE(after.members[i].interface.returnType, before.members[i].interface.returnType);
        QCOMPARE(after.members[i].type, before.members[i].type);
        QCOMPARE(after.members[i].body, before.members[i].body);
    }
    QCOMPARE(printCodesysMember(base, QStringLiteral("Add")), kAddText);
    QCOMPARE(printCodesysMember(base, QStringLiteral("Count")), kCountText);
    QCOMPARE(runTwoCycles(project), QStringLiteral("14 14"));
}

void TestCodesysMembers::editedMethodRunsAndKeepsWhatItHad_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("values");
    // b.Count := 5 each cycle, then r := b.Add(2) + b.Count.
    QTest::newRow("unchanged") << kAddText << QStringLiteral("14 14");
    QTest::newRow("body") << QString(kAddText).replace(QStringLiteral("n := n + x;"), QStringLiteral("n := n + 10 * x;"))
                          << QStringLiteral("50 50");
    QTest::newRow("a local variable") << QStringLiteral("METHOD Add : INT\nVAR_INPUT\n    x : INT;\nEND_VAR\nVAR\n    twice : INT;\nEND_VAR\n"
                                                        "twice := 2 * x;\nn := n + twice;\nAdd := n;\nEND_METHOD\n")
                                      << QStringLiteral("18 18");
    QTest::newRow("IL body") << QStringLiteral("METHOD Add : INT\nVAR_INPUT\n    x : INT;\nEND_VAR\nLD n\nADD x\nADD 1\nST n\nST Add\nEND_METHOD\n")
                             << QStringLiteral("16 16");
}

void TestCodesysMembers::editedMethodRunsAndKeepsWhatItHad()
{
    QFETCH(QString, text);
    QFETCH(QString, values);
    model::Project project = loaded();
    const model::AddData before = project.types.pous.front().addData;
    QCOMPARE(replaced(project, QStringLiteral("Add"), text), QString());
    QCOMPARE(runTwoCycles(project), values);
    const model::AddData &after = project.types.pous.front().addData;
    QCOMPARE(after.size(), before.size());
    QCOMPARE(after[1], before[1]); // the property's entry, byte for byte
    // Its ObjectId and the other tool's addData stay; the declaration is kept as CODESYS keeps it.
    QVERIFY2(after[0].content.startsWith(QStringLiteral("<Method name=\"Add\" ObjectId=\"7f3c\">")), qPrintable(after[0].content));
    QVERIFY(after[0].content.contains(QStringLiteral("<data name=\"urn:other-tool\" handleUnknown=\"preserve\"><Note>kept</Note></data>")));
    QVERIFY(after[0].content.contains(QStringLiteral("<InterfaceAsPlainText><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">METHOD Add : INT")));
    // Written and read again, the file holds the edit.
    const auto again = model::plcopen::readProject(model::plcopen::writeProject(project));
    QVERIFY(again.ok);
    QCOMPARE(printCodesysMember(again.project.types.pous.front(), QStringLiteral("Add")), text);
}

void TestCodesysMembers::newMemberIsWrittenInCodesysForm()
{
    model::Project project = loaded();
    QCOMPARE(replaced(project, QString(), QStringLiteral("METHOD PRIVATE Reset\nn := 0;\nEND_METHOD\n")), QString());
    const model::AddData &addData = project.types.pous.front().addData;
    QCOMPARE(addData.size(), size_t(3)); // the new method's entry, before the property below
    QCOMPARE(addData[2].name, QStringLiteral("http://www.3s-software.com/plcopenxml/method"));
    QCOMPARE(addData[2].handleUnknown, QStringLiteral("implementation"));
    QCOMPARE(addData[2].content,
        QStringLiteral("<Method name=\"Reset\"><interface/><body><ST><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">n := 0;</xhtml></ST></body>"
                       "<addData><data name=\"http://www.3s-software.com/plcopenxml/interfaceasplaintext\" handleUnknown=\"implementation\">"
                       "<InterfaceAsPlainText><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">METHOD PRIVATE Reset\n</xhtml></InterfaceAsPlainText>"
                       "</data></addData></Method>"));
    QCOMPARE(replaced(project, QString(), QStringLiteral("PROPERTY Limit : INT\nGET\nLimit := 0;\nEND_GET\nSET\nEND_SET\nEND_PROPERTY\n")),
        QString());
    // Saved and opened again, the model is the same (the monkey test saves and compares so).
    const auto again = model::plcopen::readProject(model::plcopen::writeProject(project));
    QVERIFY(again.ok);
    const model::AddData &written = project.types.pous.front().addData;
    QCOMPARE(again.project.types.pous.front().addData.size(), written.size());
    for (size_t i = 0; i < written.size(); ++i) // entry by entry, so that a failure shows the text
        QCOMPARE(again.project.types.pous.front().addData.at(i), written.at(i));
    const model::plcopen::CodesysClass read = model::plcopen::readCodesysClass(project.types.pous.front());
    QCOMPARE(read.members[read.members.size() - 3].name, QStringLiteral("Reset"));
    QCOMPARE(read.members[read.members.size() - 3].qualifiers, QStringList {QStringLiteral("PRIVATE")});
    QCOMPARE(printCodesysMember(project.types.pous.front(), QStringLiteral("Reset")),
        QStringLiteral("METHOD PRIVATE Reset\nn := 0;\nEND_METHOD\n"));
}

void TestCodesysMembers::textThatIsNotOneMemberIsRefused_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("message");
    QTest::newRow("syntax error on its line")
        << QStringLiteral("METHOD Add : INT\nVAR_INPUT\n    x : INT;\nEND_VAR\nAdd := x +;\nEND_METHOD\n")
        << QStringLiteral("Base.Add:5:");
    QTest::newRow("two methods") << QStringLiteral("METHOD A\nEND_METHOD\nMETHOD B\nEND_METHOD\n")
                                 << QStringLiteral("Base:1:1: error: Write one METHOD");
    QTest::newRow("a statement") << QStringLiteral("x := 1;\n") << QStringLiteral("Base:1:1: error: Write one METHOD");
    QTest::newRow("no END_METHOD") << QStringLiteral("METHOD A\nn := 1;\n") << QStringLiteral("Base.A:");
}

void TestCodesysMembers::textThatIsNotOneMemberIsRefused()
{
    QFETCH(QString, text);
    QFETCH(QString, message);
    model::Project project = loaded();
    const model::AddData before = project.types.pous.front().addData;
    const QString error = replaced(project, QStringLiteral("Add"), text);
    QVERIFY2(error.startsWith(message), qPrintable(error));
    QCOMPARE(project.types.pous.front().addData, before);
}

void TestCodesysMembers::removedMemberGoes()
{
    model::Project project = loaded();
    model::Pou &base = project.types.pous.front();
    const model::AddData before = base.addData;
    base.addData = model::plcopen::addDataWithoutMember(base.addData, QStringLiteral("add"));
    QCOMPARE(base.addData.size(), size_t(1));
    QCOMPARE(base.addData.front(), before[1]);
    QCOMPARE(codesysMembers(base).size(), size_t(1));
}

void TestCodesysMembers::stFileKeepsMembersThroughTheModel()
{
    const QString source = QStringLiteral("FUNCTION_BLOCK Base\nVAR\n    n : INT;\nEND_VAR\n") + kAddText + kCountText
        + QStringLiteral("END_FUNCTION_BLOCK\n"
                         "FUNCTION_BLOCK Derived EXTENDS Base\n"
                         "n := n + 1;\n" // never called: PLC_PRG uses only the members
                         "END_FUNCTION_BLOCK\n"
                         "PROGRAM PLC_PRG\nVAR\n    b : Derived;\n    r : INT;\nEND_VAR\n"
                         "b.Count := 5;\nr := b.Add(2) + b.Count;\n"
                         "END_PROGRAM\n");
    const TextReadResult read = readIecText(source, QStringLiteral("st"));
    QVERIFY2(!read.diagnostics.hasErrors(), qPrintable(errorsOf(read.diagnostics)));
    const model::Pou &base = read.project.types.pous.front();
    QCOMPARE(base.body()->text(), QString()); // the members are not the body
    QCOMPARE(printCodesysMember(base, QStringLiteral("Add")), kAddText);
    QCOMPARE(printCodesysMember(base, QStringLiteral("Count")), kCountText);
    QCOMPARE(model::plcopen::readCodesysClass(read.project.types.pous[1]).extends, QStringLiteral("Base"));
    QCOMPARE(read.project.types.pous[1].body()->text(), QStringLiteral("n := n + 1;")); // EXTENDS is no statement
    QCOMPARE(runTwoCycles(read.project), QStringLiteral("14 14"));
    // Printed as text and read again, the same model comes out.
    const QString printed = printProject(read.project);
    QVERIFY2(printed.contains(kAddText + kCountText), qPrintable(printed));
    QVERIFY(printed.contains(QStringLiteral("FUNCTION_BLOCK Derived EXTENDS Base\n")));
    const TextReadResult again = readIecText(printed, QStringLiteral("st"));
    QCOMPARE(again.project.types.pous, read.project.types.pous);
}

void TestCodesysMembers::stInterfacesGoToTheProjectsAddData()
{
    const QString interfaceText = QStringLiteral("INTERFACE ICount\n"
                                                 "METHOD Step : INT\nVAR_INPUT\n    amount : INT;\nEND_VAR\nEND_METHOD\n"
                                                 "PROPERTY Value : INT\nGET\nEND_GET\nEND_PROPERTY\n"
                                                 "END_INTERFACE\n");
    const QString source = interfaceText
        + QStringLiteral("FUNCTION_BLOCK Counter IMPLEMENTS ICount\nVAR\n    n : INT;\nEND_VAR\n"
                         "METHOD Step : INT\nVAR_INPUT\n    amount : INT;\nEND_VAR\nn := n + amount;\nStep := n;\nEND_METHOD\n"
                         "PROPERTY Value : INT\nGET\nValue := n;\nEND_GET\nEND_PROPERTY\n"
                         "END_FUNCTION_BLOCK\n"
                         "PROGRAM PLC_PRG\nVAR\n    c : Counter;\n    i : ICount;\n    r : INT;\nEND_VAR\n"
                         "i := c;\nr := i.Step(3) + i.Value;\n"
                         "END_PROGRAM\n");
    const TextReadResult read = readIecText(source, QStringLiteral("st"));
    QVERIFY2(!read.diagnostics.hasErrors(), qPrintable(errorsOf(read.diagnostics)));
    // The interface is no POU (it was read as an empty block, and shifted every body after it).
    QCOMPARE(read.project.types.pous.size(), size_t(2));
    QCOMPARE(read.project.types.pous[0].name, QStringLiteral("Counter"));
    QCOMPARE(read.project.types.pous[0].body()->text(), QString());
    QCOMPARE(read.project.types.pous[1].body()->text(), QStringLiteral("i := c;\nr := i.Step(3) + i.Value;"));
    const std::vector<model::plcopen::CodesysInterface> interfaces = model::plcopen::readCodesysInterfaces(read.project);
    QCOMPARE(interfaces.size(), size_t(1));
    QCOMPARE(interfaces[0].name, QStringLiteral("ICount"));
    QCOMPARE(interfaces[0].definition.members.size(), size_t(2));
    QCOMPARE(runTwoCycles(read.project), QStringLiteral("6 12")); // through the interface
    // Printed as text, read again, and through a PLCopen file: the same.
    const QString printed = printProject(read.project);
    QVERIFY2(printed.startsWith(interfaceText), qPrintable(printed));
    const TextReadResult again = readIecText(printed, QStringLiteral("st"));
    QCOMPARE(again.project.types.pous, read.project.types.pous);
    QCOMPARE(again.project.addData, read.project.addData);
    const auto file = model::plcopen::readProject(model::plcopen::writeProject(read.project));
    QVERIFY(file.ok);
    QCOMPARE(runTwoCycles(file.project), QStringLiteral("6 12"));
}

namespace {

// A project whose addData keeps CODESYS's INTERFACE ICount (with its ObjectId) and another
// tool's entry after it; Counter implements ICount and PLC_PRG calls it through the interface.
QByteArray interfaceProjectXml()
{
    return R"(<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0200">
  <fileHeader companyName="" productName="CODESYS" productVersion="CODESYS V3.5 SP16" creationDateTime="2024-01-01T00:00:00" />
  <contentHeader name="itf"><coordinateInfo><fbd><scaling x="1" y="1" /></fbd><ld><scaling x="1" y="1" /></ld><sfc><scaling x="1" y="1" /></sfc></coordinateInfo></contentHeader>
  <types><dataTypes />
    <pous>
      <pou name="Counter" pouType="functionBlock">
        <interface><localVars><variable name="n"><type><INT /></type></variable></localVars>
          <addData><data name="http://www.3s-software.com/plcopenxml/pouinheritance" handleUnknown="implementation"><Inheritance><Implements>ICount</Implements></Inheritance></data></addData>
        </interface>
        <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml"></xhtml></ST></body>
        <addData>
          <data name="http://www.3s-software.com/plcopenxml/method" handleUnknown="implementation">
            <Method name="Step" ObjectId="m1">
              <interface><returnType><INT /></returnType><inputVars><variable name="amount"><type><INT /></type></variable></inputVars></interface>
              <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">n := n + amount;
Step := n;</xhtml></ST></body>
              <addData />
            </Method>
          </data>
        </addData>
      </pou>
      <pou name="PLC_PRG" pouType="program">
        <interface><localVars>
          <variable name="c"><type><derived name="Counter" /></type></variable>
          <variable name="i"><type><derived name="ICount" /></type></variable>
          <variable name="r"><type><INT /></type></variable>
        </localVars></interface>
        <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">i := c;
r := i.Step(2);</xhtml></ST></body>
      </pou>
    </pous>
  </types>
  <instances><configurations /></instances>
  <addData>
    <data name="http://www.3s-software.com/plcopenxml/interface" handleUnknown="implementation">
      <Interface name="ICount" ObjectId="a1b2">
        <addData>
          <data name="http://www.3s-software.com/plcopenxml/method" handleUnknown="implementation">
            <Method name="Step" ObjectId="c3">
              <interface><returnType><INT /></returnType><inputVars><variable name="amount"><type><INT /></type></variable></inputVars></interface>
              <addData />
            </Method>
          </data>
        </addData>
      </Interface>
    </data>
    <data name="urn:other-tool" handleUnknown="preserve"><Note>kept</Note></data>
  </addData>
</project>
)";
}

const QString kICountText = QStringLiteral("INTERFACE ICount\n"
                                           "METHOD Step : INT\n"
                                           "VAR_INPUT\n"
                                           "    amount : INT;\n"
                                           "END_VAR\n"
                                           "END_METHOD\n"
                                           "END_INTERFACE\n");

} // namespace

// The IDE's interface tab: the text of an INTERFACE read back replaces it where it stood, with its
// ObjectId; a new name renames it; removed, its entry goes and the others stay.
void TestCodesysMembers::editedInterfaceStaysWhereItStood()
{
    const auto file = model::plcopen::readProject(interfaceProjectXml());
    QVERIFY(file.ok);
    model::Project project = file.project;
    QCOMPARE(runTwoCycles(project), QStringLiteral("2 4"));
    QCOMPARE(codesysInterfaceNames(project), QStringList {QStringLiteral("ICount")});
    QCOMPARE(printCodesysInterface(project, QStringLiteral("icount")), kICountText);
    QCOMPARE(printCodesysInterface(project, QStringLiteral("IOther")), QString());
    // Printed and read back: the same interface.
    const InterfaceText same = readInterfaceText(kICountText);
    QVERIFY2(same.definition, qPrintable(errorsOf(same.diagnostics)));
    model::Project again = project;
    again.addData = model::plcopen::addDataWithInterface(project.addData, QStringLiteral("ICount"), *same.definition);
    QCOMPARE(printCodesysInterface(again, QStringLiteral("ICount")), kICountText);
    QCOMPARE(runTwoCycles(again), QStringLiteral("2 4"));
    // A property added: in place, ObjectId kept, the other tool's entry after it untouched.
    QString edited = kICountText;
    edited.replace(QStringLiteral("END_INTERFACE"), QStringLiteral("PROPERTY Value : INT\nGET\nEND_GET\nEND_PROPERTY\nEND_INTERFACE"));
    const InterfaceText read = readInterfaceText(edited);
    QVERIFY2(read.definition, qPrintable(errorsOf(read.diagnostics)));
    project.addData = model::plcopen::addDataWithInterface(project.addData, QStringLiteral("ICount"), *read.definition);
    QCOMPARE(project.addData.size(), size_t(2));
    QVERIFY2(project.addData[0].content.contains(QStringLiteral("<Interface name=\"ICount\" ObjectId=\"a1b2\">")),
        qPrintable(project.addData[0].content));
    QCOMPARE(project.addData[1].name, QStringLiteral("urn:other-tool"));
    QCOMPARE(printCodesysInterface(project, QStringLiteral("ICount")), edited);
    // Counter does not implement the new property, as CODESYS requires.
    QCOMPARE(runTwoCycles(project), QStringLiteral("Counter:1:1: error: Counter must implement the GET of the property Value of ICount."));
    // Written to a file and read again: the same text.
    const auto saved = model::plcopen::readProject(model::plcopen::writeProject(project));
    QVERIFY(saved.ok);
    QCOMPARE(printCodesysInterface(saved.project, QStringLiteral("ICount")), edited);
    // Renamed in its header: where it stood, with its ObjectId; the block still names ICount,
    // which no longer exists, so the compiler says so.
    QString renamed = edited;
    renamed.replace(QStringLiteral("INTERFACE ICount"), QStringLiteral("INTERFACE ICounter"));
    project.addData = model::plcopen::addDataWithInterface(project.addData, QStringLiteral("ICount"), *readInterfaceText(renamed).definition);
    QCOMPARE(codesysInterfaceNames(project), QStringList {QStringLiteral("ICounter")});
    QVERIFY(project.addData[0].content.contains(QStringLiteral("<Interface name=\"ICounter\" ObjectId=\"a1b2\">")));
    QVERIFY(model::plcopen::keepsInterface(project.addData, QStringLiteral("icounter")));
    QVERIFY(!model::plcopen::keepsInterface(project.addData, QStringLiteral("ICount")));
    QVERIFY(runTwoCycles(project).contains(QStringLiteral("ICount")));
    // Removed: its entry goes, the other stays.
    project.addData = model::plcopen::addDataWithoutInterface(project.addData, QStringLiteral("ICounter"));
    QCOMPARE(project.addData.size(), size_t(1));
    QCOMPARE(project.addData[0].name, QStringLiteral("urn:other-tool"));
    QCOMPARE(codesysInterfaceNames(project), QStringList());
}

void TestCodesysMembers::textThatIsNotOneInterfaceIsRefused_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("message"); // the first diagnostic, as Diagnostic::toString prints it
    QTest::newRow("a function block") << QStringLiteral("FUNCTION_BLOCK F\nEND_FUNCTION_BLOCK\n")
                                      << QStringLiteral("1:1: error: This text must be one INTERFACE ... END_INTERFACE and nothing else.");
    QTest::newRow("two interfaces") << QStringLiteral("INTERFACE A\nEND_INTERFACE\nINTERFACE B\nEND_INTERFACE\n")
                                    << QStringLiteral("1:1: error: This text must be one INTERFACE ... END_INTERFACE and nothing else.");
    QTest::newRow("no end") << QStringLiteral("INTERFACE A\nMETHOD M : INT\nEND_METHOD\n") << QString();
    QTest::newRow("empty") << QString() << QStringLiteral("1:1: error: This text must be one INTERFACE ... END_INTERFACE and nothing else.");
}

void TestCodesysMembers::textThatIsNotOneInterfaceIsRefused()
{
    QFETCH(QString, text);
    QFETCH(QString, message);
    const InterfaceText read = readInterfaceText(text);
    QVERIFY(!read.definition);
    QVERIFY(read.diagnostics.hasErrors());
    if (!message.isEmpty())
        QCOMPARE(read.diagnostics.all().front().toString(), message);
}

QTEST_GUILESS_MAIN(TestCodesysMembers)
#include "tst_codesysmembers.moc"
