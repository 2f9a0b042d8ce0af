#include "interpreter/sfc/sfcgraph.h"

#include "interpreter/graphical/astbuild.h"

#include <QCoreApplication>
#include <QHash>
#include <QSet>

#include <algorithm>
#include <limits>

namespace iec::interp::sfc {

namespace {

SourceLocation at(quint64 localId)
{
    return graphical::elementLocation(localId);
}

// One graphical body of the chart: the POU's, or a macro step's.
struct Scope {
    const model::Body *body = nullptr;
    const std::vector<model::Element> *elements = nullptr;
    int macro = -1;
    QHash<quint64, int> byId;                // localId -> element index
    QHash<quint64, std::vector<int>> after;  // localId -> elements whose flow input refers to it
};

// The inputs of an element that carry the chart's flow (not action blocks, not wired conditions).
std::vector<const model::ConnectionPointIn *> flowInputs(const model::Element &element)
{
    std::vector<const model::ConnectionPointIn *> inputs;
    const auto one = [&](const std::optional<model::ConnectionPointIn> &in) {
        if (in)
            inputs.push_back(&*in);
    };
    std::visit(
        [&](const auto &e) {
            using E = std::decay_t<decltype(e)>;
            if constexpr (std::is_same_v<E, model::Step> || std::is_same_v<E, model::MacroStep>
                || std::is_same_v<E, model::JumpStep> || std::is_same_v<E, model::Transition>
                || std::is_same_v<E, model::SelectionDivergence> || std::is_same_v<E, model::SimultaneousDivergence>) {
                one(e.connectionPointIn);
            } else if constexpr (std::is_same_v<E, model::SelectionConvergence>
                || std::is_same_v<E, model::SimultaneousConvergence>) {
                for (const model::ConnectionPointIn &in : e.connectionPointIns)
                    inputs.push_back(&in);
            }
        },
        element);
    return inputs;
}

QString kindName(const model::Element &element)
{
    return graphical::elementKindName(element);
}

QString key(const QString &name)
{
    return name.toUpper();
}

class Builder
{
public:
    Builder(const QString &pou, Diagnostics &diagnostics)
        : m_pou(pou), m_diagnostics(diagnostics)
    {
    }

    Chart build(const model::Body &body)
    {
        addScope(body, -1);
        for (size_t s = 0; s < m_scopes.size(); ++s)
            indexScope(m_scopes[s]);
        collectSteps();
        resolveMacros();
        for (size_t s = 0; s < m_scopes.size(); ++s)
            resolveScope(int(s));
        checkInitialStep();
        std::stable_sort(m_chart.transitions.begin(), m_chart.transitions.end(),
            [](const ChartTransition &a, const ChartTransition &b) {
                const quint64 pa = a.priority.value_or(std::numeric_limits<quint64>::max());
                const quint64 pb = b.priority.value_or(std::numeric_limits<quint64>::max());
                if (pa != pb)
                    return pa < pb;
                if (a.x != b.x)
                    return a.x < b.x;
                return a.order < b.order;
            });
        return std::move(m_chart);
    }

private:
    void error(quint64 localId, const QString &message, const QString &hint = {})
    {
        m_diagnostics.error(m_pou, at(localId), message, hint);
    }
    void warning(quint64 localId, const QString &message)
    {
        m_diagnostics.warning(m_pou, at(localId), message);
    }

    void addScope(const model::Body &body, int macro)
    {
        Scope scope;
        scope.body = &body;
        scope.elements = body.elements();
        scope.macro = macro;
        if (!scope.elements)
            return;
        m_scopes.push_back(scope);
    }

    static void indexScope(Scope &scope)
    {
        for (int i = 0; i < int(scope.elements->size()); ++i) {
            const model::Element &element = (*scope.elements)[size_t(i)];
            scope.byId.insert(model::header(element).localId, i);
            for (const model::ConnectionPointIn *in : flowInputs(element)) {
                for (const model::Connection &c : in->connections)
                    scope.after[c.refLocalId].push_back(i);
            }
        }
    }

    const model::Element *find(const Scope &scope, quint64 localId) const
    {
        const auto it = scope.byId.constFind(localId);
        return it == scope.byId.constEnd() ? nullptr : &(*scope.elements)[size_t(*it)];
    }

