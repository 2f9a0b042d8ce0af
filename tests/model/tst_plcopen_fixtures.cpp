// The hand-written fixtures in tests/model/fixtures: every element and attribute of TC6 XML 2.01
// round-trips to the same bytes; unknown content is kept in place; other namespaces read the same.

#include "model/plcopen/reader.h"
#include "model/plcopen/writer.h"
#include "model/statistics.h"
#include "roundtrip.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace iec::model;
using namespace iec::test;

namespace {

QByteArray fixture(const char *name)
{
    QFile file(QStringLiteral(IEC_SOURCE_DIR "/tests/model/fixtures/") + QLatin1String(name));
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

const Pou &pouNamed(const Project &project, const char *name)
{
    static const Pou none;
    const Pou *pou = project.findPou(QLatin1String(name));
    return pou ? *pou : none;
}

const std::vector<Element> &elementsOf(const Project &project, const char *pou)
{
    static const std::vector<Element> none;
    const Pou &p = pouNamed(project, pou);
    return p.bodies.empty() || !p.bodies.front().elements() ? none : *p.bodies.front().elements();
}

} // namespace

class TestPlcopenFixtures : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void everyElementRoundTripsToTheSameBytes();
    void everyElementIsRead_data();
    void everyElementIsRead();
    void dataTypeKinds_data();
    void dataTypeKinds();
    void varListKindsAndFlags();
    void sfcDetails();
    void instances();
    void unknownContentIsKeptInPlace();
    void otherNamespacesReadTheSame_data();
    void otherNamespacesReadTheSame();
    void programTextWithCdataEnd();
    void saveReplacesTheFileOrLeavesItAlone();
    void saveStampsAMissingCreationTime();
    void unplacedDiagramGetsALayoutOnce();
    void vendorPousNestedInVendorPous();
    void deletedVendorPouLeavesNoTrace();
    void generatedLayoutsDoNotStackElements_data();
    void generatedLayoutsDoNotStackElements();
};

void TestPlcopenFixtures::everyElementRoundTripsToTheSameBytes()
{
    const QByteArray original = fixture("every_element.xml");
    QVERIFY(!original.isEmpty());
    QCOMPARE(schemaErrors(original), QString());
    const plcopen::ReadResult result = plcopen::readProject(original);
    QVERIFY2(result.diagnostics.empty(), qPrintable(diagnosticsText(result.diagnostics)));
    QVERIFY(result.ok);
    QCOMPARE(plcopen::writeProject(result.project), original);
}

void TestPlcopenFixtures::everyElementIsRead_data()
{
    QTest::addColumn<QString>("kind");
    QTest::addColumn<int>("count");
    // Top-level elements of the LD, FBD and SFC bodies (statistics do not count inline bodies).
    const std::pair<const char *, int> expected[] = {
        {"actionBlock", 1},
        {"block", 1},
        {"coil", 4},
        {"comment", 2},
        {"connector", 1},
        {"contact", 4},
        {"continuation", 1},
        {"error", 1},
        {"inOutVariable", 1},
        {"inVariable", 2},
        {"jump", 1},
        {"jumpStep", 1},
        {"label", 1},
        {"leftPowerRail", 1},
        {"macroStep", 1},
        {"outVariable", 1},
        {"return", 1},
        {"rightPowerRail", 1},
        {"selectionConvergence", 1},
        {"selectionDivergence", 1},
        {"simultaneousConvergence", 1},
        {"simultaneousDivergence", 1},
        {"step", 4},
        {"transition", 5},
        {"vendorElement", 1},
    };
    for (const auto &[kind, count] : expected)
        QTest::newRow(kind) << QString::fromLatin1(kind) << count;
}

void TestPlcopenFixtures::everyElementIsRead()
{
    QFETCH(QString, kind);
    QFETCH(int, count);
    const ProjectStatistics stats = statistics(plcopen::readProject(fixture("every_element.xml")).project);
    QCOMPARE(stats.elementsByKind.size(), std::size_t {25}); // every kind of the XSD occurs
    QCOMPARE(stats.elementsByKind.at(kind), count);
}

