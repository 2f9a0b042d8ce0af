#pragma once

// The SFC lowering's working state (sfclowering.h is its interface): one object per chart,
// its declarations and user bodies in sfclowering.cpp, the code of the cycle's phases in
// sfcloweringphases.cpp.
#include "interpreter/compiler/ast.h"
#include "interpreter/compiler/diagnostics.h"
#include "interpreter/graphical/astbuild.h"
#include "interpreter/graphical/graphicallowering.h"
#include "interpreter/sfc/sfcgraph.h"

#include "model/pou.h"

#include <QHash>
#include <QSet>
#include <QString>
#include <QStringList>

#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace iec::interp::sfc::detail {

// The placeholder __SFC_SPLICE(n) stands in generated text for user statements parsed apart.
inline constexpr const char *kSplice = "__SFC_SPLICE";

inline QString key(const QString &name)
{
    return name.toUpper();
}

class Lowering
{
public:
    // `hiddenPrefix` starts the names of the hidden variables ("__sfc_"; a chart in action A has
    // "__sfc_A_", however deep it is lowered, so that it runs beside the POU's chart and the online
    // view finds it, sfcstatus.h). The statements go to `output`, by default the POU's body.
    Lowering(const model::Pou &pou, ast::Pou &result, Diagnostics &diagnostics, const std::vector<ast::SfcAction> *parsed,
        QString hiddenPrefix = QStringLiteral("__sfc_"), std::vector<ast::Stmt> *output = nullptr)
        : m_pou(pou), m_result(result), m_diagnostics(diagnostics), m_parsed(parsed), m_hiddenPrefix(std::move(hiddenPrefix)),
          m_output(output ? output : &result.body.statements)
    {
    }

    void run();

private:
    // ---- helpers ------------------------------------------------------------------------------

    static constexpr quint64 kNoElement = ~quint64(0);

    SourceLocation at(quint64 localId) const { return graphical::elementLocation(localId); } // kNoElement: none

    void error(quint64 localId, const QString &message, const QString &hint = {});

    bool declared(const QString &name) const { return m_declared.contains(key(name)); }
    bool hasFlag(const char *name) const { return declared(QLatin1String(name)); }

    // Generated ST, located on `localId`. `{Name}` placeholders are not used: callers build text.
    // The generated text with this chart's own names for its hidden variables.
    QString named(QString text) const;

    std::vector<ast::Stmt> code(const QString &text, quint64 localId = kNoElement);

    int splice(std::vector<ast::Stmt> statements);

    QString spliceText(std::vector<ast::Stmt> statements);

    void expandSplices(std::vector<ast::Stmt> &statements);

    // ---- declarations -------------------------------------------------------------------------

    void collectDeclaredNames();

    // CODESYS V3 declares the flags its SFC settings mark with Declare="true".
    void declareCodesysFlags();

    // An implicit variable the chart declares unless the POU already has it with the right type.
    void implicit(QString &text, const QString &name, const QString &type, quint64 localId);

    void declare();

    void declareAction(QString &text, int j);

    // ---- user bodies --------------------------------------------------------------------------

    // IL cannot be inlined into the chart's ST; such an action is compiled as an action of the
    // POU (Main.Act) and the chart calls it: Act();
    bool isCalledAction(const QString &name) const;

    std::vector<ast::Stmt> callAction(const QString &name, ast::Body body, quint64 localId);

    // The statements of a POU action (entry/exit/active action or IEC action).
    std::optional<std::vector<ast::Stmt>> actionBody(const model::Body &body, const QString &owner, quint64 localId);

public:
    // An action of the POU whose body is a chart: its statements into `out`, its variables and the
    // actions it calls into the POU.
    bool lowerNestedChart(const model::PouAction &action, std::vector<ast::Stmt> &out);

private:

    // A POU action by name (entry/exit/active actions of a step).
    QString stepActionText(const QString &name, const ChartStep &step);

    // An ST condition: an expression, or statements that assign the transition's name. An inline
    // condition (`inlineOn`: its transition) is reported on the transition, at the place counted
    // in its text; a named transition's on the lines of its own body.
    std::optional<ast::Expr> stCondition(const QString &text, const QString &owner, const QString &resultName,
        std::vector<ast::Stmt> &pre, std::optional<quint64> inlineOn = {});

    // Passes on what parsing a condition's `text` found (see stCondition).
    void reportCondition(const Diagnostics &local, const QString &owner, std::optional<quint64> inlineOn, const QString &text,
        bool errorsOnly);

    ast::Expr conditionVariable(const QString &name);

    // `inlineOn`: the transition whose inline body this is (see stCondition).
    std::optional<ast::Expr> bodyCondition(const model::Body &body, const QString &owner, const QString &name,
        quint64 localId, std::vector<ast::Stmt> &pre, std::optional<quint64> inlineOn = {});

    std::optional<ast::Expr> condition(const ChartTransition &t, std::vector<ast::Stmt> &pre);

    // CODESYS wires an inVariable holding an expression to the condition; other networks go to
    // the graphical lowering.
    std::optional<ast::Expr> wiredCondition(const ChartTransition &t, const model::ConnectionPointIn &wire,
        std::vector<ast::Stmt> &pre);

    std::optional<ast::Expr> stConditionExpr(const QString &text, quint64 localId);

    // ---- the cycle ----------------------------------------------------------------------------

    void generate();

    // Located generated code goes through a splice so each element keeps its localId.
    // `isPlace` false: the code keeps localId for its diagnostics but is no place for the
    // debugger (a breakpoint on the element does not halt there, nor does a step).
    QString located(const QString &text, quint64 localId, bool isPlace = true);

    QString stepReset(bool activateInitial);

    QString preamble();

    // _x becomes x; a step that was left (or left and re-entered by one transition) runs its exit
    // action, one that was entered its entry action.
    QString copyPhase();

    QString exitPhase() { return stepActionPhase(&model::StepOptions::exitAction, "ex"); }
    QString entryPhase() { return stepActionPhase(&model::StepOptions::entryAction, "en"); }

    // The steps' exit or entry actions (CoDeSys), each guarded by its step's hidden flag `flag`.
    QString stepActionPhase(QString model::StepOptions::*action, const char *flag);

    // what: a QT_TRANSLATE_NOOP text in the context iec::interp::Compiler.
    bool checkDuration(const QString &duration, quint64 localId, const char *what);

    // Step times, maximum time (SFCError) and the active action of each step, in chart order.
    QString stepPhase();

    // ACTION_CONTROL of each action (IEC 61131-3), then the bodies: the actions that became
    // inactive this cycle run a last time first, then the active ones, both alphabetically.
    QString actionPhase();

    std::vector<const ChartAssociation *> associationsOf(int j) const;

    // Inline TON: q := IN for at least PT.
    static QString timer(const QString &in, const QString &mem, const QString &start, const QString &pt, const QString &q);

    QString actionControl(int j);

    QString runAction(int j);

    QString transitionPhase();

    QString epilogue();

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
    // The action charts being lowered around this one (keys): a chart that runs itself is refused.
    QStringList m_chartChain;
    std::vector<ast::Stmt> *m_output;
    QSet<QString> m_calledActions; // keys of the actions already in m_result.actions
    bool m_failed = false;
};

} // namespace iec::interp::sfc::detail
