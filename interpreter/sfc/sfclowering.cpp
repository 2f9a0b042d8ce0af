// SFC charts become statements and variables of their POU (docs/sfc.md has the cycle order and
// every rule). The chart's own code is generated as ST text per element and parsed, so it reads
// like what a student would write; the user's bodies (actions, conditions) are parsed on their
// own, with their own diagnostics, and spliced in where the placeholder __SFC_SPLICE(n) stands.
#include "interpreter/sfc/sfclowering.h"

#include "interpreter/graphical/astbuild.h"

#include "interpreter/compiler/limits.h"
#include "interpreter/compiler/parser.h"
#include "interpreter/graphical/graphicallowering.h"
#include "interpreter/sfc/sfcgraph.h"
#include "interpreter/sfc/sfcnames.h"
#include "interpreter/sfc/sfctext.h"

#include <QCoreApplication>
#include <QHash>
#include <QRegularExpression>
#include <QSet>

#include <algorithm>
#include <limits>
#include <map>
#include <memory>

namespace iec::interp::sfc {

QStringList chartActions(const Chart &chart)
{
    QStringList names;
    QSet<QString> seen;
    for (const ChartAssociation &a : chart.associations) {
        if (!seen.contains(a.action.toUpper())) {
            seen.insert(a.action.toUpper());
            names << a.action;
        }
    }
    std::stable_sort(names.begin(), names.end(),
        [](const QString &a, const QString &b) { return a.compare(b, Qt::CaseInsensitive) < 0; });
    return names;
}

namespace {

constexpr const char *kSplice = "__SFC_SPLICE";

// The SFC flags a POU may declare (CoDeSys). Inputs are read, outputs written.
struct Flag {
    const char *name;
    const char *type;
    const char *codesysSetting; // the element name in CODESYS V3's SFCSettings addData
};
constexpr Flag kFlags[] = {
    {"SFCInit", "BOOL", "Init"},
    {"SFCReset", "BOOL", "Reset"},
    {"SFCPause", "BOOL", "Pause"},
    {"SFCError", "BOOL", "Error"},
    {"SFCErrorStep", "STRING", "ErrorStep"},
    {"SFCErrorPOU", "STRING", "ErrorPOU"},
    {"SFCQuitError", "BOOL", "QuitError"},
    {"SFCEnableLimit", "BOOL", "EnableLimit"},
    {"SFCTrans", "BOOL", "Trans"},
    {"SFCCurrentStep", "STRING", "CurrentStep"},
    {"SFCTip", "BOOL", "Tip"},
    {"SFCTipMode", "BOOL", "TipMode"},
};

QString key(const QString &name)
{
    return name.toUpper();
}

QString quoted(const QString &text)
{
    QString escaped = text;
    escaped.replace(QLatin1Char('$'), QStringLiteral("$$")).replace(QLatin1Char('\''), QStringLiteral("$'"));
    return QLatin1Char('\'') + escaped + QLatin1Char('\'');
}

using graphical::notExpr; // folds NOT TRUE to FALSE; the parser writes TRUE/FALSE upper-case

// A simple IL condition (LD, AND, OR, XOR with N, NOT, comparisons, ST to the result) as an
// expression. nullopt when the list uses jumps, parentheses or calls, or (`tooDeep` set) more
// NOTs than an expression may nest (limits.h): each wraps all that comes before it.
std::optional<ast::Expr> ilToExpression(const std::vector<ast::IlInstruction> &il, bool &tooDeep)
{
    std::optional<ast::Expr> acc;
    int nots = 0;
    static const QHash<QString, QString> binary {{QStringLiteral("AND"), QStringLiteral("AND")},
        {QStringLiteral("&"), QStringLiteral("AND")}, {QStringLiteral("OR"), QStringLiteral("OR")},
        {QStringLiteral("XOR"), QStringLiteral("XOR")}, {QStringLiteral("GT"), QStringLiteral(">")},
        {QStringLiteral("GE"), QStringLiteral(">=")}, {QStringLiteral("EQ"), QStringLiteral("=")},
        {QStringLiteral("NE"), QStringLiteral("<>")}, {QStringLiteral("LT"), QStringLiteral("<")},
        {QStringLiteral("LE"), QStringLiteral("<=")}, {QStringLiteral("ADD"), QStringLiteral("+")},
        {QStringLiteral("SUB"), QStringLiteral("-")}, {QStringLiteral("MUL"), QStringLiteral("*")},
        {QStringLiteral("DIV"), QStringLiteral("/")}};
    for (const ast::IlInstruction &i : il) {
        if (i.op.isEmpty())
            continue; // a lone label
        if (i.openParen || !i.label.isEmpty())
            return std::nullopt;
        QString op = i.op.toUpper();
        if (op == QLatin1String("ST") || op == QLatin1String("STN"))
            break; // TRANSITION T FROM .. TO ..: LD x ST T: the accumulator is the condition
        if (op == QLatin1String("NOT") && !i.operand && acc) {
            if (++nots > limits::kMaxNesting) {
                tooDeep = true;
                return std::nullopt;
            }
            acc = notExpr(std::move(*acc));
            continue;
        }
        if (!i.operand)
            return std::nullopt;
        bool negate = false;
        if (op.size() > 2 && op.endsWith(QLatin1Char('N')) && op != QLatin1String("MIN")) {
            negate = true;
            op.chop(1);
        }
        ast::Expr operand = *i.operand;
        if (negate)
            operand = notExpr(std::move(operand));
        if (op == QLatin1String("LD")) {
            acc = std::move(operand);
        } else if (binary.contains(op) && acc) {
            ast::Expr e;
            e.kind = ast::ExprKind::Binary;
            e.text = binary.value(op);
            e.location = i.location;
            e.operands.push_back(std::move(*acc));
            e.operands.push_back(std::move(operand));
            acc = std::move(e);
        } else {
            return std::nullopt;
        }
    }
    return acc;
}

class Lowering
{
public:
    // `hiddenPrefix` starts the names of the hidden variables ("__sfc_"; a chart in an action has
    // its own, so that it runs beside the POU's chart). The statements go to `output`, by default
    // the POU's body.
    Lowering(const model::Pou &pou, ast::Pou &result, Diagnostics &diagnostics, const std::vector<ast::SfcAction> *parsed,
        QString hiddenPrefix = QStringLiteral("__sfc_"), std::vector<ast::Stmt> *output = nullptr)
        : m_pou(pou), m_result(result), m_diagnostics(diagnostics), m_parsed(parsed), m_hiddenPrefix(std::move(hiddenPrefix)),
          m_output(output ? output : &result.body.statements)
    {
    }

