// bench_model: generates a ~10 MB PLCopen project with 1,000 POUs in all five languages, then
// times reading and writing it and prints the peak memory. Goal: load and save each < 0.5 s
// (Release build).

#include "model/plcopen/reader.h"
#include "model/plcopen/writer.h"
#include "model/statistics.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QTemporaryDir>
#include <QTextStream>

#include <sys/resource.h>

#include <algorithm>

using namespace iec::model;

namespace {

constexpr int kPous = 1000;
constexpr int kVariables = 12;
constexpr int kStatements = 12; // ST and IL lines
constexpr int kRungs = 4; // LD rungs, FBD networks, SFC steps

ConnectionPointIn wiredFrom(quint64 source, std::optional<QString> pin = {})
{
    ConnectionPointIn in;
    in.relPosition = Position {0, 10};
    in.connections.push_back(
        {.refLocalId = source, .formalParameter = std::move(pin), .waypoints = {{10, 20}, {30, 20}}});
    return in;
}

ConnectionPointOut pinOut()
{
    return {.relPosition = Position {40, 10}};
}

template<class E> E placed(quint64 localId, double x, double y)
{
    E element;
    element.localId = localId;
    element.position = {x, y};
    element.width = 40;
    element.height = 20;
    return element;
}

Interface declarations(int pou)
{
    Interface result;
    for (VarListKind kind : {VarListKind::Input, VarListKind::Output, VarListKind::Local}) {
        VarList &list = result.varLists.emplace_back(VarList {.kind = kind});
        for (int i = 0; i < kVariables / 3; ++i) {
            Variable variable {.name = QStringLiteral("Var%1_%2_%3").arg(pou).arg(int(kind)).arg(i),
                .type = DataType {ElementaryType {i % 2 ? QStringLiteral("INT") : QStringLiteral("BOOL")}}};
            variable.initialValue = Value {SimpleValue {QStringLiteral("0")}};
            variable.documentation = FormattedText {QStringLiteral("Variable %1 of POU %2").arg(i).arg(pou), {}};
            list.variables.push_back(std::move(variable));
        }
    }
    return result;
}

Body textBody(BodyLanguage language, int pou)
{
    Body body = Body::withLanguage(language);
    QString text;
    for (int i = 0; i < kStatements; ++i) {
        text += language == BodyLanguage::ST
            ? QStringLiteral("Var%1_2_%2 := Var%1_0_%2 + %3; (* statement %3 *)\n").arg(pou).arg(i % 4).arg(i)
            : QStringLiteral("LD Var%1_0_%2\nADD %3\nST Var%1_2_%2\n").arg(pou).arg(i % 4).arg(i);
    }
    body.setText(text);
    return body;
}

Body ladderBody()
{
    Body body = Body::withLanguage(BodyLanguage::LD);
    std::vector<Element> &elements = *body.elements();
    auto rail = placed<LeftPowerRail>(1, 10, 10);
    auto right = placed<RightPowerRail>(2, 600, 10);
    quint64 id = 3;
    for (int rung = 0; rung < kRungs; ++rung) {
        rail.connectionPointOuts.push_back(
            {.relPosition = Position {3, 20.0 + 40 * rung}, .formalParameter = QString()});
        quint64 previous = 1;
        for (int c = 0; c < 4; ++c) {
            auto contact = placed<Contact>(id, 60.0 + 80 * c, 20.0 + 40 * rung);
            contact.variable = QStringLiteral("Input%1").arg(c);
            contact.edge = c == 1 ? EdgeModifier::Rising : EdgeModifier::None;
            contact.connectionPointIn = wiredFrom(previous, previous == 1 ? std::optional(QString()) : std::nullopt);
            contact.connectionPointOut = pinOut();
            previous = id++;
            elements.push_back(std::move(contact));
        }
        auto coil = placed<Coil>(id, 500, 20.0 + 40 * rung);
        coil.variable = QStringLiteral("Output%1").arg(rung);
        coil.connectionPointIn = wiredFrom(previous);
        coil.connectionPointOut = pinOut();
        right.connectionPointIns.push_back(wiredFrom(id++));
        elements.push_back(std::move(coil));
    }
    elements.insert(elements.begin(), std::move(rail));
    elements.push_back(std::move(right));
    return body;
}

Body fbdBody()
{
    Body body = Body::withLanguage(BodyLanguage::FBD);
    std::vector<Element> &elements = *body.elements();
    quint64 id = 1;
    for (int network = 0; network < kRungs; ++network) {
        const double y = 10.0 + 100 * network;
        auto a = placed<InVariable>(id++, 10, y);
        a.expression = QStringLiteral("Input%1").arg(network);
        a.connectionPointOut = pinOut();
        auto b = placed<InVariable>(id++, 10, y + 40);
        b.expression = QStringLiteral("T#%1ms").arg(100 * network);
        b.connectionPointOut = pinOut();
        auto block = placed<Block>(id++, 100, y);
        block.typeName = QStringLiteral("TON");
        block.instanceName = QStringLiteral("Timer%1").arg(network);
        block.inputVariables.push_back(
            {.formalParameter = QStringLiteral("IN"), .connectionPointIn = wiredFrom(a.localId)});
        block.inputVariables.push_back(
            {.formalParameter = QStringLiteral("PT"), .connectionPointIn = wiredFrom(b.localId)});
        block.outputVariables.push_back({.formalParameter = QStringLiteral("Q"), .connectionPointOut = pinOut()});
        block.outputVariables.push_back({.formalParameter = QStringLiteral("ET"), .connectionPointOut = pinOut()});
        auto out = placed<OutVariable>(id++, 250, y);
        out.expression = QStringLiteral("Output%1").arg(network);
        out.connectionPointIn = wiredFrom(block.localId, QStringLiteral("Q"));
        elements.push_back(std::move(a));
        elements.push_back(std::move(b));
        elements.push_back(std::move(block));
        elements.push_back(std::move(out));
    }
    return body;
}

Body sfcBody()
{
    Body body = Body::withLanguage(BodyLanguage::SFC);
    std::vector<Element> &elements = *body.elements();
    quint64 id = 1;
    quint64 previous = 0;
    for (int s = 0; s < kRungs; ++s) {
        const double y = 10.0 + 120 * s;
        auto step = placed<Step>(id++, 100, y);
        step.name = QStringLiteral("Step%1").arg(s);
        step.initialStep = s == 0;
        if (previous != 0)
            step.connectionPointIn = wiredFrom(previous);
        step.connectionPointOut = ConnectionPointOut {.relPosition = Position {20, 30}, .formalParameter = QString()};
        step.connectionPointOutAction
            = ConnectionPointOut {.relPosition = Position {40, 15}, .formalParameter = QString()};
        auto actions = placed<ActionBlock>(id++, 200, y);
        actions.connectionPointIn = wiredFrom(step.localId);
        actions.actions.push_back({.qualifier = QStringLiteral("N"),
            .relPosition = {0, 0},
            .reference = Reference {QStringLiteral("Action%1").arg(s)}});
        auto transition = placed<Transition>(id++, 110, y + 60);
        transition.connectionPointIn = wiredFrom(step.localId);
        transition.connectionPointOut = pinOut();
        Condition condition;
        condition.kind = InlineCondition {QStringLiteral("Condition%1").arg(s), Body::withLanguage(BodyLanguage::ST)};
        std::get<InlineCondition>(condition.kind)
            .body->setText(QStringLiteral("Input%1 AND NOT Input%2").arg(s).arg(s + 1));
        transition.condition = std::move(condition);
        previous = transition.localId;
        elements.push_back(std::move(step));
        elements.push_back(std::move(actions));
        elements.push_back(std::move(transition));
    }
    auto jump = placed<JumpStep>(id, 110, 10.0 + 120 * kRungs);
    jump.targetName = QStringLiteral("Step0");
    jump.connectionPointIn = wiredFrom(previous);
    elements.push_back(std::move(jump));
    return body;
}

Project generatedProject()
{
    Project project;
    project.fileHeader = {.companyName = QStringLiteral("IEC Studio"),
        .productName = QStringLiteral("bench_model"),
        .productVersion = QStringLiteral("1"),
        .creationDateTime = QStringLiteral("2026-01-01T00:00:00")};
    project.contentHeader.name = QStringLiteral("Benchmark");
    const BodyLanguage languages[]
        = {BodyLanguage::ST, BodyLanguage::IL, BodyLanguage::LD, BodyLanguage::FBD, BodyLanguage::SFC};
    for (int i = 0; i < kPous; ++i) {
        Pou pou {
            .name = QStringLiteral("Pou%1").arg(i), .kind = i % 3 == 0 ? PouKind::Program : PouKind::FunctionBlock};
        pou.pouInterface = declarations(i);
        switch (languages[i % 5]) {
        case BodyLanguage::ST:
        case BodyLanguage::IL:
            pou.bodies.push_back(textBody(languages[i % 5], i));
            break;
        case BodyLanguage::LD:
            pou.bodies.push_back(ladderBody());
            break;
        case BodyLanguage::FBD:
            pou.bodies.push_back(fbdBody());
            break;
        case BodyLanguage::SFC:
            pou.bodies.push_back(sfcBody());
            for (int a = 0; a < kRungs; ++a)
                pou.actions.push_back(
                    {.name = QStringLiteral("Action%1").arg(a), .body = textBody(BodyLanguage::ST, i)});
            break;
        }
        project.types.pous.push_back(std::move(pou));
    }
    return project;
}

double peakMegabytes()
{
    rusage usage {};
    getrusage(RUSAGE_SELF, &usage);
    return double(usage.ru_maxrss) / 1024.0; // ru_maxrss is in KiB on Linux
}

template<class F> double bestOf(int runs, F &&f)
{
    double best = 1e9;
    for (int i = 0; i < runs; ++i) {
        QElapsedTimer timer;
        timer.start();
        f();
        best = std::min(best, double(timer.nsecsElapsed()) / 1e6);
    }
    return best;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication application(argc, argv);
    QTextStream out(stdout);
    const Project project = generatedProject();
    const QByteArray bytes = plcopen::writeProject(project);
    const double afterGenerate = peakMegabytes();

    plcopen::ReadResult read;
    const double readMs = bestOf(5, [&] { read = plcopen::readProject(bytes); });
    const double afterRead = peakMegabytes();
    QByteArray written;
    const double writeMs = bestOf(5, [&] { written = plcopen::writeProject(read.project); });
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("bench.xml"));
    const double saveMs = bestOf(5, [&] { plcopen::saveProjectFile(read.project, path); });
    const double loadMs = bestOf(5, [&] { read = plcopen::readProjectFile(path); });

