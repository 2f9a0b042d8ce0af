#include "app/online/watchpane.h"

#include "interpreter/runtime/symbols.h"
#include "interpreter/vm/bytecode.h"

#include <QAction>
#include <QBrush>
#include <QCompleter>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLineEdit>
#include <QStringListModel>
#include <QToolBar>
#include <QToolButton>
#include <QTreeView>
#include <QVBoxLayout>

namespace iec::app {

namespace {

constexpr int kMaxDepth = 4;

void collectNames(const QString &prefix, const interp::Type *type, int depth, int limit, QStringList &names)
{
    if (names.size() >= limit)
        return;
    names.append(prefix);
    if (!type || depth >= kMaxDepth)
        return;
    if (type->kind == interp::TypeKind::Struct || type->kind == interp::TypeKind::FunctionBlock) {
        for (const interp::Member &member : type->members) {
            // Compiler-made helpers (SFC step flags keep their IEC names) start with an underscore.
            if (member.name.startsWith(QLatin1Char('_')))
                continue;
            collectNames(prefix + QLatin1Char('.') + member.name, member.type, depth + 1, limit, names);
        }
    }
}

QString watchTypeName(const interp::Type *type)
{
    return type ? type->name : QString();
}

} // namespace

QStringList watchableNames(const interp::Module &module, int limit)
{
    QStringList names;
    for (const interp::Symbol &symbol : module.symbols)
        collectNames(symbol.name, symbol.type, 0, limit, names);
    for (const interp::LocatedVar &located : module.located) {
        if (names.size() < limit)
            names.append(located.address);
    }
    names.removeDuplicates();
    names.sort(Qt::CaseInsensitive);
    return names;
}

// ---- WatchModel -------------------------------------------------------------------------------

WatchModel::WatchModel(QObject *parent)
    : QAbstractTableModel(parent)
{
}

bool WatchModel::addName(const QString &name, const QString &type)
{
    const QString trimmed = name.trimmed();
    if (trimmed.isEmpty() || rowOf(trimmed) >= 0)
        return false;
    beginInsertRows({}, int(m_rows.size()), int(m_rows.size()));
    m_rows.append({.name = trimmed, .type = type});
    endInsertRows();
    Q_EMIT namesChanged();
    return true;
}

void WatchModel::removeName(const QString &name)
{
    const int row = rowOf(name);
    if (row < 0)
        return;
    beginRemoveRows({}, row, row);
    m_rows.removeAt(row);
    endRemoveRows();
    Q_EMIT namesChanged();
}

QStringList WatchModel::names() const
{
    QStringList names;
    for (const Row &row : m_rows)
        names.append(row.name);
    return names;
}

int WatchModel::rowOf(const QString &name) const
{
    for (int row = 0; row < m_rows.size(); ++row) {
        if (m_rows[row].name.compare(name.trimmed(), Qt::CaseInsensitive) == 0)
            return row;
    }
    return -1;
}

void WatchModel::setPrepared(int row, const QString &literal)
{
    setData(index(row, PreparedColumn), literal, Qt::EditRole);
}

void WatchModel::setType(int row, const QString &type)
{
    m_rows[row].type = type;
    Q_EMIT dataChanged(index(row, TypeColumn), index(row, TypeColumn));
}

void WatchModel::setSnapshot(const interp::RuntimeSnapshot *snapshot)
{
    m_online = snapshot != nullptr;
    const std::optional<int> historyCycle = snapshot ? snapshot->historyCycle : std::nullopt;
    if (historyCycle != m_historyCycle) {
        m_historyCycle = historyCycle;
        Q_EMIT headerDataChanged(Qt::Horizontal, ValueColumn, ValueColumn);
        if (!m_rows.isEmpty())
            Q_EMIT dataChanged(index(0, ValueColumn), index(int(m_rows.size()) - 1, ValueColumn));
    }
    int first = -1;
    int last = -1;
    for (int row = 0; row < m_rows.size(); ++row) {
        Row &entry = m_rows[row];
        QString value;
        bool known = false;
        if (snapshot) {
            const auto found = snapshot->values.constFind(entry.name);
            known = found != snapshot->values.constEnd();
            if (known)
                value = *found;
        }
        const bool forced = snapshot && snapshot->isForced(entry.name);
        if (value == entry.value && forced == entry.forced && known == entry.known)
            continue;
        entry.value = value;
        entry.forced = forced;
        entry.known = known || !snapshot;
        first = first < 0 ? row : first;
        last = row;
    }
    // One signal for the changed range keeps 200 rows at 20 Hz cheap.
    if (first >= 0)
        Q_EMIT dataChanged(index(first, NameColumn), index(last, ValueColumn));
}

int WatchModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_rows.size());
}

int WatchModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant WatchModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= m_rows.size())
        return {};
    const Row &row = m_rows[index.row()];
    if (role == Qt::DisplayRole || role == Qt::EditRole) {
        switch (index.column()) {
        case NameColumn:
            return row.name;
        case TypeColumn:
            return row.type;
        case ValueColumn:
            if (!row.known)
                return tr("(no such variable)");
            return row.forced && role == Qt::DisplayRole ? tr("%1 (forced)").arg(row.value) : row.value;
        case PreparedColumn:
            return row.prepared;
        }
    }
    // Values of an earlier scan (going back in time) sit on amber, as the history bar does.
    if (role == Qt::BackgroundRole && index.column() == ValueColumn && m_historyCycle)
        return QBrush(QColor(0xff, 0xec, 0xb3));
    if (role == Qt::ForegroundRole && index.column() == ValueColumn) {
        if (row.forced)
            return QBrush(QColor(0xc0, 0x10, 0x10));
        if (!row.known)
            return QBrush(Qt::gray);
    }
    if (role == Qt::ToolTipRole && index.column() == PreparedColumn)
        return tr("Type the value to write or force, then choose Write or Force.");
    return {};
}

bool WatchModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    if (!index.isValid() || index.column() != PreparedColumn || role != Qt::EditRole)
        return false;
    m_rows[index.row()].prepared = value.toString().trimmed();
    Q_EMIT dataChanged(index, index);
    return true;
}

Qt::ItemFlags WatchModel::flags(const QModelIndex &index) const
{
    Qt::ItemFlags flags = QAbstractTableModel::flags(index);
    if (index.column() == PreparedColumn)
        flags |= Qt::ItemIsEditable;
    return flags;
}

QVariant WatchModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case NameColumn:
        return tr("Expression");
    case TypeColumn:
        return tr("Type");
    case ValueColumn:
        return m_historyCycle ? tr("Value after scan %1 (history)").arg(*m_historyCycle) : tr("Value");
    case PreparedColumn:
        return tr("Prepared value");
    }
    return {};
}

// ---- WatchPane --------------------------------------------------------------------------------

WatchPane::WatchPane(QWidget *parent)
    : QWidget(parent)
    , m_model(new WatchModel(this))
{
    m_nameEdit = new QLineEdit(this);
    m_nameEdit->setObjectName(QStringLiteral("watchNameEdit"));
    m_nameEdit->setClearButtonEnabled(true);
    m_completionModel = new QStringListModel(this);
    m_completer = new QCompleter(m_completionModel, this);
    m_completer->setCaseSensitivity(Qt::CaseInsensitive);
    m_completer->setFilterMode(Qt::MatchStartsWith);
    m_completer->setModelSorting(QCompleter::CaseInsensitivelySortedModel);
    m_completer->setMaxVisibleItems(14);
    m_nameEdit->setCompleter(m_completer);
    connect(m_nameEdit, &QLineEdit::returnPressed, this, &WatchPane::addFromLine);
    m_addButton = new QToolButton(this);
    connect(m_addButton, &QToolButton::clicked, this, &WatchPane::addFromLine);

    m_view = new QTreeView(this);
    m_view->setObjectName(QStringLiteral("watchView"));
    m_view->setModel(m_model);
    m_view->setRootIsDecorated(false);
    m_view->setUniformRowHeights(true); // 200 rows repaint at 20 Hz
    m_view->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_view->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed
                            | QAbstractItemView::AnyKeyPressed);
    m_view->header()->setStretchLastSection(true);
    m_view->setColumnWidth(WatchModel::NameColumn, 200);
    m_view->setColumnWidth(WatchModel::TypeColumn, 70);
    m_view->setColumnWidth(WatchModel::ValueColumn, 140);
    // A double-click on the value of a BOOL prepares its opposite, as in CODESYS.
    connect(m_view, &QTreeView::doubleClicked, this, [this](const QModelIndex &index) {
        if (index.column() != WatchModel::ValueColumn)
            return;
        const QString value = m_model->value(index.row());
        if (value == QLatin1String("TRUE") || value == QLatin1String("FALSE"))
            m_model->setPrepared(index.row(), value == QLatin1String("TRUE") ? QStringLiteral("FALSE") : QStringLiteral("TRUE"));
    });

    auto *tools = new QToolBar(this);
    tools->setIconSize(QSize(16, 16));
    tools->setToolButtonStyle(Qt::ToolButtonTextOnly);
    const auto addAction = [this, tools](const QKeySequence &keys, auto slot) {
        auto *action = new QAction(this);
        action->setShortcut(keys);
        // Window-wide, as in CODESYS: a value prepared from an editor (a double-click on a
        // contact) is written with Ctrl+F7 while the editor keeps the focus.
        action->setShortcutContext(Qt::WindowShortcut);
        connect(action, &QAction::triggered, this, slot);
        tools->addAction(action);
        return action;
    };
    m_writeAction = addAction(QKeySequence(Qt::CTRL | Qt::Key_F7), &WatchPane::writePrepared);
    m_forceAction = addAction(QKeySequence(Qt::Key_F7), &WatchPane::forcePrepared);
    m_releaseAction = addAction(QKeySequence(Qt::ALT | Qt::Key_F7), &WatchPane::releaseSelected);
    m_releaseAllAction = addAction(QKeySequence(), [this] { Q_EMIT releaseAllRequested(); });
    m_removeAction = addAction(QKeySequence::Delete, &WatchPane::removeSelected);
    for (QAction *action : {m_writeAction, m_forceAction, m_releaseAction, m_releaseAllAction})
        QWidget::addAction(action);
    // Delete removes rows only from the list, not while typing a name or a value.
    m_removeAction->setShortcutContext(Qt::WidgetShortcut);
    m_view->addAction(m_removeAction);

    auto *line = new QHBoxLayout;
    line->setContentsMargins(0, 0, 0, 0);
    line->addWidget(m_nameEdit, 1);
    line->addWidget(m_addButton);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->setSpacing(2);
    layout->addLayout(line);
    layout->addWidget(tools);
    layout->addWidget(m_view, 1);

    connect(m_model, &WatchModel::namesChanged, this, &WatchPane::namesChanged);
    retranslate();
}