    void run()
    {
        const model::Body *body = m_pou.body();
        if (!body)
            return;
        Diagnostics structure;
        m_chart = buildChart(*body, m_pou.name, structure);
        m_diagnostics.append(structure);
        if (structure.hasErrors())
            return;
        collectDeclaredNames();
        declareCodesysFlags();
        m_actions = chartActions(m_chart);
        declare();
        if (m_failed)
            return;
        generate();
    }

private:
    // ---- helpers ------------------------------------------------------------------------------

    static constexpr quint64 kNoElement = ~quint64(0);

    SourceLocation at(quint64 localId) const { return graphical::elementLocation(localId); } // kNoElement: none

    void error(quint64 localId, const QString &message, const QString &hint = {})
    {
        m_diagnostics.error(m_pou.name, at(localId), message, hint);
        m_failed = true;
    }

    bool declared(const QString &name) const { return m_declared.contains(key(name)); }
    bool hasFlag(const char *name) const { return declared(QLatin1String(name)); }

    // Generated ST, located on `localId`. `{Name}` placeholders are not used: callers build text.
    // The generated text with this chart's own names for its hidden variables.
    QString named(QString text) const
    {
        if (m_hiddenPrefix != QLatin1String("__sfc_"))
            text.replace(QLatin1String("__sfc_"), m_hiddenPrefix);
        return text;
    }

    std::vector<ast::Stmt> code(const QString &text, quint64 localId = kNoElement)
    {
        Diagnostics local;
        std::vector<ast::Stmt> statements = parseStBody(named(text), m_pou.name, local);
        if (local.hasErrors()) {
            // Only user text inside (a duration, a variable name) can make it fail.
            m_diagnostics.error(m_pou.name, at(localId),
                QCoreApplication::translate("iec::interp::Compiler", "The chart's code for this element does not parse: %1").arg(local.all().front().message));
            m_failed = true;
            return {};
        }
        graphical::relocate(statements, at(localId)); // point at the chart element
        return statements;
    }

    int splice(std::vector<ast::Stmt> statements)
    {
        m_splices.push_back(std::move(statements));
        return int(m_splices.size()) - 1;
    }

    QString spliceText(std::vector<ast::Stmt> statements)
    {
        if (statements.empty())
            return {};
        return QStringLiteral("%1(%2);\n").arg(QLatin1String(kSplice)).arg(splice(std::move(statements)));
    }

    void expandSplices(std::vector<ast::Stmt> &statements)
    {
        std::vector<ast::Stmt> out;
        for (ast::Stmt &s : statements) {
            if (s.kind == ast::StmtKind::Call && s.target.kind == ast::ExprKind::Call
                && s.target.text == QLatin1String(kSplice) && s.target.callArgs.size() == 1) {
                const int index = s.target.callArgs.front().value.text.toInt();
                std::vector<ast::Stmt> inner = m_splices[size_t(index)];
                expandSplices(inner);
                for (ast::Stmt &i : inner)
                    out.push_back(std::move(i));
                continue;
            }
            expandSplices(s.body);
            for (ast::ConditionalBlock &b : s.branches)
                expandSplices(b.body);
            for (ast::CaseBranch &c : s.cases)
                expandSplices(c.body);
            out.push_back(std::move(s));
        }
        statements = std::move(out);
    }