    int addStep(const QString &name, quint64 localId, bool initial, const model::StepOptions &options, int macro)
    {
        if (name.trimmed().isEmpty()) {
            error(localId, QCoreApplication::translate("iec::interp::Compiler", "A step has no name."), QCoreApplication::translate("iec::interp::Compiler", "give every step a unique name"));
        } else if (m_stepByName.contains(key(name))) {
            error(localId, QCoreApplication::translate("iec::interp::Compiler", "Two steps are called %1; every step of a chart needs its own name.").arg(name));
        }
        ChartStep step;
        step.name = name;
        step.localId = localId;
        step.initial = initial;
        step.options = options;
        step.macro = macro;
        m_chart.steps.push_back(step);
        const int index = int(m_chart.steps.size()) - 1;
        if (!name.trimmed().isEmpty() && !m_stepByName.contains(key(name)))
            m_stepByName.insert(key(name), index);
        return index;
    }

    void collectSteps()
    {
        // Scopes grow while macro bodies are found, so iterate by index.
        for (size_t s = 0; s < m_scopes.size(); ++s) {
            const Scope scope = m_scopes[s];
            for (const model::Element &element : *scope.elements) {
                if (const auto *step = std::get_if<model::Step>(&element)) {
                    const int index = addStep(step->name, step->localId, step->initialStep, model::stepOptions(*step),
                        scope.macro);
                    m_stepOf.insert({int(s), step->localId}, index);
                } else if (const auto *macro = std::get_if<model::MacroStep>(&element)) {
                    const QString name = macro->name.value_or(QString());
                    if (macro->body && (*macro->body)->elements()
                        && (*macro->body)->language() == model::BodyLanguage::SFC) {
                        if (m_stepByName.contains(key(name)) || m_macroNames.contains(key(name)))
                            error(macro->localId, QCoreApplication::translate("iec::interp::Compiler", "Two steps are called %1; every step of a chart needs its own name.").arg(name));
                        m_macroNames.insert(key(name));
                        ChartMacro chartMacro;
                        chartMacro.name = name;
                        chartMacro.localId = macro->localId;
                        m_chart.macros.push_back(chartMacro);
                        const int index = int(m_chart.macros.size()) - 1;
                        m_macroOf.insert({int(s), macro->localId}, index);
                        m_macroBodyScope.push_back(int(m_scopes.size()));
                        Scope inner;
                        inner.body = &**macro->body;
                        inner.elements = inner.body->elements();
                        inner.macro = index;
                        indexScope(inner);
                        m_scopes.push_back(inner);
                    } else {
                        // A macro step without a body behaves as a plain step.
                        const int index = addStep(name, macro->localId, false, {}, scope.macro);
                        m_stepOf.insert({int(s), macro->localId}, index);
                    }
                }
            }
        }
    }

    // The entry step (the body's initial step, else its first step) and exit steps (steps with no
    // transition after them) of each macro.
    void resolveMacros()
    {
        m_macroEntry.assign(m_chart.macros.size(), -1);
        m_macroExits.assign(m_chart.macros.size(), {});
        for (size_t m = 0; m < m_chart.macros.size(); ++m) {
            const int s = m_macroBodyScope[m];
            for (int i = 0; i < int(m_chart.steps.size()); ++i) {
                if (m_chart.steps[size_t(i)].macro != int(m))
                    continue;
                m_chart.macros[m].inner.push_back(i);
                if (m_chart.steps[size_t(i)].initial && m_macroEntry[m] < 0)
                    m_macroEntry[m] = i;
                m_chart.steps[size_t(i)].initial = false; // only the chart's own initial step starts it
                if (!hasFollowingTransition(m_scopes[size_t(s)], m_chart.steps[size_t(i)].localId))
                    m_macroExits[m].push_back(i);
            }
            if (m_macroEntry[m] < 0 && !m_chart.macros[m].inner.empty())
                m_macroEntry[m] = m_chart.macros[m].inner.front();
            if (m_chart.macros[m].inner.empty())
                error(m_chart.macros[m].localId, QCoreApplication::translate("iec::interp::Compiler", "Macro step %1 has no steps inside.").arg(m_chart.macros[m].name));
        }
    }

    bool hasFollowingTransition(const Scope &scope, quint64 localId) const
    {
        for (int i : scope.after.value(localId)) {
            const model::Element &e = (*scope.elements)[size_t(i)];
            if (std::holds_alternative<model::Transition>(e) || std::holds_alternative<model::SelectionDivergence>(e)
                || std::holds_alternative<model::SimultaneousConvergence>(e))
                return true;
        }
        return false;
    }