void TestPlcopenFixtures::dataTypeKinds_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<int>("kind"); // index into DataType::kind
    QTest::newRow("elementary") << "Speed" << 0;
    QTest::newRow("string") << "Name" << 1;
    QTest::newRow("wstring") << "WideName" << 1;
    QTest::newRow("array") << "Matrix" << 2;
    QTest::newRow("enum") << "Colour" << 4;
    QTest::newRow("enum with base") << "Mode" << 4;
    QTest::newRow("struct") << "Point" << 5;
    QTest::newRow("subrange signed") << "Percent" << 6;
    QTest::newRow("subrange unsigned") << "Index" << 6;
    QTest::newRow("pointer") << "PointRef" << 7;
}

void TestPlcopenFixtures::dataTypeKinds()
{
    QFETCH(QString, name);
    QFETCH(int, kind);
    const Project project = plcopen::readProject(fixture("every_element.xml")).project;
    const DataTypeDecl *type = project.findDataType(name);
    QVERIFY(type);
    QCOMPARE(int(type->baseType.kind.index()), kind);
}

void TestPlcopenFixtures::varListKindsAndFlags()
{
    const Project project = plcopen::readProject(fixture("every_element.xml")).project;
    const Pou &motor = pouNamed(project, "Motor");
    QVERIFY(motor.pouInterface);
    const std::vector<VarList> &lists = motor.pouInterface->varLists;
    QCOMPARE(lists.size(), std::size_t {8});
    const VarListKind kinds[] = {VarListKind::Input, VarListKind::Output, VarListKind::InOut, VarListKind::External,
        VarListKind::Local, VarListKind::Temp, VarListKind::Global, VarListKind::Access};
    for (std::size_t i = 0; i < lists.size(); ++i)
        QCOMPARE(lists[i].kind, kinds[i]);
    QVERIFY(lists[0].constant);
    QVERIFY(lists[1].retain);
    QCOMPARE(lists[1].variables.front().address, std::optional<QString>(QStringLiteral("%QX0.0")));
    QVERIFY(lists[2].nonretain);
    QVERIFY(lists[3].persistent);
    QVERIFY(lists[4].nonpersistent);
    QCOMPARE(lists[4].name, std::optional<QString>(QStringLiteral("Locals")));
    QCOMPARE(lists[4].documentation->text, QStringLiteral("Local variables"));
    const auto &initial = std::get<StructValue>(lists[4].variables.at(1).initialValue->kind);
    QCOMPARE(initial.values.front().member, QStringLiteral("X"));
    QCOMPARE(motor.actions.size(), std::size_t {1});
    QCOMPARE(motor.transitions.front().body.language(), BodyLanguage::IL);
    QCOMPARE(motor.bodies.front().worksheetName, std::optional<QString>(QStringLiteral("Main")));
    const Pou &scale = pouNamed(project, "Scale");
    QCOMPARE(scale.kind, PouKind::Function);
    QVERIFY(std::holds_alternative<ElementaryType>(scale.pouInterface->returnType->kind));
}