    // ---- declarations -------------------------------------------------------------------------

    void collectDeclaredNames()
    {
        for (ast::VarSection &section : m_result.sections) {
            // CoDeSys 2.3 projects declare the step and action structures themselves; the chart
            // declares them anyway, so those declarations go.
            std::erase_if(section.vars, [](const ast::VarDecl &v) {
                const QString type = v.type.kind == ast::TypeSpec::Kind::Named ? v.type.name.toUpper() : QString();
                return type == QLatin1String("SFCSTEPTYPE") || type == QLatin1String("SFCACTIONTYPE");
            });
            for (const ast::VarDecl &v : section.vars)
                m_declared.insert(key(v.name), v.type.kind == ast::TypeSpec::Kind::Named ? v.type.name.toUpper() : QString());
        }
        for (const model::PouAction &action : m_pou.actions)
            m_pouActions.insert(key(action.name), &action);
        for (const model::PouTransition &transition : m_pou.transitions)
            m_pouTransitions.insert(key(transition.name), &transition);
    }

    // CODESYS V3 declares the flags its SFC settings mark with Declare="true".
    void declareCodesysFlags()
    {
        for (const model::AddDataEntry &entry : m_pou.addData) {
            if (!entry.name.endsWith(QLatin1String("/sfcsettings")))
                continue;
            for (const Flag &flag : kFlags) {
                const QRegularExpression declared(
                    QStringLiteral("<%1\\s+Declare=\"true\"").arg(QLatin1String(flag.codesysSetting)));
                if (declared.match(entry.content).hasMatch() && !hasFlag(flag.name)) {
                    m_extraDeclarations += QStringLiteral("%1 : %2;\n").arg(QLatin1String(flag.name), QLatin1String(flag.type));
                    m_declared.insert(key(QLatin1String(flag.name)), QLatin1String(flag.type));
                }
            }
        }
    }

    // An implicit variable the chart declares unless the POU already has it with the right type.
    void implicit(QString &text, const QString &name, const QString &type, quint64 localId)
    {
        if (declared(name)) {
            const QString userType = m_declared.value(key(name));
            if (!type.startsWith(QLatin1String("STRUCT")) && userType == type.section(QLatin1Char(' '), 0, 0).toUpper())
                return; // CoDeSys 2.3: "_timeStep1 : TIME;" declared by hand
            error(localId, QCoreApplication::translate("iec::interp::Compiler", "%1 is the name of a variable and of the chart's implicit variable; rename one of them.").arg(name));
            return;
        }
        m_declared.insert(key(name), type);
        text += QStringLiteral("%1 : %2;\n").arg(name, type);
    }

    void declare()
    {
        QString text = m_extraDeclarations;
        text += QStringLiteral("__sfc_now : TIME;\n__sfc_trans : BOOL;\n__sfc_error : BOOL;\n__sfc_count : INT;\n"
                               "__sfc_tipm : BOOL;\n__sfc_quitm : BOOL;\n");
        for (int i = 0; i < int(m_chart.steps.size()); ++i) {
            const ChartStep &step = m_chart.steps[size_t(i)];
            const QString init = step.initial ? QStringLiteral(" := TRUE") : QString();
            if (step.options.simplified) {
                implicit(text, step.name, QStringLiteral("BOOL"), step.localId);
                implicit(text, QLatin1Char('_') + step.name, QStringLiteral("BOOL") + init, step.localId);
                implicit(text, QStringLiteral("_time") + step.name, QStringLiteral("TIME"), step.localId);
            } else {
                implicit(text, step.name,
                    QStringLiteral("STRUCT x : BOOL; _x : BOOL%1; t : TIME; _t : TIME; END_STRUCT").arg(init),
                    step.localId);
            }
            text += QStringLiteral("%1 : TIME; %2 : BOOL; %3 : BOOL; %4 : BOOL;\n")
                        .arg(hidden("s", i, "start"), hidden("s", i, "re"), hidden("s", i, "en"), hidden("s", i, "ex"));
        }
        for (const ChartMacro &macro : m_chart.macros)
            implicit(text, macro.name, QStringLiteral("STRUCT x : BOOL; t : TIME; END_STRUCT"), macro.localId);
        for (int k = 0; k < int(m_chart.transitions.size()); ++k)
            text += QStringLiteral("%1 : BOOL;\n").arg(hidden("t", k, "c"));
        for (int j = 0; j < m_actions.size(); ++j)
            declareAction(text, j);
        Diagnostics local;
        std::vector<ast::VarSection> sections
            = parseDeclarations(named(QStringLiteral("VAR\n") + text + QStringLiteral("END_VAR\n")), m_pou.name, local);
        if (local.hasErrors()) {
            m_diagnostics.error(m_pou.name, {},
                QCoreApplication::translate("iec::interp::Compiler", "The chart's variables cannot be declared: %1").arg(local.all().front().message));
            m_failed = true;
            return;
        }
        for (ast::VarSection &section : sections) {
            for (ast::VarDecl &v : section.vars)
                v.location = {};
            m_result.sections.push_back(std::move(section));
        }
    }