    // The steps a transition leaves: walk up through selection divergences and simultaneous
    // convergences.
    void upstream(int s, const model::ConnectionPointIn &in, quint64 transition, std::vector<int> &steps, int depth)
    {
        const Scope &scope = m_scopes[size_t(s)];
        if (depth > 64)
            return;
        for (const model::Connection &c : in.connections) {
            if (m_visited.contains(c.refLocalId))
                continue; // a malformed file may loop through divergences: each element once
            m_visited.insert(c.refLocalId);
            const model::Element *e = find(scope, c.refLocalId);
            if (!e) {
                error(transition, QCoreApplication::translate("iec::interp::Compiler", "The transition is connected to element %1, which the chart does not have.").arg(c.refLocalId));
                continue;
            }
            if (std::holds_alternative<model::Step>(*e) || std::holds_alternative<model::MacroStep>(*e)) {
                const quint64 id = model::header(*e).localId;
                if (const auto macro = m_macroOf.constFind({s, id}); macro != m_macroOf.constEnd())
                    steps.insert(steps.end(), m_macroExits[size_t(*macro)].begin(), m_macroExits[size_t(*macro)].end());
                else if (const auto step = m_stepOf.constFind({s, id}); step != m_stepOf.constEnd())
                    steps.push_back(*step);
            } else if (const auto *div = std::get_if<model::SelectionDivergence>(e)) {
                if (div->connectionPointIn)
                    upstream(s, *div->connectionPointIn, transition, steps, depth + 1);
            } else if (const auto *join = std::get_if<model::SimultaneousConvergence>(e)) {
                for (const model::ConnectionPointIn &i : join->connectionPointIns)
                    upstream(s, i, transition, steps, depth + 1);
            } else {
                error(transition,
                    QCoreApplication::translate("iec::interp::Compiler", "A transition must come after a step, a selection divergence or a simultaneous "
                                   "convergence, not after a %1.")
                        .arg(kindName(*e)));
            }
        }
    }

    // The steps a transition activates: walk down through simultaneous divergences, selection
    // convergences and jumps.
    void downstream(int s, quint64 from, quint64 transition, std::vector<int> &steps, int depth)
    {
        const Scope &scope = m_scopes[size_t(s)];
        if (depth > 64)
            return;
        for (int i : scope.after.value(from)) {
            const model::Element &e = (*scope.elements)[size_t(i)];
            const quint64 id = model::header(e).localId;
            if (m_visited.contains(id))
                continue;
            m_visited.insert(id);
            if (std::holds_alternative<model::Step>(e) || std::holds_alternative<model::MacroStep>(e)) {
                if (const auto macro = m_macroOf.constFind({s, id}); macro != m_macroOf.constEnd()) {
                    if (m_macroEntry[size_t(*macro)] >= 0)
                        steps.push_back(m_macroEntry[size_t(*macro)]);
                } else if (const auto step = m_stepOf.constFind({s, id}); step != m_stepOf.constEnd()) {
                    steps.push_back(*step);
                }
            } else if (const auto *jump = std::get_if<model::JumpStep>(&e)) {
                const auto target = m_stepByName.constFind(key(jump->targetName));
                if (target != m_stepByName.constEnd())
                    steps.push_back(*target);
                else if (const auto macro = std::find_if(m_chart.macros.begin(), m_chart.macros.end(),
                             [&](const ChartMacro &m) { return key(m.name) == key(jump->targetName); });
                         macro != m_chart.macros.end() && m_macroEntry[size_t(macro - m_chart.macros.begin())] >= 0)
                    steps.push_back(m_macroEntry[size_t(macro - m_chart.macros.begin())]);
            } else if (std::holds_alternative<model::SimultaneousDivergence>(e)
                || std::holds_alternative<model::SelectionConvergence>(e)) {
                downstream(s, id, transition, steps, depth + 1);
            } else if (std::holds_alternative<model::Transition>(e)) {
                error(id, QCoreApplication::translate("iec::interp::Compiler", "Two transitions follow each other; put a step between them."));
            } else {
                error(transition,
                    QCoreApplication::translate("iec::interp::Compiler", "A transition must lead to a step, a jump, a simultaneous divergence or a selection "
                                   "convergence, not to a %1.")
                        .arg(kindName(e)));
            }
        }
    }

