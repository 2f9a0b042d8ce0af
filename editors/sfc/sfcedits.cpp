#include "editors/sfc/sfcedits.h"

#include "interpreter/compiler/lexer.h"
#include "model/body.h"

#include <QCoreApplication>
#include <QStringList>

#include <algorithm>
#include <unordered_map>
#include <unordered_set>

namespace iec::editors::sfc {

using namespace model;

namespace {

// One level of the path to a node: where it sits (see NodePlace).
using Level = NodePlace;
using Path = std::vector<Level>;

bool pathIn(Sequence &seq, Node *parent, bool isMain, quint64 id, Path &path)
{
    for (std::size_t i = 0; i < seq.size(); ++i) {
        Node &node = seq[i];
        path.push_back({&seq, i, parent, isMain});
        if ((node.localId == id && !node.wired) || (node.convergenceId != 0 && node.convergenceId == id))
            return true;
        for (Sequence &branch : node.branches)
            if (pathIn(branch, &node, false, id, path))
                return true;
        path.pop_back();
    }
    return false;
}

Path pathTo(Chart &chart, quint64 id)
{
    Path path;
    if (pathIn(chart.main, nullptr, true, id, path))
        return path;
    for (Sequence &chain : chart.loose)
        if (pathIn(chain, nullptr, false, id, path))
            return path;
    return {};
}

// A range of consecutive nodes of one chain.
struct Range {
    Level level; // sequence, parent, isMain; index unused
    std::size_t first = 0;
    std::size_t last = 0;
    Path parentPath; // the path to the sequence's parent node (for unwrapping a block)
};

// The action blocks are selectable too; they stand for their step.
quint64 ownerOf(const ChartDocument &document, quint64 id)
{
    if (const Element *e = document.element(id); e && std::holds_alternative<ActionBlock>(*e)) {
        const auto &block = std::get<ActionBlock>(*e);
        if (block.connectionPointIn && !block.connectionPointIn->connections.empty())
            return block.connectionPointIn->connections.front().refLocalId;
    }
    return id;
}

std::optional<Range> rangeOf(ChartDocument &document, const std::vector<quint64> &selection)
{
    std::vector<Path> paths;
    for (quint64 id : selection) {
        Path path = pathTo(document.chart, ownerOf(document, id));
        if (!path.empty())
            paths.push_back(std::move(path));
    }
    if (paths.empty())
        return std::nullopt;
    // The deepest level every path goes through: the same chain, and the same node above it.
    const Path &front = paths.front();
    if (!std::ranges::all_of(paths, [&](const Path &p) { return p[0].sequence == front[0].sequence; }))
        return std::nullopt; // in different chains
    std::size_t depth = 0;
    while (true) {
        const bool ends = std::ranges::any_of(paths, [&](const Path &p) { return p.size() == depth + 1; });
        const bool sameNode = std::ranges::all_of(paths, [&](const Path &p) { return p[depth].index == front[depth].index; });
        if (ends || !sameNode)
            break;
        const bool sameBranch = std::ranges::all_of(paths, [&](const Path &p) { return p[depth + 1].sequence == front[depth + 1].sequence; });
        if (!sameBranch)
            break;
        ++depth;
    }
    ++depth;
    const std::size_t level = depth - 1;
    Range range;
    range.level = paths.front()[level];
    range.first = range.last = range.level.index;
    for (const Path &p : paths) {
        range.first = std::min(range.first, p[level].index);
        range.last = std::max(range.last, p[level].index);
    }
    range.parentPath.assign(paths.front().begin(), paths.front().begin() + std::ptrdiff_t(level));
    return range;
}

enum class Context { Main, Loose, SelectionBranch, ParallelBranch };

Context contextOf(const Level &level)
{
    if (!level.parent)
        return level.isMain ? Context::Main : Context::Loose;
    return level.parent->kind == NodeKind::Selection ? Context::SelectionBranch : Context::ParallelBranch;
}

bool validSequence(const Sequence &seq, Context context)
{
    if (seq.empty())
        return context == Context::Main || context == Context::Loose;
    for (std::size_t i = 0; i < seq.size(); ++i) {
        const Role role = roleOf(seq[i].kind);
        if (role == Role::Jump && i + 1 != seq.size())
            return false;
        if (i > 0) {
            const Role before = roleOf(seq[i - 1].kind);
            const Role effective = role == Role::Jump ? Role::StepLike : role;
            if (before == Role::Jump || before == effective)
                return false;
        }
    }
    const Role first = roleOf(seq.front().kind);
    const Role last = roleOf(seq.back().kind);
    switch (context) {
    case Context::Main:
        return first == Role::StepLike;
    case Context::Loose:
        return true;
    case Context::SelectionBranch:
        return first == Role::TransitionLike && last != Role::StepLike;
    case Context::ParallelBranch:
        return first == Role::StepLike && last == Role::StepLike;
    }
    return true;
}

Node newStep(ChartDocument &document, const QString &name)
{
    Step step;
    step.name = name;
    return {NodeKind::Step, document.add(step)};
}

Node newTransition(ChartDocument &document, const QString &condition = QStringLiteral("TRUE"))
{
    Transition transition;
    Body body = Body::withLanguage(BodyLanguage::ST);
    body.setText(condition);
    transition.condition = Condition {false, InlineCondition {QString(), body}};
    return {NodeKind::Transition, document.add(transition)};
}

Node newJump(ChartDocument &document, const QString &target)
{
    JumpStep jump;
    jump.targetName = target;
    return {NodeKind::Jump, document.add(jump)};
}

Node newMacroStep(ChartDocument &document, const QString &name)
{
    MacroStep macro;
    macro.name = name;
    Body inner = Body::withLanguage(BodyLanguage::SFC);
    Step first;
    first.localId = 1;
    first.name = name + QStringLiteral("_1");
    inner.elements()->push_back(first);
    macro.body = inner;
    return {NodeKind::MacroStep, document.add(macro)};
}

std::vector<quint64> allIds(const ChartDocument &document, const Sequence &nodes)
{
    std::vector<quint64> ids;
    for (const Node &node : nodes) {
        const std::vector<quint64> more = elementsOf(document, node);
        ids.insert(ids.end(), more.begin(), more.end());
    }
    return ids;
}

EditResult refuse(const char *text)
{
    return {QCoreApplication::translate("iec::editors::sfc::SfcEdits", text), {}};
}

EditResult insertPair(ChartDocument &document, const std::vector<quint64> &selection, bool after, bool macro)
{
    if (document.chart.main.empty() && document.chart.loose.empty())
        return createDefaultChart(document);
    std::optional<Range> range = rangeOf(document, selection);
    if (!range)
        return refuse(QT_TRANSLATE_NOOP("iec::editors::sfc::SfcEdits", "Select a step or a transition first."));
    Sequence &seq = *range->level.sequence;
    const std::size_t anchorIndex = after ? range->last : range->first;
    const Role anchor = roleOf(seq[anchorIndex].kind);
    if (after && anchor == Role::Jump)
        return refuse(QT_TRANSLATE_NOOP("iec::editors::sfc::SfcEdits", "Nothing can follow a jump. Select the transition before it."));
    if (!after && range->level.isMain && anchorIndex == 0)
        return refuse(QT_TRANSLATE_NOOP("iec::editors::sfc::SfcEdits", "Nothing can go before the initial step. Insert after it instead."));
    const bool stepFirst = after ? anchor == Role::TransitionLike : anchor != Role::TransitionLike;
    const QString name = uniqueStepName(document);
    Node step = macro ? newMacroStep(document, name) : newStep(document, name);
    Node transition = newTransition(document);
    Sequence pair = stepFirst ? Sequence {step, transition} : Sequence {transition, step};
    const std::size_t at = after ? anchorIndex + 1 : anchorIndex;
    seq.insert(seq.begin() + std::ptrdiff_t(at), pair.begin(), pair.end());
    return {{}, {step.localId}};
}

EditResult insertBranch(ChartDocument &document, const std::vector<quint64> &selection, bool right, bool parallel)
{
    std::optional<Range> range = rangeOf(document, selection);
    if (!range)
        return refuse(QT_TRANSLATE_NOOP("iec::editors::sfc::SfcEdits", "Select a step or a transition first."));
    Sequence &seq = *range->level.sequence;
    const Role wanted = parallel ? Role::StepLike : Role::TransitionLike;
    const NodeKind blockKind = parallel ? NodeKind::Parallel : NodeKind::Selection;
    const Role first = roleOf(seq[range->first].kind);
    Role last = roleOf(seq[range->last].kind);
    if (!parallel && last == Role::Jump)
        last = Role::TransitionLike;
    if (first != wanted || last != wanted) {
        return parallel ? refuse(QT_TRANSLATE_NOOP("iec::editors::sfc::SfcEdits", "Select a step (or steps from one to another) to add a parallel branch."))
                        : refuse(QT_TRANSLATE_NOOP("iec::editors::sfc::SfcEdits", "Select a transition (or a range from a transition to a transition) to add an "
                                 "alternative branch."));
    }
    Node fresh = parallel ? newStep(document, uniqueStepName(document)) : newTransition(document);
    if (range->first == range->last && seq[range->first].kind == blockKind) {
        auto &branches = seq[range->first].branches;
        branches.insert(right ? branches.end() : branches.begin(), Sequence {fresh});
        return {{}, {fresh.localId}};
    }
    Node block;
    block.kind = blockKind;
    block.localId = parallel ? document.add(SimultaneousDivergence {}) : document.add(SelectionDivergence {});
    Sequence taken(seq.begin() + std::ptrdiff_t(range->first), seq.begin() + std::ptrdiff_t(range->last) + 1);
    block.branches = right ? std::vector<Sequence> {taken, Sequence {fresh}} : std::vector<Sequence> {Sequence {fresh}, taken};
    seq.erase(seq.begin() + std::ptrdiff_t(range->first), seq.begin() + std::ptrdiff_t(range->last) + 1);
    seq.insert(seq.begin() + std::ptrdiff_t(range->first), block);
    return {{}, {fresh.localId}};
}

bool isStepName(const ChartDocument &document, const QString &name)
{
    return document.stepNamed(name).has_value();
}

} // namespace

QStringList stepNames(const ChartDocument &document)
{
    QStringList names;
    for (const Element &e : document.elements) {
        if (const auto *step = std::get_if<Step>(&e))
            names << step->name;
        else if (const auto *macro = std::get_if<MacroStep>(&e); macro && macro->name)
            names << *macro->name;
    }
    return names;
}

QString uniqueStepName(const ChartDocument &document, const QString &base)
{
    for (int n = 1;; ++n) {
        const QString name = base + QString::number(n);
        if (!isStepName(document, name))
            return name;
    }
}

EditResult createDefaultChart(ChartDocument &document)
{
    if (!document.chart.isEmpty())
        return refuse(QT_TRANSLATE_NOOP("iec::editors::sfc::SfcEdits", "The chart is not empty."));
    Step init;
    init.name = isStepName(document, QStringLiteral("Init")) ? uniqueStepName(document, QStringLiteral("Init"))
                                                              : QStringLiteral("Init");
    init.initialStep = true;
    Node step {NodeKind::Step, document.add(init)};
    Node transition = newTransition(document);
    Node jump = newJump(document, init.name);
    document.chart.main = {step, transition, jump};
    return {{}, {step.localId}};
}

EditResult insertStepTransition(ChartDocument &document, const std::vector<quint64> &selection, bool after)
{
    return insertPair(document, selection, after, false);
}

EditResult insertMacroStep(ChartDocument &document, const std::vector<quint64> &selection, bool after)
{
    return insertPair(document, selection, after, true);
}

EditResult insertAlternativeBranch(ChartDocument &document, const std::vector<quint64> &selection, bool right)
{
    return insertBranch(document, selection, right, false);
}

EditResult insertParallelBranch(ChartDocument &document, const std::vector<quint64> &selection, bool right)
{
    return insertBranch(document, selection, right, true);
}

EditResult insertJump(ChartDocument &document, const std::vector<quint64> &selection, const QString &target)
{
    if (!isStepName(document, target))
        return {QCoreApplication::translate("iec::editors::sfc::SfcEdits", "There is no step '%1' to jump to.").arg(target), {}};
    std::optional<Range> range = rangeOf(document, selection);
    if (!range)
        return refuse(QT_TRANSLATE_NOOP("iec::editors::sfc::SfcEdits", "Select the transition the jump follows."));
    Sequence &seq = *range->level.sequence;
    Node &anchor = seq[range->last];
    if (roleOf(anchor.kind) == Role::Jump) { // retarget
        if (auto *jump = std::get_if<JumpStep>(document.element(anchor.localId)))
            jump->targetName = target;
        return {{}, {anchor.localId}};
    }
    if (roleOf(anchor.kind) != Role::TransitionLike || range->last + 1 != seq.size())
        return refuse(QT_TRANSLATE_NOOP("iec::editors::sfc::SfcEdits", "A jump can only follow the last transition of a chain or branch."));
    Node jump = newJump(document, target);
    seq.push_back(jump);
    return {{}, {jump.localId}};
}

EditResult insertTransitionJump(ChartDocument &document, const std::vector<quint64> &selection, const QString &target)
{
    if (!isStepName(document, target))
        return {QCoreApplication::translate("iec::editors::sfc::SfcEdits", "There is no step '%1' to jump to.").arg(target), {}};
    std::optional<Range> range = rangeOf(document, selection);
    if (!range)
        return refuse(QT_TRANSLATE_NOOP("iec::editors::sfc::SfcEdits", "Select the step the transition and jump follow."));
    Sequence &seq = *range->level.sequence;
    if (roleOf(seq[range->last].kind) != Role::StepLike || range->last + 1 != seq.size()
        || contextOf(range->level) == Context::ParallelBranch)
        return refuse(QT_TRANSLATE_NOOP("iec::editors::sfc::SfcEdits", "A transition-jump can only follow the last step of a chain or of an alternative branch."));
    Node transition = newTransition(document);
    Node jump = newJump(document, target);
    seq.push_back(transition);
    seq.push_back(jump);
    return {{}, {transition.localId}};
}

EditResult deleteSelection(ChartDocument &document, const std::vector<quint64> &selection)
{
    std::optional<Range> range = rangeOf(document, selection);
    if (!range)
        return refuse(QT_TRANSLATE_NOOP("iec::editors::sfc::SfcEdits", "Select what to delete first."));
    Sequence &seq = *range->level.sequence;
    const Context context = contextOf(range->level);
    // A whole branch: the block loses it; a block left with one branch dissolves into its chain.
    if (range->first == 0 && range->last + 1 == seq.size() && range->level.parent) {
        Node &parent = *range->level.parent;
        const auto branch = std::ranges::find_if(parent.branches, [&](const Sequence &b) { return &b == &seq; });
        document.remove(allIds(document, seq));
        parent.branches.erase(branch);
        if (parent.branches.size() > 1)
            return {{}, {parent.localId}};
        Level holder = range->parentPath.back();
        Sequence &outer = *holder.sequence;
        Sequence remaining = parent.branches.empty() ? Sequence {} : parent.branches.front();
        document.remove({parent.localId, parent.convergenceId});
        outer.erase(outer.begin() + std::ptrdiff_t(holder.index));
        outer.insert(outer.begin() + std::ptrdiff_t(holder.index), remaining.begin(), remaining.end());
        return {{}, remaining.empty() ? std::vector<quint64> {} : std::vector<quint64> {remaining.front().localId}};
    }
    if (range->level.isMain && range->first == 0 && range->last + 1 != seq.size())
        return refuse(QT_TRANSLATE_NOOP("iec::editors::sfc::SfcEdits", "The initial step cannot be deleted on its own. Delete what follows it, or the whole chart."));
    // A step goes with the transition after it (or before it), so steps and transitions still alternate.
    const std::vector<std::pair<std::size_t, std::size_t>> candidates {{range->first, range->last},
        {range->first, range->last + 1}, {range->first == 0 ? range->first : range->first - 1, range->last}};
    for (auto [first, last] : candidates) {
        if (last >= seq.size())
            continue;
        if (range->level.isMain && first == 0 && last + 1 != seq.size())
            continue;
        // Never take an unselected jump along: the chain would lose its loop.
        if ((last > range->last && seq[last].kind == NodeKind::Jump) || (first < range->first && seq[first].kind == NodeKind::Jump))
            continue;
        Sequence trial = seq;
        trial.erase(trial.begin() + std::ptrdiff_t(first), trial.begin() + std::ptrdiff_t(last) + 1);
        if (!validSequence(trial, context))
            continue;
        const Sequence removed(seq.begin() + std::ptrdiff_t(first), seq.begin() + std::ptrdiff_t(last) + 1);
        document.remove(allIds(document, removed));
        seq = std::move(trial);
        std::vector<quint64> select;
        if (!seq.empty())
            select.push_back(seq[std::min(first, seq.size() - 1)].localId);
        return {{}, select};
    }
    return refuse(QT_TRANSLATE_NOOP("iec::editors::sfc::SfcEdits", "Deleting this would leave two steps or two transitions in a row. Select a step together with "
                  "its transition."));
}

std::optional<StepProperties> stepProperties(const ChartDocument &document, quint64 stepId)
{
    const Element *e = document.element(stepId);
    if (const auto *step = e ? std::get_if<Step>(e) : nullptr) {
        return StepProperties {step->name, step->initialStep, model::stepOptions(*step),
            step->documentation ? step->documentation->text : QString()};
    }
    if (const auto *macro = e ? std::get_if<MacroStep>(e) : nullptr)
        return StepProperties {macro->name.value_or(QString()), false, {}, macro->documentation ? macro->documentation->text : QString()};
    return std::nullopt;
}

QStringList stepActionNames(const model::StepOptions &options)
{
    QStringList names;
    for (const QString &name : {options.entryAction, options.exitAction, options.activeAction}) {
        if (!name.trimmed().isEmpty())
            names << name.trimmed();
    }
    return names;
}

EditResult setStepProperties(ChartDocument &document, quint64 stepId, const StepProperties &properties)
{
    const std::optional<StepProperties> before = stepProperties(document, stepId);
    if (!before)
        return refuse(QT_TRANSLATE_NOOP("iec::editors::sfc::SfcEdits", "Select a step first."));
    const QString name = properties.name.trimmed();
    if (!interp::isIecIdentifier(name))
        return {QCoreApplication::translate("iec::editors::sfc::SfcEdits", "'%1' is not a valid step name: use letters, digits and single underscores, starting with a "
                   "letter.").arg(name), {}};
    if (name.compare(before->name, Qt::CaseInsensitive) != 0 && isStepName(document, name))
        return {QCoreApplication::translate("iec::editors::sfc::SfcEdits", "There is already a step named '%1'.").arg(name), {}};
    for (const QString &action : stepActionNames(properties.options)) {
        if (!interp::isIecIdentifier(action))
            return {QCoreApplication::translate("iec::editors::sfc::SfcEdits", "'%1' is not a valid action name: use letters, digits and single underscores, starting with a "
                       "letter.").arg(action), {}};
    }
    if (properties.initial != before->initial) {
        std::optional<NodePlace> place = findNode(document.chart, stepId);
        const bool first = place && place->sequence->front().localId == stepId && !place->parent;
        if (!first || (place->isMain && !properties.initial))
            return refuse(QT_TRANSLATE_NOOP("iec::editors::sfc::SfcEdits", "Only the first step of the chart is the initial step."));
    }
    Element *e = document.element(stepId);
    if (properties.options.simplified && document.actionBlockOf(stepId) != 0)
        return refuse(QT_TRANSLATE_NOOP("iec::editors::sfc::SfcEdits", "This step has IEC actions. Remove them before making it a simplified step."));
    auto documentation = properties.comment.isEmpty() ? std::optional<FormattedText> {}
                                                      : std::optional<FormattedText> {FormattedText {properties.comment, {}}};
    if (auto *step = std::get_if<Step>(e)) {
        step->name = name;
        step->initialStep = properties.initial;
        model::setStepOptions(*step, properties.options);
        step->documentation = documentation;
    } else if (auto *macro = std::get_if<MacroStep>(e)) {
        macro->name = name;
        macro->documentation = documentation;
    }
    if (name != before->name) {
        for (Element &other : document.elements) {
            if (auto *jump = std::get_if<JumpStep>(&other); jump && jump->targetName.compare(before->name, Qt::CaseInsensitive) == 0)
                jump->targetName = name;
        }
    }
    return {{}, {stepId}};
}

std::vector<ActionBlockAction> stepActions(const ChartDocument &document, quint64 stepId)
{
    const quint64 blockId = document.actionBlockOf(stepId);
    const Element *e = blockId ? document.element(blockId) : nullptr;
    const auto *block = e ? std::get_if<ActionBlock>(e) : nullptr;
    return block ? block->actions : std::vector<ActionBlockAction> {};
}

ActionBlockAction actionAssociation(const QString &qualifier, const QString &name, const QString &duration, const QString &indicator)
{
    ActionBlockAction action;
    if (!qualifier.isEmpty())
        action.qualifier = qualifier;
    action.reference = Reference {name};
    if (!duration.isEmpty())
        action.duration = duration;
    if (!indicator.isEmpty())
        action.indicator = indicator;
    return action;
}

namespace {

const QStringList &qualifiers()
{
    static const QStringList list {QStringLiteral("N"), QStringLiteral("R"), QStringLiteral("S"), QStringLiteral("L"),
        QStringLiteral("D"), QStringLiteral("P"), QStringLiteral("SD"), QStringLiteral("DS"), QStringLiteral("SL"),
        QStringLiteral("P0"), QStringLiteral("P1")};
    return list;
}

std::optional<QString> checkAction(const ActionBlockAction &action)
{
    const QString qualifier = action.qualifier.value_or(QStringLiteral("N"));
    if (!qualifiers().contains(qualifier))
        return QCoreApplication::translate("iec::editors::sfc::SfcEdits", "'%1' is not an action qualifier.").arg(qualifier);
    const bool timed = qualifier == QLatin1String("L") || qualifier == QLatin1String("D") || qualifier == QLatin1String("SD")
        || qualifier == QLatin1String("DS") || qualifier == QLatin1String("SL");
    if (timed && (!action.duration || action.duration->trimmed().isEmpty()))
        return QCoreApplication::translate("iec::editors::sfc::SfcEdits", "The qualifier %1 needs a time, such as T#5s.").arg(qualifier);
    if (action.reference && !interp::hasIdentifierShape(action.reference->name.section(QLatin1Char('.'), -1)))
        return QCoreApplication::translate("iec::editors::sfc::SfcEdits", "'%1' is not an action or variable name.").arg(action.reference->name);
    return std::nullopt;
}

ActionBlock *blockOf(ChartDocument &document, quint64 stepId)
{
    const quint64 id = document.actionBlockOf(stepId);
    return id ? std::get_if<ActionBlock>(document.element(id)) : nullptr;
}

bool isStep(const ChartDocument &document, quint64 id)
{
    const Element *e = document.element(id);
    return e && (std::holds_alternative<Step>(*e) || std::holds_alternative<MacroStep>(*e));
}

} // namespace

EditResult addAction(ChartDocument &document, quint64 stepId, ActionBlockAction action, int index)
{
    if (!isStep(document, stepId))
        return refuse(QT_TRANSLATE_NOOP("iec::editors::sfc::SfcEdits", "Select a step first."));
    if (const auto *step = std::get_if<Step>(document.element(stepId)); step && model::stepOptions(*step).simplified)
        return refuse(QT_TRANSLATE_NOOP("iec::editors::sfc::SfcEdits", "A simplified step has no IEC actions. Make it an IEC step in its properties first."));
    if (auto problem = checkAction(action))
        return {*problem, {}};
    ActionBlock *block = blockOf(document, stepId);
    if (!block) {
        ActionBlock fresh;
        fresh.connectionPointIn = ConnectionPointIn {};
        Connection wire;
        wire.refLocalId = stepId;
        fresh.connectionPointIn->connections.push_back(wire);
        const quint64 id = document.add(fresh);
        block = std::get_if<ActionBlock>(document.element(id));
    }
    auto &actions = block->actions;
    const std::size_t at = index < 0 || std::size_t(index) > actions.size() ? actions.size() : std::size_t(index);
    actions.insert(actions.begin() + std::ptrdiff_t(at), std::move(action));
    return {{}, {stepId}};
}

EditResult changeAction(ChartDocument &document, quint64 stepId, int index, ActionBlockAction action)
{
    ActionBlock *block = blockOf(document, stepId);
    if (!block || index < 0 || std::size_t(index) >= block->actions.size())
        return refuse(QT_TRANSLATE_NOOP("iec::editors::sfc::SfcEdits", "The step has no such action."));
    if (auto problem = checkAction(action))
        return {*problem, {}};
    action.relPosition = block->actions[std::size_t(index)].relPosition;
    block->actions[std::size_t(index)] = std::move(action);
    return {{}, {stepId}};
}

EditResult removeAction(ChartDocument &document, quint64 stepId, int index)
{
    ActionBlock *block = blockOf(document, stepId);
    if (!block || index < 0 || std::size_t(index) >= block->actions.size())
        return refuse(QT_TRANSLATE_NOOP("iec::editors::sfc::SfcEdits", "The step has no such action."));
    block->actions.erase(block->actions.begin() + index);
    if (block->actions.empty())
        document.remove({block->localId});
    return {{}, {stepId}};
}

EditResult moveAction(ChartDocument &document, quint64 stepId, int from, int to)
{
    ActionBlock *block = blockOf(document, stepId);
    const int count = block ? int(block->actions.size()) : 0;
    if (from < 0 || from >= count || to < 0 || to >= count)
        return refuse(QT_TRANSLATE_NOOP("iec::editors::sfc::SfcEdits", "The action cannot move there."));
    ActionBlockAction moved = block->actions[std::size_t(from)];
    block->actions.erase(block->actions.begin() + from);
    block->actions.insert(block->actions.begin() + to, std::move(moved));
    return {{}, {stepId}};
}

EditResult setInlineCondition(ChartDocument &document, quint64 transitionId, const QString &stText)
{
    auto *transition = std::get_if<Transition>(document.element(transitionId));
    if (!transition)
        return refuse(QT_TRANSLATE_NOOP("iec::editors::sfc::SfcEdits", "Select a transition first."));
    const QString text = stText.trimmed();
    if (text.isEmpty())
        return refuse(QT_TRANSLATE_NOOP("iec::editors::sfc::SfcEdits", "A transition needs a condition, such as TRUE or Level > 50."));
    Body body = Body::withLanguage(BodyLanguage::ST);
    body.setText(text);
    transition->condition = Condition {false, InlineCondition {QString(), body}};
    return {{}, {transitionId}};
}

EditResult setConditionReference(ChartDocument &document, quint64 transitionId, const QString &transitionName)
{
    auto *transition = std::get_if<Transition>(document.element(transitionId));
    if (!transition)
        return refuse(QT_TRANSLATE_NOOP("iec::editors::sfc::SfcEdits", "Select a transition first."));
    if (!interp::isIecIdentifier(transitionName))
        return {QCoreApplication::translate("iec::editors::sfc::SfcEdits", "'%1' is not a valid transition name.").arg(transitionName), {}};
    transition->condition = Condition {false, Reference {transitionName}};
    return {{}, {transitionId}};
}

EditResult setPriority(ChartDocument &document, quint64 transitionId, std::optional<quint64> priority)
{
    auto *transition = std::get_if<Transition>(document.element(transitionId));
    if (!transition)
        return refuse(QT_TRANSLATE_NOOP("iec::editors::sfc::SfcEdits", "Select a transition first."));
    transition->priority = priority;
    return {{}, {transitionId}};
}

std::optional<Fragment> copyFragment(ChartDocument &document, const std::vector<quint64> &selection, QString *error)
{
    std::optional<Range> range = rangeOf(document, selection);
    if (!range) {
        if (error)
            *error = QCoreApplication::translate("iec::editors::sfc::SfcEdits", "Select steps and transitions of one chain to copy.");
        return std::nullopt;
    }
    Fragment fragment;
    Sequence &seq = *range->level.sequence;
    fragment.nodes.assign(seq.begin() + std::ptrdiff_t(range->first), seq.begin() + std::ptrdiff_t(range->last) + 1);
    std::vector<quint64> ids = allIds(document, fragment.nodes);
    // A transition's wired condition is copied with it, so the copy gets a network of its own.
    const std::size_t chainIds = ids.size();
    for (std::size_t i = 0; i < chainIds; ++i) {
        const std::vector<quint64> network = conditionNetwork(document, ids[i]);
        ids.insert(ids.end(), network.begin(), network.end());
    }
    for (quint64 id : ids) {
        if (const Element *e = document.element(id))
            fragment.elements.push_back(*e);
    }
    return fragment;
}

std::optional<Fragment> fragmentFromElements(std::vector<Element> elements, QString *error)
{
    // A copied range has no initial step: it is read as the chain that starts without an input
    // (a step: the main chain; a transition: the one loose chain).
    const Chart chart = parseChart(elements);
    const std::size_t chains = (chart.main.empty() ? 0 : 1) + chart.loose.size();
    if (chains != 1) {
        if (error)
            *error = QCoreApplication::translate("iec::editors::sfc::SfcEdits",
                "The copied elements are not one chain of steps and transitions: nothing was pasted.");
        return std::nullopt;
    }
    Fragment fragment;
    fragment.nodes = chart.main.empty() ? chart.loose.front() : chart.main;
    fragment.elements = std::move(elements);
    return fragment;
}

namespace {

void remapNodes(Sequence &nodes, const std::unordered_map<quint64, quint64> &ids)
{
    for (Node &node : nodes) {
        if (!node.wired && ids.contains(node.localId))
            node.localId = ids.at(node.localId);
        if (node.convergenceId && ids.contains(node.convergenceId))
            node.convergenceId = ids.at(node.convergenceId);
        for (Sequence &branch : node.branches)
            remapNodes(branch, ids);
    }
}

} // namespace

EditResult pasteFragment(ChartDocument &document, const std::vector<quint64> &selection, const Fragment &fragment)
{
    if (fragment.isEmpty())
        return refuse(QT_TRANSLATE_NOOP("iec::editors::sfc::SfcEdits", "There is nothing to paste."));
    std::optional<Range> range = rangeOf(document, selection);
    if (!range)
        return refuse(QT_TRANSLATE_NOOP("iec::editors::sfc::SfcEdits", "Select where to paste first."));
    Sequence &seq = *range->level.sequence;
    // Pasting must keep the alternation, as if the fragment were typed after the selection.
    Sequence trial = seq;
    trial.insert(trial.begin() + std::ptrdiff_t(range->last) + 1, fragment.nodes.begin(), fragment.nodes.end());
    if (!validSequence(trial, contextOf(range->level)))
        return refuse(QT_TRANSLATE_NOOP("iec::editors::sfc::SfcEdits", "The copied part does not fit here: after a step paste a part that starts with a transition, "
                      "after a transition one that starts with a step."));
    std::unordered_map<quint64, quint64> ids;
    std::unordered_map<QString, QString> names;
    std::vector<Element> added;
    quint64 next = document.allocateId();
    for (const Element &e : fragment.elements)
        ids[header(e).localId] = next++;
    for (Element e : fragment.elements) {
        header(e).localId = ids.at(header(e).localId);
        for (ConnectionPointIn *point : inputPoints(e)) {
            for (Connection &c : point->connections) {
                if (ids.contains(c.refLocalId))
                    c.refLocalId = ids.at(c.refLocalId);
            }
        }
        if (auto *step = std::get_if<Step>(&e)) {
            step->initialStep = false;
            if (isStepName(document, step->name) || std::ranges::any_of(added, [&](const Element &a) {
                    const auto *s = std::get_if<Step>(&a);
                    return s && s->name == step->name;
                })) {
                const QString fresh = uniqueStepName(document, step->name + QStringLiteral("_"));
                names[step->name] = fresh;
                step->name = fresh;
            }
        }
        added.push_back(std::move(e));
    }
    for (Element &e : added) {
        if (auto *jump = std::get_if<JumpStep>(&e); jump && names.contains(jump->targetName))
            jump->targetName = names.at(jump->targetName);
        document.elements.push_back(std::move(e));
    }
    Sequence nodes = fragment.nodes;
    remapNodes(nodes, ids);
    seq.insert(seq.begin() + std::ptrdiff_t(range->last) + 1, nodes.begin(), nodes.end());
    return {{}, {nodes.front().localId}};
}

std::vector<quint64> connectedRange(ChartDocument &document, quint64 anchor, quint64 clicked)
{
    std::optional<Range> range = rangeOf(document, {anchor, clicked});
    if (!range)
        return {clicked};
    Sequence &seq = *range->level.sequence;
    return allIds(document, Sequence(seq.begin() + std::ptrdiff_t(range->first), seq.begin() + std::ptrdiff_t(range->last) + 1));
}

} // namespace iec::editors::sfc
