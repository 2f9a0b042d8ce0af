#include "interpreter/sfc/sfctext.h"

#include "interpreter/sfc/sfcgraph.h"

#include "interpreter/compiler/astdump.h"

#include "model/layout.h"

#include <QCoreApplication>
#include <QHash>

namespace iec::interp::sfc {

QString expressionText(const ast::Expr &e)
{
    return ast::sourceText(e);
}

namespace {

QString ilText(const std::vector<ast::IlInstruction> &il)
{
    QStringList lines;
    for (const ast::IlInstruction &i : il) {
        QString line;
        if (!i.label.isEmpty())
            line += i.label + QStringLiteral(": ");
        line += i.op;
        if (i.openParen)
            line += QStringLiteral(" (");
        if (i.operand)
            line += QLatin1Char(' ') + expressionText(*i.operand);
        lines << line.trimmed();
    }
    return lines.join(QLatin1Char('\n'));
}

model::ConnectionPointIn wiredTo(quint64 source)
{
    model::ConnectionPointIn in;
    model::Connection connection;
    connection.refLocalId = source;
    in.connections.push_back(connection);
    return in;
}

class Converter
{
public:
    Converter(const ast::SfcChart &chart, const QString &pou, Diagnostics &diagnostics)
        : m_chart(chart), m_pou(pou), m_diagnostics(diagnostics)
    {
    }

    model::Body convert()
    {
        model::Body body = model::Body::withLanguage(model::BodyLanguage::SFC);
        assignIds();
        auto &elements = *body.elements();
        for (size_t s = 0; s < m_chart.steps.size(); ++s)
            addStep(int(s), elements);
        for (size_t t = 0; t < m_chart.transitions.size(); ++t)
            addTransition(int(t), elements);
        model::generateLayoutIfUnplaced(body);
        return body;
    }

private:
    quint64 next() { return m_nextId++; }

    void assignIds()
    {
        for (size_t s = 0; s < m_chart.steps.size(); ++s) {
            const QString key = m_chart.steps[s].name.toUpper();
            if (m_stepIndex.contains(key))
                m_diagnostics.error(m_pou, m_chart.steps[s].location, QCoreApplication::translate("iec::interp::Compiler", "Two steps are called %1.").arg(m_chart.steps[s].name));
            else
                m_stepIndex.insert(key, int(s));
        }
        m_stepId.resize(m_chart.steps.size());
        m_divergence.assign(m_chart.steps.size(), 0);
        m_convergence.assign(m_chart.steps.size(), 0);
        m_out.resize(m_chart.steps.size());
        m_in.resize(m_chart.steps.size());
        for (size_t s = 0; s < m_chart.steps.size(); ++s)
            m_stepId[s] = next();
        m_transitionId.resize(m_chart.transitions.size());
        m_join.assign(m_chart.transitions.size(), 0);
        m_fork.assign(m_chart.transitions.size(), 0);
        m_from.resize(m_chart.transitions.size());
        m_to.resize(m_chart.transitions.size());
        for (size_t t = 0; t < m_chart.transitions.size(); ++t) {
            const ast::SfcTransition &transition = m_chart.transitions[t];
            m_transitionId[t] = next();
            m_from[t] = steps(transition.from, transition);
            m_to[t] = steps(transition.to, transition);
            if (m_from[t].size() > 1)
                m_join[t] = next();
            if (m_to[t].size() > 1)
                m_fork[t] = next();
            for (int s : m_from[t])
                m_out[size_t(s)].push_back(int(t));
            for (int s : m_to[t])
                m_in[size_t(s)].push_back(int(t));
        }
        for (size_t s = 0; s < m_chart.steps.size(); ++s) {
            if (m_out[s].size() > 1)
                m_divergence[s] = next();
            if (m_in[s].size() > 1)
                m_convergence[s] = next();
        }
    }

    std::vector<int> steps(const QStringList &names, const ast::SfcTransition &transition)
    {
        std::vector<int> result;
        for (const QString &name : names) {
            const auto it = m_stepIndex.constFind(name.toUpper());
            if (it == m_stepIndex.constEnd())
                m_diagnostics.error(m_pou, transition.location, QCoreApplication::translate("iec::interp::Compiler", "The transition refers to step %1, which the chart does not have.").arg(name));
            else
                result.push_back(*it);
        }
        return result;
    }

    // What the flow leaves a step through: the step itself, or its selection divergence.
    quint64 exitOf(int s) const { return m_divergence[size_t(s)] ? m_divergence[size_t(s)] : m_stepId[size_t(s)]; }
    // What a transition hands on through: the transition, or its simultaneous divergence.
    quint64 outputOf(int t) const { return m_fork[size_t(t)] ? m_fork[size_t(t)] : m_transitionId[size_t(t)]; }

