#pragma once

// Builds LD/FBD bodies element by element and runs them scan by scan, for the graphical lowering
// tests:
//   Diagram d;
//   d.rail(1).contact(2, "a", {1}).coil(3, "x", {2});
//   runDiagram("VAR a, x : BOOL; END_VAR", model::BodyLanguage::LD, d, {"a=TRUE => x=TRUE"});
// Steps are "name=value; ... => name=value; ..." as in ../tracerunner.h; names are Main's.

#include "interpreter/frontend/iecreader.h"
#include "interpreter/frontend/projectsource.h"
#include "interpreter/runtime/runtime.h"

#include "model/element.h"

#include "../tracerunner.h"

#include <QStringList>

#include <initializer_list>
#include <utility>

namespace iec::testing {

struct From {
    quint64 id;
    QString pin; // the source's output (blocks), empty otherwise
};

struct Pin {
    QString name;
    std::vector<From> from; // empty: not connected
    bool negated = false;
    model::EdgeModifier edge = model::EdgeModifier::None;
};

class Diagram
{
public:
    std::vector<model::Element> elements;

    static model::ConnectionPointIn wire(const std::vector<From> &from)
    {
        model::ConnectionPointIn point;
        for (const From &f : from) {
            model::Connection c;
            c.refLocalId = f.id;
            if (!f.pin.isEmpty())
                c.formalParameter = f.pin;
            point.connections.push_back(c);
        }
        return point;
    }

    template<class T> T &add(quint64 id, double x, double y)
    {
        T element;
        element.localId = id;
        element.position = {x, y};
        elements.emplace_back(std::move(element));
        return std::get<T>(elements.back());
    }

    Diagram &rail(quint64 id, double y = 0)
    {
        auto &r = add<model::LeftPowerRail>(id, 0, y);
        r.connectionPointOuts.emplace_back();
        return *this;
    }
    Diagram &contact(quint64 id, const QString &variable, const std::vector<From> &from, double x = 0, double y = 0,
        bool negated = false, model::EdgeModifier edge = model::EdgeModifier::None)
    {
        auto &c = add<model::Contact>(id, x ? x : 100 + 10 * double(id), y);
        c.variable = variable;
        c.negated = negated;
        c.edge = edge;
        if (!from.empty())
            c.connectionPointIn = wire(from);
        c.connectionPointOut.emplace();
        return *this;
    }
    Diagram &coil(quint64 id, const QString &variable, const std::vector<From> &from, double x = 500, double y = 0,
        bool negated = false, model::EdgeModifier edge = model::EdgeModifier::None,
        model::StorageModifier storage = model::StorageModifier::None)
    {
        auto &c = add<model::Coil>(id, x, y);
        c.variable = variable;
        c.negated = negated;
        c.edge = edge;
        c.storage = storage;
        if (!from.empty())
            c.connectionPointIn = wire(from);
        c.connectionPointOut.emplace();
        return *this;
    }
    Diagram &in(quint64 id, const QString &expression, double x = 0, double y = 0, bool negated = false,
        model::EdgeModifier edge = model::EdgeModifier::None)
    {
        auto &v = add<model::InVariable>(id, x, y);
        v.expression = expression;
        v.negated = negated;
        v.edge = edge;
        v.connectionPointOut.emplace();
        return *this;
    }
    Diagram &out(quint64 id, const QString &expression, const std::vector<From> &from, double x = 500, double y = 0,
        model::StorageModifier storage = model::StorageModifier::None, bool negated = false)
    {
        auto &v = add<model::OutVariable>(id, x, y);
        v.expression = expression;
        v.storage = storage;
        v.negated = negated;
        if (!from.empty())
            v.connectionPointIn = wire(from);
        return *this;
    }
    Diagram &inOut(quint64 id, const QString &expression, const std::vector<From> &from, double x = 400, double y = 0)
    {
        auto &v = add<model::InOutVariable>(id, x, y);
        v.expression = expression;
        if (!from.empty())
            v.connectionPointIn = wire(from);
        v.connectionPointOut.emplace();
        return *this;
    }
    Diagram &block(quint64 id, const QString &type, const QString &instance, const std::vector<Pin> &inputs,
        const QStringList &outputs, double x = 200, double y = 0)
    {
        auto &b = add<model::Block>(id, x, y);
        b.typeName = type;
        if (!instance.isEmpty())
            b.instanceName = instance;
        for (const Pin &pin : inputs) {
            model::BlockVariable v;
            v.formalParameter = pin.name;
            v.negated = pin.negated;
            v.edge = pin.edge;
            if (!pin.from.empty())
                v.connectionPointIn = wire(pin.from);
            else
                v.connectionPointIn.emplace();
            b.inputVariables.push_back(v);
        }
        for (const QString &name : outputs) {
            model::BlockVariable v;
            v.formalParameter = name;
            v.connectionPointOut.emplace();
            b.outputVariables.push_back(v);
        }
        return *this;
    }
    Diagram &connector(quint64 id, const QString &name, const std::vector<From> &from, double x = 300, double y = 0)
    {
        auto &c = add<model::Connector>(id, x, y);
        c.name = name;
        c.connectionPointIn = wire(from);
        return *this;
    }
    Diagram &continuation(quint64 id, const QString &name, double x = 0, double y = 0)
    {
        auto &c = add<model::Continuation>(id, x, y);
        c.name = name;
        c.connectionPointOut.emplace();
        return *this;
    }
    Diagram &label(quint64 id, const QString &name, double y)
    {
        add<model::Label>(id, 0, y).label = name;
        return *this;
    }
    Diagram &jump(quint64 id, const QString &label, const std::vector<From> &from, double x = 500, double y = 0)
    {
        auto &j = add<model::Jump>(id, x, y);
        j.label = label;
        j.connectionPointIn = wire(from);
        return *this;
    }
    Diagram &ret(quint64 id, const std::vector<From> &from, double x = 500, double y = 0)
    {
        add<model::Return>(id, x, y).connectionPointIn = wire(from);
        return *this;
    }
    Diagram &order(quint64 id, quint64 executionOrderId)
    {
        for (model::Element &e : elements) {
            if (model::header(e).localId == id)
                model::header(e).executionOrderId = executionOrderId;
        }
        return *this;
    }