void WatchPane::retranslate()
{
    m_nameEdit->setPlaceholderText(tr("Variable to watch, e.g. Main.Counter"));
    m_addButton->setText(tr("Add"));
    m_writeAction->setText(tr("Write"));
    m_writeAction->setToolTip(tr("Write the prepared values once, at the start of the next cycle (Ctrl+F7)"));
    m_forceAction->setText(tr("Force"));
    m_forceAction->setToolTip(tr("Hold the prepared values every cycle until released (F7)"));
    m_releaseAction->setText(tr("Release"));
    m_releaseAction->setToolTip(tr("Release the forces of the selected variables (Alt+F7)"));
    m_releaseAllAction->setText(tr("Release All"));
    m_removeAction->setText(tr("Remove"));
}

void WatchPane::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void WatchPane::setModule(std::shared_ptr<const interp::Module> module)
{
    m_module = std::move(module);
    m_completionModel->setStringList(m_module ? watchableNames(*m_module) : QStringList());
    if (!m_module)
        return;
    const QStringList names = m_model->names();
    for (int row = 0; row < names.size(); ++row) {
        const std::optional<interp::VariableRef> ref = interp::resolveSymbol(*m_module, names[row]);
        m_model->setType(row, ref ? watchTypeName(ref->type) : QString());
    }
}

bool WatchPane::addVariable(const QString &name)
{
    QString type;
    if (m_module) {
        if (const std::optional<interp::VariableRef> ref = interp::resolveSymbol(*m_module, name.trimmed()))
            type = watchTypeName(ref->type);
    }
    return m_model->addName(name, type);
}

void WatchPane::prepareValue(const QString &name, const QString &literal)
{
    addVariable(name);
    const int row = m_model->rowOf(name);
    if (row >= 0)
        m_model->setPrepared(row, literal);
}

void WatchPane::addFromLine()
{
    if (addVariable(m_nameEdit->text()))
        m_nameEdit->clear();
}

void WatchPane::setSnapshot(const interp::RuntimeSnapshot *snapshot)
{
    m_model->setSnapshot(snapshot);
}

QList<int> WatchPane::selectedRows() const
{
    QList<int> rows;
    for (const QModelIndex &index : m_view->selectionModel()->selectedRows())
        rows.append(index.row());
    std::sort(rows.begin(), rows.end());
    return rows;
}

void WatchPane::writePrepared()
{
    sendPrepared(&WatchPane::writeRequested);
}

void WatchPane::forcePrepared()
{
    sendPrepared(&WatchPane::forceRequested);
}

// Hands every prepared value to `request` (write or force) and clears it.
void WatchPane::sendPrepared(void (WatchPane::*request)(const QString &, const QString &))
{
    const QStringList names = m_model->names();
    for (int row = 0; row < m_model->rowCount(); ++row) {
        const QString literal = m_model->prepared(row);
        if (literal.isEmpty())
            continue;
        Q_EMIT(this->*request)(names.at(row), literal);
        m_model->setPrepared(row, {});
    }
}

void WatchPane::releaseSelected()
{
    QList<int> rows = selectedRows();
    if (rows.isEmpty()) {
        for (int row = 0; row < m_model->rowCount(); ++row)
            rows.append(row);
    }
    const QStringList names = m_model->names();
    for (int row : std::as_const(rows)) {
        if (m_model->isForced(row))
            Q_EMIT releaseRequested(names.at(row));
    }
}

void WatchPane::removeSelected()
{
    const QStringList names = m_model->names();
    const QList<int> rows = selectedRows();
    for (int row : rows)
        m_model->removeName(names.at(row));
}

} // namespace iec::app