void TestPlcopenFixtures::sfcDetails()
{
    const Project project = plcopen::readProject(fixture("every_element.xml")).project;
    const std::vector<Element> &sfc = elementsOf(project, "Chart");
    const auto &init = std::get<Step>(sfc.at(0));
    QVERIFY(init.initialStep);
    QVERIFY(init.connectionPointOutAction);
    const auto &actions = std::get<ActionBlock>(sfc.at(1));
    QVERIFY(actions.negated);
    QCOMPARE(actions.actions.size(), std::size_t {3});
    QCOMPARE(actions.actions[0].qualifier, std::optional<QString>(QStringLiteral("L")));
    QCOMPARE(actions.actions[0].duration, std::optional<QString>(QStringLiteral("T#2s")));
    QCOMPARE(actions.actions[0].indicator, std::optional<QString>(QStringLiteral("Lamp")));
    QCOMPARE(actions.actions[0].reference->name, QStringLiteral("Reset"));
    QCOMPARE((*actions.actions[1].inlineBody)->text(), QStringLiteral("A := TRUE;"));
    const auto &t3 = std::get<Transition>(sfc.at(2));
    QCOMPARE(t3.priority, std::optional<quint64>(1));
    QVERIFY(t3.condition->negated);
    QVERIFY(std::holds_alternative<Reference>(t3.condition->kind));
    QVERIFY(std::holds_alternative<InlineCondition>(std::get<Transition>(sfc.at(4)).condition->kind));
    QCOMPARE(
        std::get<ConnectionPointIn>(std::get<Transition>(sfc.at(6)).condition->kind).connections.front().refLocalId,
        quint64(20));
    QCOMPARE(std::get<SimultaneousDivergence>(sfc.at(11)).name, std::optional<QString>(QStringLiteral("Fork")));
    QCOMPARE(std::get<JumpStep>(sfc.back()).targetName, QStringLiteral("Init"));
    const std::vector<Element> &fbd = elementsOf(project, "Blocks");
    QCOMPARE(header(fbd.back()).localId, quint64(18446744073709551615ULL));
    const auto &block = std::get<Block>(fbd.at(1));
    QCOMPARE(block.inputVariables.front().edge, EdgeModifier::Falling);
    QCOMPARE(block.inputVariables.front().storage, StorageModifier::Reset);
    QVERIFY(block.inputVariables.front().hidden);
    const std::vector<Element> &ld = elementsOf(project, "Ladder");
    QCOMPARE(std::get<Contact>(ld.at(3)).edge, EdgeModifier::Rising);
    QCOMPARE(std::get<Coil>(ld.at(5)).storage, StorageModifier::Set);
    const auto &wire = std::get<Contact>(ld.at(1)).connectionPointIn->connections.front();
    QCOMPARE(wire.waypoints.size(), std::size_t {2});
    QCOMPARE(wire.formalParameter, std::optional<QString>(QString()));
    QCOMPARE(wire.globalId, std::optional<QString>(QStringLiteral("ID_W1")));
    QCOMPARE(wire.addData.front().content, QStringLiteral("<colour value=\"red\"/>"));
}

void TestPlcopenFixtures::instances()
{
    const Project project = plcopen::readProject(fixture("every_element.xml")).project;
    QCOMPARE(project.instances.configurations.size(), std::size_t {1});
    const Configuration &configuration = project.instances.configurations.front();
    const Resource &resource = configuration.resources.front();
    QCOMPARE(resource.tasks.size(), std::size_t {2});
    QCOMPARE(resource.tasks[0].interval, std::optional<QString>(QStringLiteral("T#10ms")));
    QCOMPARE(resource.tasks[1].single, std::optional<QString>(QStringLiteral("Trigger")));
    QCOMPARE(resource.tasks[1].priority, quint32(65535));
    QCOMPARE(resource.tasks[0].pouInstances.front().typeName, QStringLiteral("Ladder"));
    QCOMPARE(resource.globalVars.front().kind, VarListKind::Global);
    QCOMPARE(configuration.accessVars->variables.size(), std::size_t {2});
    QCOMPARE(configuration.accessVars->variables[0].direction, std::optional(AccessDirection::ReadOnly));
    QCOMPARE(configuration.configVars->variables.front().address, std::optional<QString>(QStringLiteral("%IX1.0")));
    QCOMPARE(project.contentHeader.coordinateInfo.ld.x, 5.5);
    QCOMPARE(project.contentHeader.coordinateInfo.pageSize->y, 1485.0);
    QCOMPARE(project.contentHeader.addDataInfo->front().version, std::optional<QString>(QStringLiteral("1.5")));
    // Rich XHTML keeps its markup; the model also has the plain text.
    QCOMPARE(project.documentation->text, QStringLiteral("The project documentation, rich.A second paragraph."));
    QVERIFY(project.documentation->xhtml.startsWith(QStringLiteral("<xhtml:div><xhtml:p>")));
}

