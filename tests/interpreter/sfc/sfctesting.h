#pragma once

// Helpers for the SFC engine's tests: charts written in textual SFC (read into the model like
// `iecstudio-cli run chart.st` does), optionally edited as model values (step options), compiled
// through the model front end and run scan by scan.
//   A trace step is "name=value; name=value => name=value; ...": the values left of "=>" are
//   written before the cycle, those right of it compared after it. Names are looked up in Main
//   first.

#include "interpreter/frontend/iecreader.h"
#include "interpreter/frontend/projectsource.h"
#include "interpreter/runtime/runtime.h"

#include "model/sfcoptions.h"

#include <QStringList>

#include <functional>

namespace iec::interp::sfctesting {

inline QString errorsOf(const Diagnostics &diagnostics)
{
    QStringList lines;
    for (const Diagnostic &d : diagnostics.all()) {
        if (d.severity == Diagnostic::Severity::Error)
            lines << d.toString();
    }
    return lines.join(QStringLiteral(" | "));
}

inline model::Project readText(const QString &source)
{
    const auto read = frontend::readIecText(source, QStringLiteral("test"));
    return read.project;
}

// Applies `edit` to the options of step `name` of POU `pou`.
inline void editStep(model::Project &project, const QString &pou, const QString &name,
    const std::function<void(model::StepOptions &)> &edit)
{
    for (model::Pou &p : project.types.pous) {
        if (p.name != pou || p.bodies.empty() || !p.bodies.front().elements())
            continue;
        for (model::Element &e : *p.bodies.front().elements()) {
            if (auto *step = std::get_if<model::Step>(&e); step && step->name == name) {
                model::StepOptions options = model::stepOptions(*step);
                edit(options);
                model::setStepOptions(*step, options);
            }
        }
    }
}

inline QString qualified(const Runtime &runtime, const QString &name)
{
    const QString local = QStringLiteral("Main.") + name;
    return runtime.find(local) ? local : name;
}

// Empty when every expectation held; otherwise what went wrong.
inline QString runTrace(const model::Project &project, const QStringList &steps, std::int64_t cycleNs = 10'000'000)
{
    Diagnostics diagnostics;
    CompileOptions options;
    options.cycleNs = cycleNs;
    const auto module = frontend::compileProject(project, diagnostics, options);
    if (!module)
        return QStringLiteral("does not compile: ") + errorsOf(diagnostics);
    Runtime runtime(module, cycleNs);
    QStringList problems;
    int cycle = 0;
    for (const QString &step : steps) {
        ++cycle;
        const QStringList sides = step.split(QStringLiteral("=>"));
        const auto pairs = [](const QString &text) {
            QList<QPair<QString, QString>> out;
            for (const QString &item : text.split(QStringLiteral("; "), Qt::SkipEmptyParts)) {
                const qsizetype eq = item.indexOf(QLatin1Char('='));
                if (eq > 0)
                    out.append({item.left(eq).trimmed(), item.mid(eq + 1).trimmed()});
            }
            return out;
        };
        for (const auto &[name, value] : pairs(sides[0])) {
            if (const auto problem = runtime.write(qualified(runtime, name), value))
                return QStringLiteral("cycle %1: cannot set %2: %3").arg(cycle).arg(name, *problem);
        }
        if (!runtime.runCycle())
            return QStringLiteral("cycle %1: fault: %2").arg(cycle).arg(runtime.fault()->toString());
        if (sides.size() < 2)
            continue;
        for (const auto &[name, expected] : pairs(sides[1])) {
            const auto actual = runtime.read(qualified(runtime, name));
            if (!actual)
                return QStringLiteral("cycle %1: no variable %2").arg(cycle).arg(name);
            if (*actual != expected)
                problems << QStringLiteral("cycle %1: %2 = %3, expected %4").arg(cycle).arg(name, *actual, expected);
        }
    }
    return problems.join(QStringLiteral(" | "));
}

inline QString runTrace(const QString &source, const QStringList &steps)
{
    return runTrace(readText(source), steps);
}

} // namespace iec::interp::sfctesting
