// The code of the SFC cycle's phases (docs/sfc.md): generated as ST text per phase, with the
// user's statements spliced in (sfcloweringclass.h).
#include "interpreter/sfc/sfcloweringclass.h"

#include "interpreter/compiler/parser.h"
#include "interpreter/sfc/sfcnames.h"
#include "interpreter/sfc/sfctext.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include <algorithm>
#include <limits>

namespace iec::interp::sfc::detail {

namespace {

QString quoted(const QString &text)
{
    QString escaped = text;
    escaped.replace(QLatin1Char('$'), QStringLiteral("$$")).replace(QLatin1Char('\''), QStringLiteral("$'"));
    return QLatin1Char('\'') + escaped + QLatin1Char('\'');
}

} // namespace

void Lowering::generate()
{
    QString text;
    text += preamble();
    text += copyPhase();
    text += exitPhase();
    text += entryPhase();
    text += stepPhase();
    text += actionPhase();
    text += transitionPhase();
    text += epilogue();
    if (m_failed)
        return;
    if (!m_conditionVariables.isEmpty()) {
        QString decl;
        for (const QString &name : m_conditionVariables)
            decl += QStringLiteral("%1 : BOOL;\n").arg(name);
        Diagnostics local;
        auto sections = parseDeclarations(named(QStringLiteral("VAR\n") + decl + QStringLiteral("END_VAR\n")), m_pou.name, local);
        for (ast::VarSection &section : sections)
            m_result.sections.push_back(std::move(section));
    }
    std::vector<ast::Stmt> statements = code(text);
    if (m_failed)
        return;
    expandSplices(statements);
    for (ast::Stmt &s : statements)
        m_output->push_back(std::move(s));
}

QString Lowering::located(const QString &text, quint64 localId, bool isPlace)
{
    if (text.isEmpty())
        return {};
    std::vector<ast::Stmt> statements = code(text, localId);
    if (!isPlace)
        graphical::setPlace(statements, SourceLocation::kNoPlace);
    return spliceText(std::move(statements));
}

QString Lowering::stepReset(bool activateInitial)
{
    QString text;
    for (int i = 0; i < int(m_chart.steps.size()); ++i) {
        const ChartStep &s = m_chart.steps[size_t(i)];
        text += QStringLiteral("%1 := FALSE; %2 := %3; %4 := T#0s; %5 := FALSE;\n")
                    .arg(stepActive(s), stepNext(s), s.initial && activateInitial ? QStringLiteral("TRUE") : QStringLiteral("FALSE"),
                        stepTime(s), hidden("s", i, "re"));
    }
    for (int j = 0; j < m_actions.size(); ++j) {
        text += QStringLiteral("%1 := FALSE; %2 := FALSE; %3 := FALSE; %4 := FALSE; %5 := FALSE; %6 := FALSE;\n")
                    .arg(hidden("a", j, "q"), hidden("a", j, "qm"), hidden("a", j, "sff"), hidden("a", j, "sdff"),
                        hidden("a", j, "dsff"), hidden("a", j, "slff"));
        if (!m_pouActions.contains(key(m_actions[j])) && !m_actions[j].startsWith(QLatin1String("__sfc_inline"))) {
            const QString type = m_declared.value(key(m_actions[j]));
            const bool boolean = type.isEmpty() || type == QLatin1String("BOOL"); // else a number used as an action
            text += QStringLiteral("%1 := %2;\n").arg(m_actions[j], boolean ? QStringLiteral("FALSE") : QStringLiteral("0"));
        }
    }
    return text;
}

QString Lowering::preamble()
{
    QString text = QStringLiteral("__sfc_now := __SYSTIME();\n__sfc_trans := FALSE;\n");
    if (hasFlag("SFCTrans"))
        text += QStringLiteral("SFCTrans := FALSE;\n");
    const bool init = hasFlag("SFCInit"), reset = hasFlag("SFCReset");
    if (init || reset) {
        QString condition = init && reset ? QStringLiteral("SFCInit OR SFCReset") : init ? QStringLiteral("SFCInit") : QStringLiteral("SFCReset");
        text += QStringLiteral("IF %1 THEN\n").arg(condition) + stepReset(true) + QStringLiteral("__sfc_error := FALSE;\n");
        if (hasFlag("SFCError"))
            text += QStringLiteral("SFCError := FALSE;\n");
        text += QStringLiteral("END_IF;\n");
        if (init) {
            // Held before the initial step: it becomes active (and its entry action runs) in the
            // first cycle with SFCInit FALSE.
            text += QStringLiteral("IF SFCInit THEN RETURN; END_IF;\n");
        }
    }
    if (hasFlag("SFCQuitError")) {
        text += QStringLiteral("IF SFCQuitError THEN __sfc_error := FALSE;%1 __sfc_quitm := TRUE; RETURN; END_IF;\n")
                    .arg(hasFlag("SFCError") ? QStringLiteral(" SFCError := FALSE;") : QString());
        text += QStringLiteral("IF __sfc_quitm THEN\n__sfc_quitm := FALSE;\n");
        for (int i = 0; i < int(m_chart.steps.size()); ++i)
            text += QStringLiteral("%1 := __sfc_now;\n").arg(hidden("s", i, "start"));
        text += QStringLiteral("END_IF;\n");
    }
    if (hasFlag("SFCPause"))
        text += QStringLiteral("IF SFCPause THEN RETURN; END_IF;\n");
    if (hasFlag("SFCError"))
        text += QStringLiteral("__sfc_error := SFCError;\n");
    return text;
}

QString Lowering::copyPhase()
{
    QString text;
    for (int i = 0; i < int(m_chart.steps.size()); ++i) {
        const ChartStep &s = m_chart.steps[size_t(i)];
        // Most steps are inactive and stay so: one test. (ex TRUE and x, _x FALSE: left
        // last cycle, so ex must be cleared.)
        text += QStringLiteral("IF %2 OR %3 OR %1 THEN\n%1 := %2 AND (NOT %3 OR %4); %5 := %3 AND (NOT %2 OR %4); %2 := %3; %4 := FALSE;\nEND_IF;\n")
                    .arg(hidden("s", i, "ex"), stepActive(s), stepNext(s), hidden("s", i, "re"), hidden("s", i, "en"));
    }
    for (const ChartMacro &macro : m_chart.macros) {
        QStringList inner;
        for (int i : macro.inner)
            inner << stepActive(m_chart.steps[size_t(i)]);
        if (!inner.isEmpty())
            text += QStringLiteral("%1.x := %2;\n").arg(macro.name, inner.join(QStringLiteral(" OR ")));
    }
    return text;
}

QString Lowering::stepActionPhase(QString model::StepOptions::*action, const char *flag)
{
    QString text;
    for (int i = 0; i < int(m_chart.steps.size()); ++i) {
        const ChartStep &s = m_chart.steps[size_t(i)];
        const QString body = stepActionText(s.options.*action, s);
        if (!body.isEmpty())
            text += QStringLiteral("IF %1 THEN\n%2END_IF;\n").arg(hidden("s", i, flag), body);
    }
    return text;
}

bool Lowering::checkDuration(const QString &duration, quint64 localId, const char *what)
{
    Diagnostics local;
    const auto parsed = parseStBody(QString(QStringLiteral("__sfc_d := ") + duration + QStringLiteral(";")), m_pou.name, local);
    if (local.hasErrors()) {
        error(localId, QCoreApplication::translate("iec::interp::Compiler", "%1 %2 is not a TIME literal or variable.")
                  .arg(QCoreApplication::translate("iec::interp::Compiler", what), duration),
            QCoreApplication::translate("iec::interp::Compiler", "write e.g. T#5s"));
        return false;
    }
    return true;
}

QString Lowering::stepPhase()
{
    QString text;
    const QString enabled = hasFlag("SFCEnableLimit") ? QStringLiteral(" AND SFCEnableLimit") : QString();
    for (int i = 0; i < int(m_chart.steps.size()); ++i) {
        const ChartStep &s = m_chart.steps[size_t(i)];
        // Only the code run when the step is entered carries its localId: a breakpoint on a
        // step halts in the cycle it becomes active. (Inside IF x, as before: most steps are
        // inactive, and one test each is what the chart costs.)
        std::vector<ast::Stmt> entered =
            code(QStringLiteral("IF %1 THEN %2 := __sfc_now; END_IF;\n").arg(hidden("s", i, "en"), hidden("s", i, "start")), s.localId);
        graphical::setPlace(entered, SourceLocation::kNoPlace); // the test runs every cycle
        if (!entered.empty() && !entered.front().branches.empty())
            graphical::setPlace(entered.front().branches.front().body, qint64(s.localId));
        QString step = QStringLiteral("IF %1 THEN\n%2%3 := __sfc_now - %4;\n")
                           .arg(stepActive(s), spliceText(std::move(entered)), stepTime(s), hidden("s", i, "start"));
        const QString max = s.options.maxTime.trimmed();
        if (!max.isEmpty() && checkDuration(max, s.localId, QT_TRANSLATE_NOOP("iec::interp::Compiler", "The maximum time"))) {
            QString raise = QStringLiteral("__sfc_error := TRUE;\n");
            if (hasFlag("SFCError"))
                raise += QStringLiteral("SFCError := TRUE;\n");
            if (hasFlag("SFCErrorStep"))
                raise += QStringLiteral("SFCErrorStep := %1;\n").arg(quoted(s.name));
            if (hasFlag("SFCErrorPOU"))
                raise += QStringLiteral("SFCErrorPOU := %1;\n").arg(quoted(m_pou.name));
            step += QStringLiteral("IF NOT __sfc_error%1 AND %2 > %3 THEN\n%4END_IF;\n").arg(enabled, stepTime(s), max, raise);
        }
        if (!s.options.minTime.trimmed().isEmpty())
            checkDuration(s.options.minTime.trimmed(), s.localId, QT_TRANSLATE_NOOP("iec::interp::Compiler", "The minimum time"));
        step += stepActionText(s.options.activeAction, s);
        step += QStringLiteral("END_IF;\n");
        text += located(step, s.localId, false);
    }
    for (const ChartMacro &macro : m_chart.macros) {
        text += QStringLiteral("IF %1.x THEN\n").arg(macro.name);
        QStringList entered;
        for (int i : macro.inner)
            entered << hidden("s", i, "start");
        // The macro step's time: since its first inner step became active.
        text += QStringLiteral("%1.t := __sfc_now - %2;\nEND_IF;\n").arg(macro.name, hidden("s", macro.inner.front(), "start"));
    }
    return text;
}

QString Lowering::actionPhase()
{
    QString control, finals, actives;
    for (int j = 0; j < m_actions.size(); ++j) {
        control += actionControl(j);
        const QString run = runAction(j);
        finals += QStringLiteral("IF %1 AND NOT %2 THEN\n%3END_IF;\n").arg(hidden("a", j, "qm"), hidden("a", j, "q"), run);
        actives += QStringLiteral("IF %1 OR %2 OR %3 THEN\n%4END_IF;\n")
                       .arg(hidden("a", j, "q"), hidden("a", j, "p1q"), hidden("a", j, "p0q"), run);
    }
    QString tail;
    for (int j = 0; j < m_actions.size(); ++j)
        tail += QStringLiteral("%1 := %2;\n").arg(hidden("a", j, "qm"), hidden("a", j, "q"));
    return control + finals + actives + tail;
}

std::vector<const ChartAssociation *> Lowering::associationsOf(int j) const
{
    std::vector<const ChartAssociation *> result;
    for (const ChartAssociation &a : m_chart.associations) {
        if (key(a.action) == key(m_actions[j]))
            result.push_back(&a);
    }
    return result;
}

QString Lowering::timer(const QString &in, const QString &mem, const QString &start, const QString &pt, const QString &q)
{
    return QStringLiteral("IF %1 THEN\nIF NOT %2 THEN %2 := TRUE; %3 := __sfc_now; END_IF;\n%5 := __sfc_now - %3 >= %4;\n"
                          "ELSE %2 := FALSE; %5 := FALSE; END_IF;\n")
        .arg(in, mem, start, pt, q);
}

QString Lowering::actionControl(int j)
{
    const auto associations = associationsOf(j);
    std::map<QString, QStringList> inputs; // qualifier -> step flags
    std::vector<const ChartAssociation *> timed;
    QStringList indicators;
    for (const ChartAssociation *a : associations) {
        inputs[a->qualifier] << stepActive(m_chart.steps[size_t(a->step)]);
        if (isTimedQualifier(a->qualifier)) {
            if (checkDuration(a->duration, a->localId, QT_TRANSLATE_NOOP("iec::interp::Compiler", "The duration")))
                timed.push_back(a);
        }
        if (!a->indicator.isEmpty())
            indicators << a->indicator;
    }
    const auto input = [&](const char *q) {
        const QStringList flags = inputs[QLatin1String(q)];
        return flags.isEmpty() ? QString() : flags.join(QStringLiteral(" OR "));
    };
    const QString t = hidden("a", j, "t");
    QString text;
    // T: the duration of the active time-qualified association; two active ones are an error.
    if (timed.size() == 1) {
        text += QStringLiteral("%1 := %2;\n").arg(t, timed.front()->duration);
    } else if (timed.size() > 1) {
        text += QStringLiteral("__sfc_count := 0;\n");
        for (const ChartAssociation *a : timed) {
            text += QStringLiteral("IF %1 THEN %2 := %3; __sfc_count := __sfc_count + 1;\nIF __sfc_count > 1 THEN\n__sfc_error := TRUE;\n")
                        .arg(stepActive(m_chart.steps[size_t(a->step)]), t, a->duration);
            if (hasFlag("SFCError"))
                text += QStringLiteral("SFCError := TRUE;\n");
            if (hasFlag("SFCErrorStep"))
                text += QStringLiteral("SFCErrorStep := %1;\n").arg(quoted(m_chart.steps[size_t(a->step)].name));
            if (hasFlag("SFCErrorPOU"))
                text += QStringLiteral("SFCErrorPOU := %1;\n").arg(quoted(m_pou.name));
            text += QStringLiteral("END_IF;\nEND_IF;\n");
        }
        // The first active association's duration counts.
        for (auto it = timed.rbegin(); it != timed.rend(); ++it)
            text += QStringLiteral("IF %1 THEN %2 := %3; END_IF;\n").arg(stepActive(m_chart.steps[size_t((*it)->step)]), t, (*it)->duration);
    }
    const QString r = input("R");
    const QString notR = r.isEmpty() ? QString() : QStringLiteral("NOT (%1) AND ").arg(r);
    QStringList terms;
    if (const QString n = input("N"); !n.isEmpty())
        terms << n;
    if (const QString s = input("S"); !s.isEmpty()) {
        text += QStringLiteral("%1 := %2(%3 OR %1);\n").arg(hidden("a", j, "sff"), notR, s);
        terms << hidden("a", j, "sff");
    } else if (!r.isEmpty()) {
        text += QStringLiteral("%1 := %2%1;\n").arg(hidden("a", j, "sff"), notR);
        terms << hidden("a", j, "sff");
    } else {
        terms << hidden("a", j, "sff"); // stored by nobody: stays FALSE, but cheap to keep uniform
    }
    if (const QString l = input("L"); !l.isEmpty()) {
        text += timer(QStringLiteral("(%1)").arg(l), hidden("a", j, "lm"), hidden("a", j, "ls"), t, hidden("a", j, "lmq"));
        terms << QStringLiteral("((%1) AND NOT %2)").arg(l, hidden("a", j, "lmq"));
    }
    if (const QString d = input("D"); !d.isEmpty()) {
        text += timer(QStringLiteral("(%1)").arg(d), hidden("a", j, "dm"), hidden("a", j, "ds"), t, hidden("a", j, "dmq"));
        terms << hidden("a", j, "dmq");
    }
    if (const QString p = input("P"); !p.isEmpty()) {
        text += QStringLiteral("%1 := (%2) AND NOT %3; %3 := %2;\n").arg(hidden("a", j, "pq"), p, hidden("a", j, "pm"));
        terms << hidden("a", j, "pq");
    }
    if (const QString sd = input("SD"); !sd.isEmpty()) {
        text += QStringLiteral("%1 := %2(%3 OR %1);\n").arg(hidden("a", j, "sdff"), notR, sd);
        text += timer(hidden("a", j, "sdff"), hidden("a", j, "sdm"), hidden("a", j, "sds"), t, hidden("a", j, "sdmq"));
        terms << hidden("a", j, "sdmq");
    } else if (!r.isEmpty()) {
        text += QStringLiteral("%1 := FALSE;\n").arg(hidden("a", j, "sdff"));
    }
    if (const QString ds = input("DS"); !ds.isEmpty()) {
        text += timer(QStringLiteral("(%1)").arg(ds), hidden("a", j, "dsm"), hidden("a", j, "dss"), t, hidden("a", j, "dsmq"));
        text += QStringLiteral("%1 := %2(%3 OR %1);\n").arg(hidden("a", j, "dsff"), notR, hidden("a", j, "dsmq"));
        terms << hidden("a", j, "dsff");
    } else if (!r.isEmpty()) {
        text += QStringLiteral("%1 := FALSE;\n").arg(hidden("a", j, "dsff"));
    }
    if (const QString sl = input("SL"); !sl.isEmpty()) {
        text += QStringLiteral("%1 := %2(%3 OR %1);\n").arg(hidden("a", j, "slff"), notR, sl);
        text += timer(hidden("a", j, "slff"), hidden("a", j, "slm"), hidden("a", j, "sls"), t, hidden("a", j, "slmq"));
        terms << QStringLiteral("(%1 AND NOT %2)").arg(hidden("a", j, "slff"), hidden("a", j, "slmq"));
    } else if (!r.isEmpty()) {
        text += QStringLiteral("%1 := FALSE;\n").arg(hidden("a", j, "slff"));
    }
    text += QStringLiteral("%1 := %2;\n").arg(hidden("a", j, "q"), terms.join(QStringLiteral(" OR ")));
    // P1 and P0 (IEC 61131-3 ed. 3): one run when an association becomes active / inactive.
    if (const QString p1 = input("P1"); !p1.isEmpty())
        text += QStringLiteral("%1 := (%2) AND NOT %3; %3 := %2;\n").arg(hidden("a", j, "p1q"), p1, hidden("a", j, "p1m"));
    if (const QString p0 = input("P0"); !p0.isEmpty())
        text += QStringLiteral("%1 := NOT (%2) AND %3; %3 := %2;\n").arg(hidden("a", j, "p0q"), p0, hidden("a", j, "p0m"));
    // Boolean-variable actions follow Q; the flags of POU actions: A.x (CoDeSys 2.3) is Q,
    // _A.x (V3) is "runs this cycle" and _A._x is Q.
    const QString &name = m_actions[j];
    const QString runs = QStringLiteral("(%1 OR %2 OR %3 OR %4)").arg(hidden("a", j, "q"), hidden("a", j, "qm"), hidden("a", j, "p1q"), hidden("a", j, "p0q"));
    if (m_pouActions.contains(key(name))) {
        if (m_implicitActionFlags.contains(key(name)))
            text += QStringLiteral("%1.x := %2; %1._x := %2;\n").arg(name, hidden("a", j, "q"));
        if (m_implicitActionFlags.contains(key(QLatin1Char('_') + name)))
            text += QStringLiteral("_%1.x := %2; _%1._x := %3;\n").arg(name, runs, hidden("a", j, "q"));
    } else if (!name.startsWith(QLatin1String("__sfc_inline"))) {
        const QString q = QStringLiteral("%1 OR %2 OR %3").arg(hidden("a", j, "q"), hidden("a", j, "p1q"), hidden("a", j, "p0q"));
        const QString type = m_declared.value(key(name));
        if (type.isEmpty() || type == QLatin1String("BOOL"))
            text += QStringLiteral("%1 := %2;\n").arg(name, q);
        else // a number used as an action (CODESYS accepts it): 1 while it is active, else 0
            text += QStringLiteral("%1 := SEL(%2, 0, 1);\n").arg(name, q);
    }
    // Indicator variables are set by the action's own code (IEC 61131-3); the chart only checks
    // that they are Boolean variables.
    for (const QString &indicator : std::as_const(indicators))
        text += QStringLiteral("IF FALSE THEN %1 := %2; END_IF;\n").arg(hidden("a", j, "ind"), indicator);
    const quint64 localId = associations.empty() ? kNoElement : associations.front()->localId;
    return located(text, localId);
}

QString Lowering::runAction(int j)
{
    const QString &name = m_actions[j];
    const auto associations = associationsOf(j);
    const quint64 localId = associations.empty() ? kNoElement : associations.front()->localId;
    // Called once per action (actionPhase), so nothing to cache.
    std::optional<std::vector<ast::Stmt>> body;
    if (const model::PouAction *action = m_pouActions.value(key(name))) {
        body = actionBody(action->body, m_pou.name + QLatin1Char('.') + action->name, localId);
    } else if (!associations.empty() && associations.front()->inlineBody) {
        body = actionBody(*associations.front()->inlineBody, m_pou.name, localId);
    } else {
        const QString type = m_declared.value(key(name));
        if (!type.isEmpty() && type != QLatin1String("BOOL"))
            m_diagnostics.warning(m_pou.name, at(localId),
                QCoreApplication::translate("iec::interp::Compiler", "The action %1 of step %2 is a variable of type %3; it is 1 while the action is active and 0 otherwise.")
                    .arg(name, m_chart.steps[size_t(associations.front()->step)].name, type));
        // A Boolean variable: the control above sets it (an unknown name is reported by the
        // compiler on the action); nothing to run.
        body = std::vector<ast::Stmt> {};
    }
    const int index = body ? splice(std::move(*body)) : -1;
    return index < 0 || m_splices[size_t(index)].empty() ? QString() : QStringLiteral("%1(%2);\n").arg(QLatin1String(kSplice)).arg(index);
}

QString Lowering::transitionPhase()
{
    QString text;
    QString fire;
    if (hasFlag("SFCTipMode") && hasFlag("SFCTip")) {
        // Inching: with SFCTipMode, only a rising edge of SFCTip passes the enabled transitions.
        text += QStringLiteral("__sfc_count := 0; IF SFCTip AND NOT __sfc_tipm THEN __sfc_count := 1; END_IF; __sfc_tipm := SFCTip;\n");
        fire = QStringLiteral("(NOT SFCTipMode AND %1) OR (SFCTipMode AND __sfc_count = 1)");
    } else {
        fire = QStringLiteral("%1");
    }
    for (int k = 0; k < int(m_chart.transitions.size()); ++k) {
        const ChartTransition &t = m_chart.transitions[size_t(k)];
        if (!t.condition || t.sources.empty() || t.targets.empty())
            continue;
        std::vector<ast::Stmt> pre;
        auto cond = condition(t, pre);
        if (!cond)
            continue;
        const QString c = hidden("t", k, "c");
        const SourceLocation where = cond->location;
        pre.push_back(graphical::assignStmt(graphical::nameExpr(named(c), where), std::move(*cond)));
        QStringList enabled;
        for (int s : t.sources) {
            const ChartStep &step = m_chart.steps[size_t(s)];
            enabled << stepNext(step);
            const QString min = step.options.minTime.trimmed();
            if (!min.isEmpty())
                enabled << QStringLiteral("%1 >= %2").arg(stepTime(step), min);
        }
        // The first source's x alone first: most transitions are not enabled.
        const ChartStep &first = m_chart.steps[size_t(t.sources.front())];
        QStringList active;
        for (size_t i = 1; i < t.sources.size(); ++i)
            active << stepActive(m_chart.steps[size_t(t.sources[i])]);
        QString body = QStringLiteral("IF %1 THEN\nIF %2 THEN\n").arg(stepActive(first), (active + enabled).join(QStringLiteral(" AND ")));
        // The condition is no place for the debugger (it is checked every cycle); the firing
        // carries the transition's localId, so a breakpoint on it halts when it fires.
        graphical::setPlace(pre, SourceLocation::kNoPlace);
        body += spliceText(std::move(pre));
        body += QStringLiteral("IF %1 THEN\n").arg(fire.arg(c));
        QString fired;
        for (int s : t.sources)
            fired += QStringLiteral("%1 := FALSE;\n").arg(stepNext(m_chart.steps[size_t(s)]));
        for (int s : t.targets)
            fired += QStringLiteral("%1 := TRUE; %2 := TRUE;\n").arg(stepNext(m_chart.steps[size_t(s)]), hidden("s", s, "re"));
        fired += QStringLiteral("__sfc_trans := TRUE;\n");
        body += located(fired, t.localId);
        body += QStringLiteral("END_IF;\nELSE %1 := FALSE;\nEND_IF;\nELSE %1 := FALSE;\nEND_IF;\n").arg(c);
        text += located(body, t.localId, false);
    }
    return text;
}

QString Lowering::epilogue()
{
    QString text;
    if (hasFlag("SFCTrans"))
        text += QStringLiteral("SFCTrans := __sfc_trans;\n");
    if (hasFlag("SFCCurrentStep")) {
        // The last active step in chart order (the rightmost branch of a parallel sequence).
        for (const ChartStep &s : m_chart.steps)
            text += QStringLiteral("IF %1 THEN SFCCurrentStep := %2; END_IF;\n").arg(stepActive(s), quoted(s.name));
    }
    return text;
}

} // namespace iec::interp::sfc::detail