    const ProjectStatistics stats = statistics(read.project);
    out << "project: " << stats.pous << " POUs (ST " << stats.pousByLanguage.at(QStringLiteral("ST")) << ", IL "
        << stats.pousByLanguage.at(QStringLiteral("IL")) << ", LD " << stats.pousByLanguage.at(QStringLiteral("LD"))
        << ", FBD " << stats.pousByLanguage.at(QStringLiteral("FBD")) << ", SFC "
        << stats.pousByLanguage.at(QStringLiteral("SFC")) << "), " << stats.elements << " graphical elements, "
        << stats.variables << " variables\n";
    out << "file size: " << QString::number(double(bytes.size()) / 1e6, 'f', 2) << " MB\n";
    out << "read (bytes -> model):   " << QString::number(readMs, 'f', 1) << " ms\n";
    out << "write (model -> bytes):  " << QString::number(writeMs, 'f', 1) << " ms\n";
    out << "load (file -> model):    " << QString::number(loadMs, 'f', 1) << " ms\n";
    out << "save (model -> file):    " << QString::number(saveMs, 'f', 1) << " ms\n";
    out << "round trip identical:    " << (written == bytes && read.ok ? "yes" : "NO") << "\n";
    out << "peak memory: " << QString::number(afterGenerate, 'f', 0) << " MB after generating, "
        << QString::number(afterRead, 'f', 0) << " MB after reading, " << QString::number(peakMegabytes(), 'f', 0)
        << " MB at the end\n";
    return written == bytes && read.ok ? 0 : 1;
}