    void declareAction(QString &text, int j)
    {
        const QString &name = m_actions[j];
        // Q, Q last cycle, the stored flip-flops, edge memories and timer starts of ACTION_CONTROL.
        for (const char *flag : {"q", "qm", "sff", "sdff", "dsff", "slff", "pm", "pq", "p1m", "p0m", "p1q", "p0q",
                 "lm", "lmq", "dm", "dmq", "sdm", "sdmq", "dsm", "dsmq", "slm", "slmq", "ind"})
            text += QStringLiteral("%1 : BOOL;\n").arg(hidden("a", j, flag));
        for (const char *start : {"ls", "ds", "sds", "dss", "sls", "t"})
            text += QStringLiteral("%1 : TIME;\n").arg(hidden("a", j, start));
        // An action the chart calls (IL) keeps its own name, so no implicit Act.x flag hides it.
        if (m_pouActions.contains(key(name)) && !declared(name) && !isCalledAction(name)) {
            implicit(text, name, QStringLiteral("STRUCT x : BOOL; _x : BOOL; END_STRUCT"), 0);
            m_implicitActionFlags.insert(key(name));
            if (!declared(QLatin1Char('_') + name)) {
                implicit(text, QLatin1Char('_') + name, QStringLiteral("STRUCT x : BOOL; _x : BOOL; END_STRUCT"), 0);
                m_implicitActionFlags.insert(key(QLatin1Char('_') + name));
            }
        }
    }

    // ---- user bodies --------------------------------------------------------------------------

    // IL cannot be inlined into the chart's ST; such an action is compiled as an action of the
    // POU (Main.Act) and the chart calls it: Act();
    bool isCalledAction(const QString &name) const
    {
        // IL and charts: compiled apart and called.
        if (m_parsed) {
            for (const ast::SfcAction &action : *m_parsed)
                if (key(action.name) == key(name))
                    return action.body.language == ast::Language::IL || action.body.language == ast::Language::SFC;
        }
        const model::PouAction *action = m_pouActions.value(key(name));
        return action && (action->body.language() == model::BodyLanguage::IL || action->body.language() == model::BodyLanguage::SFC);
    }

    std::vector<ast::Stmt> callAction(const QString &name, ast::Body body, quint64 localId)
    {
        if (!m_calledActions.contains(key(name))) {
            m_calledActions.insert(key(name));
            ast::SfcAction action;
            action.name = name;
            action.body = std::move(body);
            m_result.actions.push_back(std::move(action));
        }
        return code(name + QStringLiteral("();\n"), localId);
    }

