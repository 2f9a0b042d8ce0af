#include "app/projecttemplates.h"

#include "editors/fbd/fbdedits.h"
#include "editors/fbd/fbdwrite.h"
#include "editors/globals/globallists.h"
#include "interpreter/frontend/iecreader.h"

namespace iec::app {

using model::BodyLanguage;

namespace {

model::Variable boolVariable(const QString &name, const QString &comment)
{
    model::Variable variable;
    variable.name = name;
    variable.type = {model::ElementaryType {QStringLiteral("BOOL")}};
    variable.documentation = model::FormattedText {comment, {}};
    return variable;
}

model::ConnectionPointIn wiredFrom(quint64 source, model::Position pin)
{
    model::ConnectionPointIn in;
    in.relPosition = pin;
    in.connections.push_back({.refLocalId = source});
    return in;
}

model::ConnectionPointOut outAt(model::Position pin)
{
    model::ConnectionPointOut out;
    out.relPosition = pin;
    return out;
}

// A contact or coil on the rung at `x`, wired from element `source`.
template <typename ContactOrCoil>
ContactOrCoil rungElement(quint64 localId, double x, const QString &variable, quint64 source)
{
    ContactOrCoil element;
    element.localId = localId;
    element.position = {x, 28};
    element.width = 21;
    element.height = 15;
    element.variable = variable;
    element.connectionPointIn = wiredFrom(source, {0, 7});
    element.connectionPointOut = outAt({21, 7});
    return element;
}

// One rung: left rail - Start - (Lamp) - right rail, at the sizes CODESYS writes.
model::Body ladderRung()
{
    model::Body body = model::Body::withLanguage(BodyLanguage::LD);
    model::LeftPowerRail left;
    left.localId = 1;
    left.position = {20, 20};
    left.width = 3;
    left.height = 30;
    left.connectionPointOuts.push_back(outAt({3, 15}));
    left.connectionPointOuts.back().formalParameter = QString();
    const auto contact = rungElement<model::Contact>(2, 80, QStringLiteral("Start"), 1);
    const auto lamp = rungElement<model::Coil>(3, 200, QStringLiteral("Lamp"), 2);
    model::RightPowerRail right;
    right.localId = 4;
    right.position = {300, 20};
    right.width = 3;
    right.height = 30;
    right.connectionPointIns.push_back(wiredFrom(3, {0, 15}));
    *body.elements() = {left, contact, lamp, right};
    return body;
}

// An initial step that stays active, from the textual SFC form (the reader lays it out).
model::Body initialChart()
{
    const interp::frontend::TextReadResult read = interp::frontend::readIecText(
        QStringLiteral("PROGRAM Main\nINITIAL_STEP Init:\nEND_STEP\n"
                       "TRANSITION FROM Init TO Init\n    := FALSE;\nEND_TRANSITION\nEND_PROGRAM\n"),
        QString());
    const model::Pou *main = read.project.findPou(QStringLiteral("Main"));
    return main && main->body() ? *main->body() : model::Body::withLanguage(BodyLanguage::SFC);
}

// One network: Start assigned to Lamp, laid out as the FBD editor lays it out.
model::Body fbdNetwork()
{
    using namespace editors::fbd;
    FbdDocument document;
    const FbdEditResult network = insertNetwork(document, FbdCursor::atNetwork(0), true);
    setElementText(document, network.cursor.element, QStringLiteral("Start"));
    for (const model::Element &e : std::vector<model::Element>(document.elements))
        if (std::holds_alternative<model::OutVariable>(e))
            setElementText(document, model::header(e).localId, QStringLiteral("Lamp"));
    writeFbd(document);
    model::Body body = model::Body::withLanguage(BodyLanguage::FBD);
    *body.elements() = std::move(document.elements);
    return body;
}

model::Pou mainProgram(ProjectTemplate projectTemplate)
{
    model::Pou pou;
    pou.name = QStringLiteral("Main");
    pou.kind = model::PouKind::Program;
    pou.pouInterface = model::Interface {};
    switch (projectTemplate) {
    case ProjectTemplate::LD:
    case ProjectTemplate::FBD: {
        model::VarList locals;
        const QString start = projectTemplate == ProjectTemplate::LD ? ProjectTemplates::tr("Closes the contact")
                                                                     : ProjectTemplates::tr("Switches Lamp on and off");
        locals.variables = {boolVariable(QStringLiteral("Start"), start),
            boolVariable(QStringLiteral("Lamp"), ProjectTemplates::tr("Lit while Start is TRUE"))};
        pou.pouInterface->varLists.push_back(locals);
        pou.bodies.push_back(projectTemplate == ProjectTemplate::LD ? ladderRung() : fbdNetwork());
        break;
    }
    case ProjectTemplate::SFC:
        pou.bodies.push_back(initialChart());
        break;
    case ProjectTemplate::CFC: {
        model::Body body = model::Body::withLanguage(BodyLanguage::FBD);
        body.addData.push_back({QString::fromLatin1(kCfcBodyAddDataName), QStringLiteral("implementation"), QStringLiteral("<cfc/>")});
        pou.bodies.push_back(body);
        break;
    }
    case ProjectTemplate::IL:
        pou.bodies.push_back(model::Body::withLanguage(BodyLanguage::IL));
        break;
    default:
        pou.bodies.push_back(model::Body::withLanguage(BodyLanguage::ST));
        break;
    }
    return pou;
}

} // namespace

QList<ProjectTemplate> ProjectTemplates::all()
{
    return {ProjectTemplate::Empty, ProjectTemplate::ST, ProjectTemplate::LD, ProjectTemplate::FBD, ProjectTemplate::CFC,
        ProjectTemplate::SFC, ProjectTemplate::IL};
}

QString ProjectTemplates::name(ProjectTemplate projectTemplate)
{
    switch (projectTemplate) {
    case ProjectTemplate::Empty:
        return tr("Empty project");
    case ProjectTemplate::ST:
        return tr("Structured Text (ST) program");
    case ProjectTemplate::LD:
        return tr("Ladder Diagram (LD) program");
    case ProjectTemplate::FBD:
        return tr("Function Block Diagram (FBD) program");
    case ProjectTemplate::CFC:
        return tr("Continuous Function Chart (CFC) program");
    case ProjectTemplate::SFC:
        return tr("Sequential Function Chart (SFC) program");
    case ProjectTemplate::IL:
        return tr("Instruction List (IL) program");
    }
    return {};
}

QString ProjectTemplates::description(ProjectTemplate projectTemplate)
{
    if (projectTemplate == ProjectTemplate::Empty)
        return tr("No POUs and no configuration: add what you need from the Project menu.");
    return tr("A program Main, run every 10 ms by the task MainTask of configuration Config.");
}

model::Project ProjectTemplates::create(ProjectTemplate projectTemplate)
{
    model::Project project;
    if (projectTemplate == ProjectTemplate::Empty)
        return project;
    project.types.pous.push_back(mainProgram(projectTemplate));
    project.instances = editors::withExplicitConfiguration({}, QStringLiteral("Main"));
    return project;
}

QString mainProgramName(const model::Project &project)
{
    for (const model::Configuration &configuration : project.instances.configurations) {
        for (const model::Resource &resource : configuration.resources) {
            for (const model::Task &task : resource.tasks) {
                for (const model::PouInstance &instance : task.pouInstances) {
                    if (project.findPou(instance.typeName))
                        return instance.typeName;
                }
            }
        }
    }
    return editors::implicitProgram(project);
}

} // namespace iec::app