    void addStep(int s, std::vector<model::Element> &elements)
    {
        const ast::SfcStep &source = m_chart.steps[size_t(s)];
        model::Step step;
        step.localId = m_stepId[size_t(s)];
        step.name = source.name;
        step.initialStep = source.initial;
        step.connectionPointOut = model::ConnectionPointOut {};
        if (!source.actions.empty())
            step.connectionPointOutAction = model::ConnectionPointOut {}; // to its action block
        const std::vector<int> &in = m_in[size_t(s)];
        if (m_convergence[size_t(s)]) {
            model::SelectionConvergence join;
            join.localId = m_convergence[size_t(s)];
            for (int t : in)
                join.connectionPointIns.push_back(wiredTo(outputOf(t)));
            join.connectionPointOut = model::ConnectionPointOut {};
            step.connectionPointIn = wiredTo(join.localId);
            elements.push_back(std::move(step));
            elements.push_back(std::move(join));
        } else {
            step.connectionPointIn = in.empty() ? model::ConnectionPointIn {} : wiredTo(outputOf(in.front()));
            elements.push_back(std::move(step));
        }
        if (m_divergence[size_t(s)]) {
            model::SelectionDivergence split;
            split.localId = m_divergence[size_t(s)];
            split.connectionPointIn = wiredTo(m_stepId[size_t(s)]);
            split.connectionPointOuts.resize(m_out[size_t(s)].size());
            elements.push_back(std::move(split));
        }
        if (!source.actions.empty())
            addActionBlock(s, elements);
    }

    void addActionBlock(int s, std::vector<model::Element> &elements)
    {
        const ast::SfcStep &source = m_chart.steps[size_t(s)];
        model::ActionBlock block;
        block.localId = next();
        block.connectionPointIn = wiredTo(m_stepId[size_t(s)]);
        for (const ast::SfcActionAssociation &association : source.actions) {
            model::ActionBlockAction action;
            action.localId = next();
            action.reference = model::Reference {association.action};
            const QString qualifier = association.qualifier.isEmpty() ? QStringLiteral("N") : association.qualifier;
            action.qualifier = qualifier;
            if (association.duration) {
                action.duration = expressionText(*association.duration);
                if (!association.indicator.isEmpty())
                    action.indicator = association.indicator;
            } else if (!association.indicator.isEmpty()) {
                // ACTION_1(L, tDelay): after a timed qualifier the name is the duration (IEC).
                static const QStringList timed {QStringLiteral("L"), QStringLiteral("D"), QStringLiteral("SD"),
                    QStringLiteral("DS"), QStringLiteral("SL")};
                if (timed.contains(qualifier.toUpper()))
                    action.duration = association.indicator;
                else
                    action.indicator = association.indicator;
            }
            block.actions.push_back(std::move(action));
        }
        elements.push_back(std::move(block));
    }

    void addTransition(int t, std::vector<model::Element> &elements)
    {
        const ast::SfcTransition &source = m_chart.transitions[size_t(t)];
        model::Transition transition;
        transition.localId = m_transitionId[size_t(t)];
        if (source.priority && source.priority->kind == ast::ExprKind::Literal)
            transition.priority = source.priority->text.toULongLong();
        const std::vector<int> &from = m_from[size_t(t)];
        if (m_join[size_t(t)]) {
            model::SimultaneousConvergence join;
            join.localId = m_join[size_t(t)];
            for (int s : from)
                join.connectionPointIns.push_back(wiredTo(exitOf(s)));
            join.connectionPointOut = model::ConnectionPointOut {};
            elements.push_back(std::move(join));
            transition.connectionPointIn = wiredTo(m_join[size_t(t)]);
        } else if (!from.empty()) {
            transition.connectionPointIn = wiredTo(exitOf(from.front()));
        }
        transition.connectionPointOut = model::ConnectionPointOut {};
        model::Condition condition;
        model::InlineCondition inl;
        inl.name = source.name;
        if (source.condition) {
            model::Body body = model::Body::withLanguage(model::BodyLanguage::ST);
            body.setText(expressionText(*source.condition));
            inl.body = body;
        } else {
            model::Body body = model::Body::withLanguage(model::BodyLanguage::IL);
            body.setText(ilText(source.ilCondition));
            inl.body = body;
        }
        condition.kind = std::move(inl);
        transition.condition = std::move(condition);
        elements.push_back(std::move(transition));
        if (m_fork[size_t(t)]) {
            model::SimultaneousDivergence fork;
            fork.localId = m_fork[size_t(t)];
            fork.connectionPointIn = wiredTo(m_transitionId[size_t(t)]);
            fork.connectionPointOuts.resize(m_to[size_t(t)].size());
            elements.push_back(std::move(fork));
        }
    }