    // The statements of a POU action (entry/exit/active action or IEC action).
    std::optional<std::vector<ast::Stmt>> actionBody(const model::Body &body, const QString &owner, quint64 localId)
    {
        if (m_parsed) {
            const QString name = owner.section(QLatin1Char('.'), -1);
            for (const ast::SfcAction &action : *m_parsed) {
                if (key(action.name) != key(name) || owner == m_pou.name)
                    continue;
                if (action.body.language == ast::Language::ST || action.body.language == ast::Language::None)
                    return action.body.statements;
                if (action.body.language == ast::Language::IL)
                    return callAction(action.name, action.body, localId);
                if (m_calledActions.contains(key(name)))
                    return code(name + QStringLiteral("();\n"), localId);
                model::PouAction chartAction; // a chart in the action: see the SFC case below
                chartAction.name = action.name;
                chartAction.body = chartToModel(*action.body.sfc, m_pou.name, m_diagnostics);
                ast::Body chart;
                chart.language = ast::Language::ST;
                if (!lowerNestedChart(chartAction, chart.statements))
                    return std::nullopt;
                return callAction(name, std::move(chart), localId);
            }
        }
        switch (body.language()) {
        case model::BodyLanguage::ST:
            if (const auto cfc = graphical::cfcDiagram(body)) { // CODESYS CFC: empty ST text, diagram in addData
                graphical::LoweringContext context {m_result, owner, m_diagnostics};
                return graphical::lowerBody(*cfc, context);
            }
            return parseStBody(body.text(), owner, m_diagnostics);
        case model::BodyLanguage::IL: {
            const QString name = owner.section(QLatin1Char('.'), -1);
            if (owner == m_pou.name) { // an inline action body has no name to call
                error(localId, QCoreApplication::translate("iec::interp::Compiler", "This inline action is written in IL; an inline action must be written in ST, LD or FBD."),
                    QCoreApplication::translate("iec::interp::Compiler", "make it an action of %1 and name it in the step").arg(m_pou.name));
                return std::nullopt;
            }
            ast::Body parsed;
            parsed.language = ast::Language::IL;
            parsed.il = parseIlBody(body.text(), owner, m_diagnostics);
            return callAction(name, std::move(parsed), localId);
        }
        case model::BodyLanguage::LD:
        case model::BodyLanguage::FBD: {
            graphical::LoweringContext context {m_result, owner, m_diagnostics};
            return graphical::lowerBody(body, context);
        }
        case model::BodyLanguage::SFC: {
            // A chart in an action: lowered on its own (hidden variables named apart) and compiled
            // as an action of the POU that the step calls, so its state lives in the instance.
            const QString name = owner.section(QLatin1Char('.'), -1);
            if (m_calledActions.contains(key(name)))
                return code(name + QStringLiteral("();\n"), localId); // lowered already, or by the POU's own list
            const model::PouAction *action = m_pouActions.value(key(name));
            if (!action || owner == m_pou.name || m_hiddenPrefix.contains(QLatin1Char('_') + name + QLatin1Char('_'))) {
                error(localId, QCoreApplication::translate("iec::interp::Compiler", "%1 is an SFC chart that contains itself.").arg(owner));
                return std::nullopt;
            }
            ast::Body chart;
            chart.language = ast::Language::ST;
            if (!lowerNestedChart(*action, chart.statements))
                return std::nullopt;
            return callAction(name, std::move(chart), localId);
        }
        }
        return std::nullopt;
    }

public:
    // An action of the POU whose body is a chart: its statements into `out`, its variables and the
    // actions it calls into the POU.
    bool lowerNestedChart(const model::PouAction &action, std::vector<ast::Stmt> &out)
    {
        model::Pou chartPou = m_pou;
        chartPou.bodies.clear();
        chartPou.bodies.push_back(action.body);
        if (m_hiddenPrefix.contains(QLatin1Char('_') + action.name + QLatin1Char('_'))) {
            error(kNoElement, QCoreApplication::translate("iec::interp::Compiler", "%1 is an SFC chart that contains itself.").arg(m_pou.name + QLatin1Char('.') + action.name));
            return false;
        }
        Lowering nested(chartPou, m_result, m_diagnostics, m_parsed, m_hiddenPrefix + action.name + QLatin1Char('_'), &out);
        nested.m_calledActions = m_calledActions;
        nested.run();
        m_calledActions.unite(nested.m_calledActions);
        return !nested.m_failed;
    }

private:

    // A POU action by name (entry/exit/active actions of a step).
    QString stepActionText(const QString &name, const ChartStep &step)
    {
        if (name.isEmpty())
            return {};
        const model::PouAction *action = m_pouActions.value(key(name));
        if (!action) {
            error(step.localId, QCoreApplication::translate("iec::interp::Compiler", "Step %1 runs action %2, which %3 does not have.").arg(step.name, name, m_pou.name));
            return {};
        }
        auto statements = actionBody(action->body, m_pou.name + QLatin1Char('.') + action->name, step.localId);
        return statements ? spliceText(std::move(*statements)) : QString();
    }

    // An ST condition: an expression, or statements that assign the transition's name. An inline
    // condition (`inlineOn`: its transition) is reported on the transition, at the place counted
    // in its text; a named transition's on the lines of its own body.
    std::optional<ast::Expr> stCondition(const QString &text, const QString &owner, const QString &resultName,
        std::vector<ast::Stmt> &pre, std::optional<quint64> inlineOn = {})
    {
        if (!text.contains(QLatin1String(":="))) {
            // Only the end is cut, so that lines and columns stay the user's.
            QString expression = text;
            while (!expression.isEmpty() && (expression.back().isSpace() || expression.back() == QLatin1Char(';')))
                expression.chop(1);
            Diagnostics local;
            auto statements = parseStBody(QString(QStringLiteral("__sfc_cond :=\n") + expression + QStringLiteral("\n;")), owner, local, 0);
            reportCondition(local, owner, inlineOn, expression, true);
            if (local.hasErrors() || statements.size() != 1 || statements.front().kind != ast::StmtKind::Assign) {
                m_failed = true;
                return std::nullopt;
            }
            if (inlineOn)
                graphical::relocate(statements, at(*inlineOn));
            return std::move(statements.front().value);
        }
        Diagnostics local;
        auto statements = parseStBody(text, owner, local);
        reportCondition(local, owner, inlineOn, text, false);
        if (local.hasErrors())
            m_failed = true;
        if (inlineOn)
            graphical::relocate(statements, at(*inlineOn));
        for (ast::Stmt &s : statements)
            pre.push_back(std::move(s));
        return conditionVariable(resultName);
    }

