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

#include "../tracerunner.h"

#include <QStringList>

#include <functional>

namespace iec::interp::sfctesting {

using testing::errorsOf;

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
    return testing::runSteps(runtime, steps);
}

inline QString runTrace(const QString &source, const QStringList &steps)
{
    return runTrace(readText(source), steps);
}

} // namespace iec::interp::sfctesting