    const ast::SfcChart &m_chart;
    QString m_pou;
    Diagnostics &m_diagnostics;
    quint64 m_nextId = 1;
    QHash<QString, int> m_stepIndex;
    std::vector<quint64> m_stepId, m_divergence, m_convergence, m_transitionId, m_join, m_fork;
    std::vector<std::vector<int>> m_out, m_in, m_from, m_to;
};

} // namespace

namespace {

QString indentedText(const QString &text)
{
    QStringList lines = text.trimmed().split(QLatin1Char('\n'));
    for (QString &line : lines)
        line = QStringLiteral("    ") + line;
    return lines.join(QLatin1Char('\n'));
}

// ":= expression;" or ":\n IL" for a condition body; nullopt when the body is a network or
// statements.
std::optional<QString> conditionText(const model::Body &body)
{
    if (body.language() == model::BodyLanguage::ST) {
        QString text = body.text().trimmed();
        while (text.endsWith(QLatin1Char(';')))
            text.chop(1);
        if (text.contains(QLatin1String(":=")))
            return std::nullopt;
        return QStringLiteral(" := %1;").arg(text);
    }
    if (body.language() == model::BodyLanguage::IL)
        return QStringLiteral(":\n%1\n").arg(indentedText(body.text()));
    return std::nullopt;
}

} // namespace

std::optional<QString> printChart(const model::Pou &pou, QString *problem, QStringList *dropped)
{
    const model::Body *body = pou.body();
    if (!body) {
        if (problem)
            *problem = QStringLiteral("it is not a chart");
        return std::nullopt;
    }
    return printChart(pou, *body, pou.name, problem, dropped);
}

std::optional<QString> printChart(const model::Pou &pou, const model::Body &body, const QString &where, QString *problem,
    QStringList *dropped)
{
    const auto fail = [&](const QString &why) -> std::optional<QString> {
        if (problem)
            *problem = why;
        return std::nullopt;
    };
    if (body.language() != model::BodyLanguage::SFC)
        return fail(QStringLiteral("it is not a chart"));
    Diagnostics diagnostics;
    const Chart chart = buildChart(body, where, diagnostics);
    if (diagnostics.hasErrors())
        return fail(diagnostics.all().front().message);
    if (!chart.macros.empty())
        return fail(QStringLiteral("it has macro steps"));
    QString text;
    for (int i = 0; i < int(chart.steps.size()); ++i) {
        const ChartStep &step = chart.steps[size_t(i)];
        if (dropped && !step.options.isDefault())
            *dropped << step.name;
        text += QStringLiteral("%1 %2:\n").arg(step.initial ? QStringLiteral("INITIAL_STEP") : QStringLiteral("STEP"), step.name);
        for (const ChartAssociation &a : chart.associations) {
            if (a.step != i)
                continue;
            if (a.inlineBody)
                return fail(QStringLiteral("step %1 has an action written in its action block").arg(step.name));
            QStringList fields {a.qualifier};
            if (!a.duration.isEmpty())
                fields << a.duration;
            if (!a.indicator.isEmpty())
                fields << a.indicator;
            text += QStringLiteral("    %1(%2);\n").arg(a.action, fields.join(QStringLiteral(", ")));
        }
        text += QStringLiteral("END_STEP\n");
    }
    const auto names = [&](const std::vector<int> &steps) {
        QStringList list;
        for (int s : steps)
            list << chart.steps[size_t(s)].name;
        return list.size() == 1 ? list.front() : QLatin1Char('(') + list.join(QStringLiteral(", ")) + QLatin1Char(')');
    };
    for (const ChartTransition &t : chart.transitions) {
        std::optional<QString> condition;
        const model::Condition &c = *t.condition;
        if (const auto *inl = std::get_if<model::InlineCondition>(&c.kind)) {
            condition = conditionText(*inl->body);
        } else if (const auto *reference = std::get_if<model::Reference>(&c.kind)) {
            const auto named = std::find_if(pou.transitions.begin(), pou.transitions.end(),
                [&](const model::PouTransition &p) { return p.name.compare(reference->name, Qt::CaseInsensitive) == 0; });
            condition = named == pou.transitions.end() ? QStringLiteral(" := %1;").arg(reference->name) : conditionText(named->body);
        } else if (const auto *wire = std::get_if<model::ConnectionPointIn>(&c.kind)) {
            if (wire->expression)
                condition = QStringLiteral(" := %1;").arg(*wire->expression);
            else if (wire->connections.size() == 1 && t.scope && t.scope->elements()) {
                for (const model::Element &e : *t.scope->elements()) {
                    const auto *in = std::get_if<model::InVariable>(&e);
                    if (in && in->localId == wire->connections.front().refLocalId && !in->negated)
                        condition = QStringLiteral(" := %1;").arg(in->expression);
                }
            }
        }
        if (!condition)
            return fail(QStringLiteral("a transition condition is drawn as a network or written as statements"));
        if (c.negated && condition->startsWith(QLatin1String(" := ")))
            condition = QStringLiteral(" := NOT (%1);").arg(condition->mid(4, condition->size() - 5));
        else if (c.negated)
            return fail(QStringLiteral("a negated IL condition has no text form"));
        const QString priority = t.priority ? QStringLiteral(" (PRIORITY := %1)").arg(*t.priority) : QString();
        text += QStringLiteral("TRANSITION%1 FROM %2 TO %3%4").arg(priority, names(t.sources), names(t.targets), *condition);
        text += condition->startsWith(QLatin1String(" := ")) ? QStringLiteral(" END_TRANSITION\n") : QStringLiteral("END_TRANSITION\n");
    }
    return text;
}

model::Body chartToModel(const ast::SfcChart &chart, const QString &pou, Diagnostics &diagnostics)
{
    return Converter(chart, pou, diagnostics).convert();
}

} // namespace iec::interp::sfc