    // Passes on what parsing a condition's `text` found (see stCondition).
    void reportCondition(const Diagnostics &local, const QString &owner, std::optional<quint64> inlineOn, const QString &text,
        bool errorsOnly)
    {
        const QStringList lines = text.split(QLatin1Char('\n'));
        for (const Diagnostic &d : local.all()) {
            const bool isError = d.severity == Diagnostic::Severity::Error;
            if (errorsOnly && !isError)
                continue;
            SourceLocation where = d.location;
            QString message = d.message;
            if (inlineOn) {
                where = at(*inlineOn);
                if (d.location.line >= 1 && d.location.line <= lines.size()) {
                    // The place in the condition as one text: its lines before, then the column.
                    int offset = 0;
                    for (int line = 1; line < d.location.line; ++line)
                        offset += int(lines[line - 1].size()) + 1;
                    where.column = offset + std::max(1, d.location.column);
                } else {
                    // At what the lowering added after the text: the condition stops too early.
                    where.column = int(text.size()) + 1;
                    message = QCoreApplication::translate("iec::interp::Compiler", "The condition %1 is incomplete: something is missing at its end.")
                                  .arg(text.trimmed());
                }
            }
            if (isError)
                m_diagnostics.error(owner, where, message, d.hint);
            else
                m_diagnostics.warning(owner, where, message, d.hint);
        }
    }

    ast::Expr conditionVariable(const QString &name)
    {
        if (!declared(name)) {
            m_declared.insert(key(name), QStringLiteral("BOOL"));
            m_conditionVariables << name;
        }
        return graphical::nameExpr(name, {});
    }

    // `inlineOn`: the transition whose inline body this is (see stCondition).
    std::optional<ast::Expr> bodyCondition(const model::Body &body, const QString &owner, const QString &name,
        quint64 localId, std::vector<ast::Stmt> &pre, std::optional<quint64> inlineOn = {})
    {
        switch (body.language()) {
        case model::BodyLanguage::ST:
            return stCondition(body.text(), owner, name, pre, inlineOn);
        case model::BodyLanguage::IL: {
            const size_t before = m_diagnostics.all().size();
            const auto il = parseIlBody(body.text(), owner, m_diagnostics);
            if (m_diagnostics.all().size() != before && m_diagnostics.hasErrors()) {
                m_failed = true;
                return std::nullopt;
            }
            bool tooDeep = false;
            if (auto expr = ilToExpression(il, tooDeep))
                return expr;
            if (tooDeep) {
                error(localId, QCoreApplication::translate("iec::interp::Compiler", "This IL condition is nested too deeply (more than %1 levels).").arg(limits::kMaxNesting),
                    QCoreApplication::translate("iec::interp::Compiler", "split it into several statements, with variables for the parts"));
                return std::nullopt;
            }
            error(localId, QCoreApplication::translate("iec::interp::Compiler", "This IL condition uses jumps, parentheses or calls, which a transition cannot run yet."),
                QCoreApplication::translate("iec::interp::Compiler", "write the condition as an ST expression"));
            return std::nullopt;
        }
        case model::BodyLanguage::LD:
        case model::BodyLanguage::FBD: {
            if (name.isEmpty()) {
                error(localId, QCoreApplication::translate("iec::interp::Compiler", "A graphical transition condition needs a name: its network assigns that name."));
                return std::nullopt;
            }
            graphical::LoweringContext context {m_result, owner, m_diagnostics};
            for (ast::Stmt &s : graphical::lowerBody(body, context))
                pre.push_back(std::move(s));
            return conditionVariable(name);
        }
        case model::BodyLanguage::SFC:
            break;
        }
        error(localId, QCoreApplication::translate("iec::interp::Compiler", "A transition condition cannot be an SFC chart."));
        return std::nullopt;
    }

    std::optional<ast::Expr> condition(const ChartTransition &t, std::vector<ast::Stmt> &pre)
    {
        const model::Condition &c = *t.condition;
        const QString owner = m_pou.name;
        std::optional<ast::Expr> expr;
        if (const auto *reference = std::get_if<model::Reference>(&c.kind)) {
            if (const model::PouTransition *named = m_pouTransitions.value(key(reference->name))) {
                expr = bodyCondition(named->body, m_pou.name + QLatin1Char('.') + named->name, named->name, t.localId, pre);
            } else if (declared(reference->name)) {
                expr = graphical::nameExpr(reference->name, {});
            } else {
                error(t.localId, QCoreApplication::translate("iec::interp::Compiler", "The transition refers to %1, which is neither a transition of %2 nor a variable.").arg(reference->name, m_pou.name));
            }
        } else if (const auto *inl = std::get_if<model::InlineCondition>(&c.kind)) {
            expr = bodyCondition(*inl->body, owner, inl->name, t.localId, pre, t.localId);
        } else if (const auto *wire = std::get_if<model::ConnectionPointIn>(&c.kind)) {
            expr = wiredCondition(t, *wire, pre);
        }
        if (expr && c.negated)
            expr = notExpr(std::move(*expr));
        return expr;
    }