void TestPlcopenFixtures::unknownContentIsKeptInPlace()
{
    const QByteArray original = fixture("unknown_content.xml");
    const plcopen::ReadResult result = plcopen::readProject(original);
    QVERIFY(!result.ok); // width="wide" is an error; unknown content alone would be a warning
    QCOMPARE(diagnosticsText(result.diagnostics),
        QStringLiteral("2:1: Unknown attribute 'vendorFlag' on <project> is kept as it is.\n"
                       "3:3: Unknown attribute 'extra' on <fileHeader> is kept as it is.\n"
                       "20:7: Unknown attribute 'color' on <pou> is kept as it is.\n"
                       "21:9: Unknown element <vendorFirst> in <pou> is kept as it is.\n"
                       "24:13: Unknown attribute 'note' on <variable> is kept as it is.\n"
                       "28:15: Unknown element <vendorAfterType> in <variable> is kept as it is.\n"
                       "36:13: The attribute width=\"wide\" of <inVariable> has an invalid value; it is kept as "
                       "written.\n"
                       "40:15: Unknown element <vendorTail> in <inVariable> is kept as it is.\n"
                       "42:13: Unknown element <strangeElement> in <FBD> is kept as it is.\n"
                       "45:9: Unknown element <vendorAfterBody> in <pou> is kept as it is.\n"
                       "46:9: Unknown element <vendorAfterBody2> in <pou> is kept as it is.\n"));
    QCOMPARE(result.diagnostics.at(2).pouName, std::optional<QString>(QStringLiteral("Main")));
    QCOMPARE(result.diagnostics.at(0).pouName, std::optional<QString>());
    QCOMPARE(result.diagnostics.at(6).severity, Diagnostic::Severity::Error);
    QCOMPARE(result.diagnostics.at(6).localId, std::optional<quint64>(1));
    QCOMPARE(result.diagnostics.at(7).severity, Diagnostic::Severity::Warning);
    QCOMPARE(plcopen::writeProject(result.project), original);
}

void TestPlcopenFixtures::otherNamespacesReadTheSame_data()
{
    QTest::addColumn<QByteArray>("namespaceDeclaration");
    QTest::newRow("tc6_0200") << QByteArray("xmlns=\"http://www.plcopen.org/xml/tc6_0200\"");
    QTest::newRow("none") << QByteArray();
    QTest::newRow("prefixed") << QByteArray("xmlns:ppx=\"http://www.plcopen.org/xml/tc6_0201\"");
}

void TestPlcopenFixtures::otherNamespacesReadTheSame()
{
    QFETCH(QByteArray, namespaceDeclaration);
    const QByteArray original = fixture("every_element.xml");
    QByteArray variant = original;
    variant.replace("xmlns=\"http://www.plcopen.org/xml/tc6_0201\"", namespaceDeclaration);
    if (namespaceDeclaration.contains("ppx")) { // every PLCopen element with a prefix
        variant.replace("<project ", "<ppx:project ").replace("</project>", "</ppx:project>");
        variant.replace("<types>", "<ppx:types>").replace("</types>", "</ppx:types>");
    }
    const plcopen::ReadResult result = plcopen::readProject(variant);
    QVERIFY2(result.diagnostics.empty(), qPrintable(diagnosticsText(result.diagnostics)));
    QVERIFY(result.project == plcopen::readProject(original).project);
    QCOMPARE(plcopen::writeProject(result.project), original);
}

void TestPlcopenFixtures::programTextWithCdataEnd()
{
    const Project project = plcopen::readProject(fixture("every_element.xml")).project;
    QCOMPARE(pouNamed(project, "Scale").bodies.front().text(),
        QStringLiteral("Scale := Value * Factor; (* a CDATA end ]]> inside *)"));
}