    void resolveScope(int s)
    {
        const Scope &scope = m_scopes[size_t(s)];
        for (const model::Element &element : *scope.elements) {
            std::visit([&](const auto &e) { resolve(s, e); }, element);
        }
    }

    template<typename E> void resolve(int, const E &)
    {
    }

    void resolve(int s, const model::Transition &t)
    {
        ChartTransition transition;
        transition.localId = t.localId;
        transition.condition = t.condition ? &*t.condition : nullptr;
        transition.scope = m_scopes[size_t(s)].body;
        transition.priority = t.priority;
        transition.x = t.position.x;
        transition.order = int(m_chart.transitions.size());
        m_visited.clear();
        if (t.connectionPointIn)
            upstream(s, *t.connectionPointIn, t.localId, transition.sources, 0);
        m_visited.clear();
        downstream(s, t.localId, t.localId, transition.targets, 0);
        dedupe(transition.sources);
        dedupe(transition.targets);
        if (transition.sources.empty())
            error(t.localId, QCoreApplication::translate("iec::interp::Compiler", "This transition has no step before it."),
                QCoreApplication::translate("iec::interp::Compiler", "connect it below a step"));
        if (transition.targets.empty())
            error(t.localId, QCoreApplication::translate("iec::interp::Compiler", "This transition leads to no step."),
                QCoreApplication::translate("iec::interp::Compiler", "connect a step or a jump below it"));
        if (!t.condition)
            error(t.localId, QCoreApplication::translate("iec::interp::Compiler", "This transition has no condition."),
                QCoreApplication::translate("iec::interp::Compiler", "write a condition such as TRUE or Start AND NOT Stop"));
        m_chart.transitions.push_back(std::move(transition));
    }

    void resolve(int s, const model::Step &step)
    {
        checkFollowed(s, step.localId, step.name);
    }

    void resolve(int s, const model::MacroStep &macro)
    {
        checkFollowed(s, macro.localId, macro.name.value_or(QString()));
    }

    void checkFollowed(int s, quint64 localId, const QString &name)
    {
        const Scope &scope = m_scopes[size_t(s)];
        if (scope.macro >= 0) {
            const auto &exits = m_macroExits[size_t(scope.macro)];
            const auto step = m_stepOf.constFind({s, localId});
            if (step != m_stepOf.constEnd() && std::find(exits.begin(), exits.end(), *step) != exits.end())
                return; // the last step of a macro hands over to the transition after the macro
        }
        if (!hasFollowingTransition(scope, localId))
            error(localId, QCoreApplication::translate("iec::interp::Compiler", "Step %1 has no transition after it.").arg(name),
                QCoreApplication::translate("iec::interp::Compiler", "add a transition below it, or a jump back"));
    }

    void resolve(int, const model::JumpStep &jump)
    {
        const bool known = m_stepByName.contains(key(jump.targetName)) || m_macroNames.contains(key(jump.targetName));
        if (!known)
            error(jump.localId, QCoreApplication::translate("iec::interp::Compiler", "The jump goes to step %1, which the chart does not have.").arg(jump.targetName));
    }

    void resolve(int s, const model::SelectionDivergence &div)
    {
        const auto branches = after(s, div.localId);
        if (branches.size() < 2)
            warning(div.localId, QCoreApplication::translate("iec::interp::Compiler", "This selection divergence needs at least two branches; it has %1.").arg(branches.size()));
        for (const model::Element *e : branches) {
            if (!std::holds_alternative<model::Transition>(*e))
                error(div.localId, QCoreApplication::translate("iec::interp::Compiler", "Each branch of a selection divergence must begin with a transition, not a %1.").arg(kindName(*e)));
        }
        if (div.connectionPointIn) {
            for (const model::Element *e : before(s, *div.connectionPointIn)) {
                if (!std::holds_alternative<model::Step>(*e) && !std::holds_alternative<model::MacroStep>(*e)
                    && !std::holds_alternative<model::SimultaneousConvergence>(*e))
                    error(div.localId, QCoreApplication::translate("iec::interp::Compiler", "A selection divergence must come after a step, not after a %1.").arg(kindName(*e)));
            }
        }
    }