    // CODESYS wires an inVariable holding an expression to the condition; other networks go to
    // the graphical lowering.
    std::optional<ast::Expr> wiredCondition(const ChartTransition &t, const model::ConnectionPointIn &wire,
        std::vector<ast::Stmt> &pre)
    {
        if (wire.expression)
            return stConditionExpr(*wire.expression, t.localId);
        if (wire.connections.size() == 1 && t.scope && t.scope->elements()) {
            for (const model::Element &e : *t.scope->elements()) {
                const auto *in = std::get_if<model::InVariable>(&e);
                if (in && in->localId == wire.connections.front().refLocalId) {
                    auto expr = stConditionExpr(in->expression, in->localId);
                    if (expr && in->negated)
                        expr = notExpr(std::move(*expr));
                    return expr;
                }
            }
        }
        if (wire.connections.empty()) {
            error(t.localId, QCoreApplication::translate("iec::interp::Compiler", "The condition of this transition is not connected."));
            return std::nullopt;
        }
        // Blocks in the network (function block calls, edge detectors) run before the condition
        // is read, every cycle, like a network of the chart's body.
        std::unique_ptr<graphical::InputLowering> &inputs = m_wiredInputs[t.scope];
        if (!inputs)
            inputs = std::make_unique<graphical::InputLowering>(*t.scope, m_pou.name, m_diagnostics);
        graphical::LoweringContext context {m_result, m_pou.name, m_diagnostics, &pre};
        auto expr = inputs->lower(wire, context);
        if (!expr)
            m_failed = true;
        return expr;
    }

    std::optional<ast::Expr> stConditionExpr(const QString &text, quint64 localId)
    {
        Diagnostics local;
        auto statements = parseStBody(QString(QStringLiteral("__sfc_cond := ") + text + QStringLiteral(";")), m_pou.name, local);
        if (local.hasErrors() || statements.size() != 1) {
            error(localId, QCoreApplication::translate("iec::interp::Compiler", "The condition %1 is not an expression: %2").arg(text, local.all().empty() ? QString() : local.all().front().message));
            return std::nullopt;
        }
        graphical::relocate(statements, at(localId)); // point at the chart element
        return std::move(statements.front().value);
    }

    // ---- the cycle ----------------------------------------------------------------------------

    void generate()
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

    // Located generated code goes through a splice so each element keeps its localId.
    // `isPlace` false: the code keeps localId for its diagnostics but is no place for the
    // debugger (a breakpoint on the element does not halt there, nor does a step).
    QString located(const QString &text, quint64 localId, bool isPlace = true)
    {
        if (text.isEmpty())
            return {};
        std::vector<ast::Stmt> statements = code(text, localId);
        if (!isPlace)
            graphical::setPlace(statements, SourceLocation::kNoPlace);
        return spliceText(std::move(statements));
    }

    QString stepReset(bool activateInitial)
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

    QString preamble()
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

    // _x becomes x; a step that was left (or left and re-entered by one transition) runs its exit
    // action, one that was entered its entry action.
    QString copyPhase()
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

    QString exitPhase() { return stepActionPhase(&model::StepOptions::exitAction, "ex"); }
    QString entryPhase() { return stepActionPhase(&model::StepOptions::entryAction, "en"); }

    // The steps' exit or entry actions (CoDeSys), each guarded by its step's hidden flag `flag`.
    QString stepActionPhase(QString model::StepOptions::*action, const char *flag)
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

    // what: a QT_TRANSLATE_NOOP text in the context iec::interp::Compiler.
    bool checkDuration(const QString &duration, quint64 localId, const char *what)
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

    // Step times, maximum time (SFCError) and the active action of each step, in chart order.
    QString stepPhase()
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

    // ACTION_CONTROL of each action (IEC 61131-3), then the bodies: the actions that became
    // inactive this cycle run a last time first, then the active ones, both alphabetically.
    QString actionPhase()
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

    std::vector<const ChartAssociation *> associationsOf(int j) const
    {
        std::vector<const ChartAssociation *> result;
        for (const ChartAssociation &a : m_chart.associations) {
            if (key(a.action) == key(m_actions[j]))
                result.push_back(&a);
        }
        return result;
    }

    // Inline TON: q := IN for at least PT.
    static QString timer(const QString &in, const QString &mem, const QString &start, const QString &pt, const QString &q)
    {
        return QStringLiteral("IF %1 THEN\nIF NOT %2 THEN %2 := TRUE; %3 := __sfc_now; END_IF;\n%5 := __sfc_now - %3 >= %4;\n"
                              "ELSE %2 := FALSE; %5 := FALSE; END_IF;\n")
            .arg(in, mem, start, pt, q);
    }