void TestPlcopenFixtures::saveReplacesTheFileOrLeavesItAlone()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("project.xml"));
    const Project project = plcopen::readProject(fixture("every_element.xml")).project;
    QString error;
    QVERIFY(plcopen::saveProjectFile(project, path, &error));
    QFile saved(path);
    QVERIFY(saved.open(QIODevice::ReadOnly));
    QCOMPARE(saved.readAll(), fixture("every_element.xml"));

    const QString missingDirectory = dir.filePath(QStringLiteral("missing/project.xml"));
    QVERIFY(!plcopen::saveProjectFile(project, missingDirectory, &error));
    QCOMPARE(error, QStringLiteral("%1 was not saved: the folder %2 does not exist. The file on the disk is unchanged.")
                        .arg(QDir::toNativeSeparators(missingDirectory), QDir::toNativeSeparators(dir.filePath(QStringLiteral("missing")))));
    QVERIFY(!QFile::exists(missingDirectory));
}

void TestPlcopenFixtures::saveStampsAMissingCreationTime()
{
    // A new project has no creation time; the XSD requires an xsd:dateTime, so the save adds one.
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("new.xml"));
    const QDateTime before = QDateTime::currentDateTimeUtc().addSecs(-1);
    QString error;
    QVERIFY2(plcopen::saveProjectFile(Project {}, path, &error), qPrintable(error));
    const QDateTime after = QDateTime::currentDateTimeUtc().addSecs(1);
    QFile saved(path);
    QVERIFY(saved.open(QIODevice::ReadOnly));
    const QByteArray bytes = saved.readAll();
    QCOMPARE(schemaErrors(bytes), QString());
    const QDateTime stamped = QDateTime::fromString(plcopen::readProject(bytes).project.fileHeader.creationDateTime, Qt::ISODate);
    QVERIFY(stamped.isValid());
    QVERIFY(stamped >= before && stamped <= after);

    FileHeader kept;
    kept.creationDateTime = QStringLiteral("2001-02-03T04:05:06");
    plcopen::stampCreationTime(kept, QDateTime::currentDateTimeUtc());
    QCOMPARE(kept.creationDateTime, QStringLiteral("2001-02-03T04:05:06"));
}

void TestPlcopenFixtures::unplacedDiagramGetsALayoutOnce()
{
    const plcopen::ReadResult result
        = plcopen::readProjectFile(corpusPath(QStringLiteral("codesys35sp18_sfc_test.xml")));
    const Body &body = result.project.types.pous.front().bodies.front();
    QVERIFY(body.layoutGenerated);
    // Steps and transitions (the chart's spine) never share a position.
    std::vector<std::pair<double, double>> spine;
    for (const Element &element : *body.elements()) {
        if (std::holds_alternative<Step>(element) || std::holds_alternative<Transition>(element))
            spine.emplace_back(header(element).position.x, header(element).position.y);
    }
    std::ranges::sort(spine);
    QVERIFY(spine.size() > 10);
    QVERIFY(std::ranges::adjacent_find(spine) == spine.end());
    // The initial step is at the top.
    const auto initial = std::ranges::find_if(*body.elements(),
        [](const Element &e) { return std::holds_alternative<Step>(e) && std::get<Step>(e).initialStep; });
    QCOMPARE(header(*initial).position.y, 20.0);
    // Written and read again: the flag is kept and nothing moves.
    const plcopen::ReadResult again = plcopen::readProject(plcopen::writeProject(result.project));
    QVERIFY(again.project.types.pous.front().bodies.front() == body);
}

namespace {

// A CODESYS-style project: POU "Outer" lives in project addData and carries POU "Inner" in its own.
QByteArray nestedVendorPous()
{
    QByteArray xml = fixture("unknown_content.xml");
    xml.replace(" vendorFlag=\"1\"", "").replace(" extra=\"kept\"", "");
    const qsizetype types = xml.indexOf("  <types>");
    xml.truncate(types);
    xml += "  <types>\n    <dataTypes />\n    <pous />\n  </types>\n  <instances>\n    <configurations />\n  "
           "</instances>\n"
           "  <addData>\n"
           "    <data name=\"http://www.3s-software.com/plcopenxml/pou\" handleUnknown=\"implementation\">\n"
           "      <pou name=\"Outer\" pouType=\"program\">\n"
           "        <addData>\n"
           "          <data name=\"http://www.3s-software.com/plcopenxml/pou\" handleUnknown=\"implementation\">\n"
           "            <pou name=\"Inner\" pouType=\"function\" />\n"
           "          </data>\n"
           "        </addData>\n"
           "      </pou>\n"
           "    </data>\n"
           "    <data name=\"http://www.3s-software.com/plcopenxml/datatype\" handleUnknown=\"implementation\">\n"
           "      <dataType name=\"Mode\">\n"
           "        <baseType>\n"
           "          <INT />\n"
           "        </baseType>\n"
           "      </dataType>\n"
           "    </data>\n"
           "  </addData>\n"
           "</project>\n";
    return xml;
}

} // namespace