    void resolve(int s, const model::SimultaneousDivergence &div)
    {
        const auto branches = after(s, div.localId);
        if (branches.size() < 2)
            warning(div.localId, QCoreApplication::translate("iec::interp::Compiler", "This simultaneous divergence needs at least two branches; it has %1.").arg(branches.size()));
        for (const model::Element *e : branches) {
            if (std::holds_alternative<model::Transition>(*e) || std::holds_alternative<model::SelectionDivergence>(*e)
                || std::holds_alternative<model::SimultaneousConvergence>(*e))
                error(div.localId, QCoreApplication::translate("iec::interp::Compiler", "Each branch of a simultaneous divergence must begin with a step, not a %1.").arg(kindName(*e)));
        }
        if (div.connectionPointIn) {
            for (const model::Element *e : before(s, *div.connectionPointIn)) {
                if (!std::holds_alternative<model::Transition>(*e) && !std::holds_alternative<model::SelectionConvergence>(*e))
                    error(div.localId, QCoreApplication::translate("iec::interp::Compiler", "A simultaneous divergence must come after a transition, not after a %1.").arg(kindName(*e)));
            }
        }
    }

    void resolve(int s, const model::SelectionConvergence &join)
    {
        if (join.connectionPointIns.size() < 2)
            warning(join.localId, QCoreApplication::translate("iec::interp::Compiler", "This selection convergence needs at least two branches; it joins %1.").arg(join.connectionPointIns.size()));
        for (const model::ConnectionPointIn &in : join.connectionPointIns) {
            for (const model::Element *e : before(s, in)) {
                // CODESYS closes a branch that ends in a jump with the convergence line too.
                if (!std::holds_alternative<model::Transition>(*e) && !std::holds_alternative<model::JumpStep>(*e))
                    error(join.localId, QCoreApplication::translate("iec::interp::Compiler", "Each branch of a selection convergence must end with a transition, not a %1.").arg(kindName(*e)));
            }
        }
        for (const model::Element *e : after(s, join.localId)) {
            if (std::holds_alternative<model::Transition>(*e) || std::holds_alternative<model::SelectionDivergence>(*e))
                error(join.localId, QCoreApplication::translate("iec::interp::Compiler", "A selection convergence must lead to a step, not to a %1.").arg(kindName(*e)));
        }
    }

    void resolve(int s, const model::SimultaneousConvergence &join)
    {
        if (join.connectionPointIns.size() < 2)
            warning(join.localId, QCoreApplication::translate("iec::interp::Compiler", "This simultaneous convergence needs at least two branches; it joins %1.").arg(join.connectionPointIns.size()));
        for (const model::ConnectionPointIn &in : join.connectionPointIns) {
            for (const model::Element *e : before(s, in)) {
                if (!std::holds_alternative<model::Step>(*e) && !std::holds_alternative<model::MacroStep>(*e))
                    error(join.localId, QCoreApplication::translate("iec::interp::Compiler", "Each branch of a simultaneous convergence must end with a step, not a %1.").arg(kindName(*e)));
            }
        }
        for (const model::Element *e : after(s, join.localId)) {
            if (!std::holds_alternative<model::Transition>(*e) && !std::holds_alternative<model::SelectionDivergence>(*e))
                error(join.localId, QCoreApplication::translate("iec::interp::Compiler", "A simultaneous convergence must lead to a transition, not to a %1.").arg(kindName(*e)));
        }
    }

    void resolve(int s, const model::ActionBlock &block)
    {
        if (!block.connectionPointIn || block.connectionPointIn->connections.empty()) {
            error(block.localId, QCoreApplication::translate("iec::interp::Compiler", "This action block is not connected to a step."));
            return;
        }
        const quint64 stepId = block.connectionPointIn->connections.front().refLocalId;
        const auto step = m_stepOf.constFind({s, stepId});
        if (step == m_stepOf.constEnd()) {
            error(block.localId, QCoreApplication::translate("iec::interp::Compiler", "An action block must be connected to a step."));
            return;
        }
        for (const model::ActionBlockAction &action : block.actions)
            addAssociation(*step, action);
    }

