// SFC charts become statements and variables of their POU (docs/sfc.md has the cycle order and
// every rule). The chart's own code is generated as ST text per element and parsed, so it reads
// like what a student would write; the user's bodies (actions, conditions) are parsed on their
// own, with their own diagnostics, and spliced in where the placeholder __SFC_SPLICE(n) stands.
#include "interpreter/sfc/sfclowering.h"

#include "interpreter/compiler/limits.h"
#include "interpreter/compiler/parser.h"
#include "interpreter/sfc/sfcloweringclass.h"
#include "interpreter/sfc/sfcnames.h"
#include "interpreter/sfc/sfctext.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include <algorithm>
#include <limits>

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

} // namespace

namespace detail {

void Lowering::run()
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

void Lowering::error(quint64 localId, const QString &message, const QString &hint)
{
    m_diagnostics.error(m_pou.name, at(localId), message, hint);
    m_failed = true;
}

QString Lowering::named(QString text) const
{
    if (m_hiddenPrefix != QLatin1String("__sfc_"))
        text.replace(QLatin1String("__sfc_"), m_hiddenPrefix);
    return text;
}

std::vector<ast::Stmt> Lowering::code(const QString &text, quint64 localId)
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

int Lowering::splice(std::vector<ast::Stmt> statements)
{
    m_splices.push_back(std::move(statements));
    return int(m_splices.size()) - 1;
}

QString Lowering::spliceText(std::vector<ast::Stmt> statements)
{
    if (statements.empty())
        return {};
    return QStringLiteral("%1(%2);\n").arg(QLatin1String(kSplice)).arg(splice(std::move(statements)));
}

void Lowering::expandSplices(std::vector<ast::Stmt> &statements)
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

void Lowering::collectDeclaredNames()
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

void Lowering::declareCodesysFlags()
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

void Lowering::implicit(QString &text, const QString &name, const QString &type, quint64 localId)
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

void Lowering::declare()
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

void Lowering::declareAction(QString &text, int j)
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

bool Lowering::isCalledAction(const QString &name) const
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

std::vector<ast::Stmt> Lowering::callAction(const QString &name, ast::Body body, quint64 localId)
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

std::optional<std::vector<ast::Stmt>> Lowering::actionBody(const model::Body &body, const QString &owner, quint64 localId)
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
        if (!action || owner == m_pou.name || m_chartChain.contains(key(name))) {
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

bool Lowering::lowerNestedChart(const model::PouAction &action, std::vector<ast::Stmt> &out)
{
    model::Pou chartPou = m_pou;
    chartPou.bodies.clear();
    chartPou.bodies.push_back(action.body);
    if (m_chartChain.contains(key(action.name))) {
        error(kNoElement, QCoreApplication::translate("iec::interp::Compiler", "%1 is an SFC chart that contains itself.").arg(m_pou.name + QLatin1Char('.') + action.name));
        return false;
    }
    // Each action chart is lowered once per POU (m_calledActions), so its action's name alone
    // keeps its hidden variables apart; the online view reads them by the same rule.
    Lowering nested(chartPou, m_result, m_diagnostics, m_parsed, hiddenPrefix(action.name), &out);
    nested.m_chartChain = m_chartChain;
    nested.m_chartChain << key(action.name);
    nested.m_calledActions = m_calledActions;
    nested.run();
    m_calledActions.unite(nested.m_calledActions);
    return !nested.m_failed;
}

QString Lowering::stepActionText(const QString &name, const ChartStep &step)
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

std::optional<ast::Expr> Lowering::stCondition(const QString &text, const QString &owner, const QString &resultName,
    std::vector<ast::Stmt> &pre, std::optional<quint64> inlineOn)
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

void Lowering::reportCondition(const Diagnostics &local, const QString &owner, std::optional<quint64> inlineOn, const QString &text,
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

ast::Expr Lowering::conditionVariable(const QString &name)
{
    if (!declared(name)) {
        m_declared.insert(key(name), QStringLiteral("BOOL"));
        m_conditionVariables << name;
    }
    return graphical::nameExpr(name, {});
}

std::optional<ast::Expr> Lowering::bodyCondition(const model::Body &body, const QString &owner, const QString &name,
    quint64 localId, std::vector<ast::Stmt> &pre, std::optional<quint64> inlineOn)
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

std::optional<ast::Expr> Lowering::condition(const ChartTransition &t, std::vector<ast::Stmt> &pre)
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

std::optional<ast::Expr> Lowering::wiredCondition(const ChartTransition &t, const model::ConnectionPointIn &wire,
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

std::optional<ast::Expr> Lowering::stConditionExpr(const QString &text, quint64 localId)
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

} // namespace detail

using detail::Lowering;


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