    QString actionControl(int j)
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

    QString runAction(int j)
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

    QString transitionPhase()
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

    QString epilogue()
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

public:
    // An action the chart only calls by name: it is compiled as an action of the POU elsewhere.
    void compiledApart(const QString &name) { m_calledActions.insert(key(name)); }

private:
    const model::Pou &m_pou;
    ast::Pou &m_result;
    Diagnostics &m_diagnostics;
    Chart m_chart;
    QStringList m_actions;
    QHash<QString, QString> m_declared; // upper-case name -> upper-case type name (empty: not a named type)
    QHash<QString, const model::PouAction *> m_pouActions;
    QHash<QString, const model::PouTransition *> m_pouTransitions;
    QSet<QString> m_implicitActionFlags;
    QString m_extraDeclarations;
    QStringList m_conditionVariables;
    std::vector<std::vector<ast::Stmt>> m_splices;
    // The wired conditions' networks, built once per body that holds wired transitions.
    std::map<const model::Body *, std::unique_ptr<graphical::InputLowering>> m_wiredInputs;
    const std::vector<ast::SfcAction> *m_parsed = nullptr;
    QString m_hiddenPrefix;
    std::vector<ast::Stmt> *m_output;
    QSet<QString> m_calledActions; // keys of the actions already in m_result.actions
    bool m_failed = false;
};

} // namespace

void lowerChart(const model::Pou &pou, ast::Pou &result, Diagnostics &diagnostics,
    const std::vector<ast::SfcAction> *parsedActions)
{
    if (pou.kind == model::PouKind::Function) {
        diagnostics.error(pou.name, {},
            QCoreApplication::translate("iec::interp::Compiler", "%1 is a function written in SFC; a chart keeps its state, so it must be a program or a function block.").arg(pou.name));
        return;
    }
    Lowering(pou, result, diagnostics, parsedActions).run();
}

bool lowerActionChart(const model::Pou &pou, const model::PouAction &action, ast::Pou &result, std::vector<ast::Stmt> &out,
    Diagnostics &diagnostics, const std::vector<ast::SfcAction> *parsedActions)
{
    Lowering outer(pou, result, diagnostics, parsedActions);
    for (const model::PouAction &a : pou.actions) // each is compiled as an action of the POU already
        outer.compiledApart(a.name);
    return outer.lowerNestedChart(action, out);
}

void lowerTextualCharts(ast::CompilationUnit &unit, Diagnostics &diagnostics)
{
    for (ast::Pou &pou : unit.pous) {
        if (pou.body.language != ast::Language::SFC || !pou.body.sfc)
            continue;
        const std::shared_ptr<ast::SfcChart> chart = pou.body.sfc;
        model::Pou chartPou;
        chartPou.name = pou.name;
        chartPou.kind = pou.kind == ast::PouKind::Function ? model::PouKind::Function
            : pou.kind == ast::PouKind::FunctionBlock     ? model::PouKind::FunctionBlock
                                                          : model::PouKind::Program;
        chartPou.bodies.push_back(chartToModel(*chart, pou.name, diagnostics));
        for (const ast::SfcAction &action : chart->actions) {
            model::PouAction placeholder; // the parsed body stands in for it
            placeholder.name = action.name;
            chartPou.actions.push_back(std::move(placeholder));
        }
        pou.body = {};
        pou.body.language = ast::Language::ST;
        lowerChart(chartPou, pou, diagnostics, &chart->actions);
    }
    // Charts in the actions of POUs written in ST or IL.
    for (ast::Pou &pou : unit.pous) {
        for (ast::SfcAction &action : pou.actions) {
            if (action.body.language != ast::Language::SFC || !action.body.sfc)
                continue;
            model::Pou chartPou;
            chartPou.name = pou.name;
            chartPou.kind = pou.kind == ast::PouKind::FunctionBlock ? model::PouKind::FunctionBlock : model::PouKind::Program;
            for (const ast::SfcAction &other : pou.actions) {
                model::PouAction placeholder; // the parsed bodies stand in for them
                placeholder.name = other.name;
                if (&other == &action)
                    placeholder.body = chartToModel(*action.body.sfc, pou.name, diagnostics);
                chartPou.actions.push_back(std::move(placeholder));
            }
            const model::PouAction chartAction = chartPou.actions[size_t(&action - pou.actions.data())];
            const std::vector<ast::SfcAction> others = pou.actions;
            ast::Body lowered;
            lowered.language = ast::Language::ST;
            lowerActionChart(chartPou, chartAction, pou, lowered.statements, diagnostics, &others);
            action.body = std::move(lowered);
        }
    }
}

} // namespace iec::interp::sfc