    model::Body body(model::BodyLanguage language) const
    {
        model::Body body = model::Body::withLanguage(language);
        *body.elements() = elements;
        return body;
    }
};

// A project with PROGRAM Main (declarations as IEC text) whose body is `diagram`; `extra` holds
// more POUs as IEC text.
inline model::Project diagramProject(const QString &declarations, model::BodyLanguage language, const Diagram &diagram,
    const QString &extra = {})
{
    auto read = interp::frontend::readIecText(
        QString(extra + QStringLiteral("\nPROGRAM Main\n") + declarations + QStringLiteral("\nEND_PROGRAM\n")),
        QStringLiteral("t"));
    for (model::Pou &pou : read.project.types.pous) {
        if (pou.name == QLatin1String("Main"))
            pou.bodies = {diagram.body(language)};
    }
    return read.project;
}

inline QString errorsOf(const interp::Diagnostics &diagnostics)
{
    QStringList lines;
    for (const interp::Diagnostic &d : diagnostics.all()) {
        if (d.severity == interp::Diagnostic::Severity::Error)
            lines << QStringLiteral("%1@%2: %3").arg(d.pou).arg(d.location.localId).arg(d.message);
    }
    return lines.join(QLatin1Char('\n'));
}

// Runs the steps; returns "" when every expectation held, otherwise what went wrong.
inline QString runProject(const model::Project &project, const QStringList &steps)
{
    interp::Diagnostics diagnostics;
    const auto module = interp::frontend::compileProject(project, diagnostics);
    if (!module)
        return QStringLiteral("does not compile: ") + errorsOf(diagnostics);
    interp::Runtime runtime(module);
    return interp::testing::runSteps(runtime, steps);
}

inline QString runDiagram(const QString &declarations, model::BodyLanguage language, const Diagram &diagram,
    const QStringList &steps, const QString &extra = {})
{
    return runProject(diagramProject(declarations, language, diagram, extra), steps);
}

// The compile errors of a diagram, one per line: "Pou@localId: message".
inline QString diagramErrors(const QString &declarations, model::BodyLanguage language, const Diagram &diagram)
{
    interp::Diagnostics diagnostics;
    interp::frontend::compileProject(diagramProject(declarations, language, diagram), diagnostics);
    return errorsOf(diagnostics);
}

} // namespace iec::testing