void TestPlcopenFixtures::vendorPousNestedInVendorPous()
{
    const QByteArray original = nestedVendorPous();
    const plcopen::ReadResult result = plcopen::readProject(original);
    QVERIFY2(result.ok && result.diagnostics.empty(), qPrintable(diagnosticsText(result.diagnostics)));
    QCOMPARE(result.project.types.pous.size(), std::size_t {2});
    QCOMPARE(result.project.types.pous[0].name, QStringLiteral("Inner"));
    QCOMPARE(result.project.types.pous[0].addDataSlot, quint32(2));
    QCOMPARE(result.project.types.pous[1].name, QStringLiteral("Outer"));
    QCOMPARE(result.project.types.pous[1].addDataSlot, quint32(1));
    QCOMPARE(result.project.types.dataTypes.front().addDataSlot, quint32(3));
    QCOMPARE(plcopen::writeProject(result.project), original); // back in place, nothing duplicated
}

void TestPlcopenFixtures::deletedVendorPouLeavesNoTrace()
{
    Project project = plcopen::readProject(nestedVendorPous()).project;
    std::erase_if(project.types.pous, [](const Pou &pou) { return pou.name == QLatin1String("Inner"); });
    const QByteArray written = plcopen::writeProject(project);
    QVERIFY(!written.contains("Inner"));
    QCOMPARE(written.count("<data name=\"http://www.3s-software.com/plcopenxml/pou\""), 1);
    QCOMPARE(schemaErrors(written), QString());
    // A vendor POU whose entry is gone is written with the ordinary POUs.
    project.addData.clear();
    const plcopen::ReadResult again = plcopen::readProject(plcopen::writeProject(project));
    QCOMPARE(again.project.types.pous.size(), std::size_t {1});
    QCOMPARE(again.project.types.pous.front().name, QStringLiteral("Outer"));
    QCOMPARE(again.project.types.pous.front().addDataSlot, quint32(0));
    QCOMPARE(again.project.types.dataTypes.front().name, QStringLiteral("Mode"));
}

void TestPlcopenFixtures::generatedLayoutsDoNotStackElements_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<int>("bodies");
    QTest::newRow("codesys sfc") << "codesys35sp18_sfc_test.xml" << 1;
    QTest::newRow("codesys fbd") << "codesys35sp14_FBDExample.xml" << 2;
    QTest::newRow("twincat ppu") << "twincat356_ppu.xml" << 35;
}

void TestPlcopenFixtures::generatedLayoutsDoNotStackElements()
{
    QFETCH(QString, file);
    QFETCH(int, bodies);
    const Project project = plcopen::readProjectFile(corpusPath(file)).project;
    int generated = 0;
    auto check = [&](const Body &body) {
        if (!body.layoutGenerated)
            return;
        ++generated;
        // Two elements in the same place would hide each other; only unwired leftovers may share a row.
        std::vector<std::pair<double, double>> positions;
        for (const Element &element : *body.elements())
            positions.emplace_back(header(element).position.x, header(element).position.y);
        std::ranges::sort(positions);
        QVERIFY2(std::ranges::adjacent_find(positions) == positions.end(), qPrintable(file));
    };
    for (const Pou &pou : project.types.pous) {
        for (const Body &body : pou.bodies)
            check(body);
        for (const PouAction &action : pou.actions)
            check(action.body);
    }
    QCOMPARE(generated, bodies);
}

QTEST_GUILESS_MAIN(TestPlcopenFixtures)
#include "tst_plcopen_fixtures.moc"