    void addAssociation(int step, const model::ActionBlockAction &action)
    {
        ChartAssociation association;
        association.step = step;
        association.localId = action.localId;
        association.qualifier = action.qualifier.value_or(QStringLiteral("N")).trimmed().toUpper();
        if (association.qualifier.isEmpty())
            association.qualifier = QStringLiteral("N");
        association.duration = action.duration.value_or(QString()).trimmed();
        association.indicator = action.indicator.value_or(QString()).trimmed();
        if (action.reference) {
            association.action = action.reference->name.trimmed();
        } else if (action.inlineBody) {
            association.action = QStringLiteral("__sfc_inline%1").arg(action.localId);
            association.inlineBody = &**action.inlineBody;
        }
        if (association.action.isEmpty()) {
            error(action.localId, QCoreApplication::translate("iec::interp::Compiler", "This action of step %1 names no action.").arg(m_chart.steps[size_t(step)].name));
            return;
        }
        if (!isKnownQualifier(association.qualifier)) {
            error(action.localId, QCoreApplication::translate("iec::interp::Compiler", "%1 is not an action qualifier; use N, R, S, L, D, P, P0, P1, SD, DS or SL.").arg(association.qualifier));
            return;
        }
        if (isTimedQualifier(association.qualifier) && association.duration.isEmpty()) {
            error(action.localId, QCoreApplication::translate("iec::interp::Compiler", "The qualifier %1 of action %2 needs a duration, e.g. T#5s.").arg(association.qualifier, association.action));
            return;
        }
        if (!isTimedQualifier(association.qualifier))
            association.duration.clear();
        m_chart.associations.push_back(association);
    }

    std::vector<const model::Element *> after(int s, quint64 localId) const
    {
        std::vector<const model::Element *> result;
        const Scope &scope = m_scopes[size_t(s)];
        for (int i : scope.after.value(localId))
            result.push_back(&(*scope.elements)[size_t(i)]);
        return result;
    }

    std::vector<const model::Element *> before(int s, const model::ConnectionPointIn &in) const
    {
        std::vector<const model::Element *> result;
        for (const model::Connection &c : in.connections) {
            if (const model::Element *e = find(m_scopes[size_t(s)], c.refLocalId))
                result.push_back(e);
        }
        return result;
    }

    void checkInitialStep()
    {
        std::vector<int> initial;
        for (int i = 0; i < int(m_chart.steps.size()); ++i) {
            if (m_chart.steps[size_t(i)].initial)
                initial.push_back(i);
        }
        if (initial.empty()) {
            m_diagnostics.error(m_pou, {}, QCoreApplication::translate("iec::interp::Compiler", "The chart of %1 has no initial step.").arg(m_pou),
                QCoreApplication::translate("iec::interp::Compiler", "make one step the initial step (double frame)"));
            return;
        }
        m_chart.initialStep = initial.front();
        for (size_t i = 1; i < initial.size(); ++i) {
            const ChartStep &step = m_chart.steps[size_t(initial[i])];
            error(step.localId,
                QCoreApplication::translate("iec::interp::Compiler", "Step %1 is a second initial step; a chart has exactly one (the first is %2).")
                    .arg(step.name, m_chart.steps[size_t(initial.front())].name));
        }
    }

    static void dedupe(std::vector<int> &v)
    {
        std::vector<int> out;
        for (int x : v) {
            if (std::find(out.begin(), out.end(), x) == out.end())
                out.push_back(x);
        }
        v = std::move(out);
    }

    QString m_pou;
    Diagnostics &m_diagnostics;
    Chart m_chart;
    std::vector<Scope> m_scopes;
    QHash<QString, int> m_stepByName;
    QSet<QString> m_macroNames;
    QHash<QPair<int, quint64>, int> m_stepOf;  // (scope, localId) -> step
    QHash<QPair<int, quint64>, int> m_macroOf; // (scope, localId) -> macro
    std::vector<int> m_macroBodyScope;
    QSet<quint64> m_visited; // elements passed by the current walk up or down
    std::vector<int> m_macroEntry;
    std::vector<std::vector<int>> m_macroExits;
};

} // namespace

bool isTimedQualifier(const QString &qualifier)
{
    return qualifier == QLatin1String("L") || qualifier == QLatin1String("D") || qualifier == QLatin1String("SD")
        || qualifier == QLatin1String("DS") || qualifier == QLatin1String("SL");
}

bool isKnownQualifier(const QString &qualifier)
{
    static const QStringList known {QStringLiteral("N"), QStringLiteral("R"), QStringLiteral("S"), QStringLiteral("L"),
        QStringLiteral("D"), QStringLiteral("P"), QStringLiteral("P0"), QStringLiteral("P1"), QStringLiteral("SD"),
        QStringLiteral("DS"), QStringLiteral("SL")};
    return known.contains(qualifier);
}

Chart buildChart(const model::Body &body, const QString &pouName, Diagnostics &diagnostics)
{
    return Builder(pouName, diagnostics).build(body);
}

} // namespace iec::interp::sfc
