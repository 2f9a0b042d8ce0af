#include "editors/declarations/declarationeditor.h"

#include "editors/declarations/declarationtablemodel.h"
#include "editors/text/codeeditor.h"
#include "model/projectmodel.h"
#include "model/undo/variablecommands.h"

#include <QAction>
#include <QComboBox>
#include <QHeaderView>
#include <QKeyEvent>
#include <QLabel>
#include <QStyledItemDelegate>
#include <QTabWidget>
#include <QTableView>
#include <QToolBar>
#include <QUndoStack>
#include <QVBoxLayout>

namespace iec::editors {

namespace {

// The class cell offers the section keywords with their qualifiers; other text may be typed.
class ClassDelegate : public QStyledItemDelegate
{
public:
    using QStyledItemDelegate::QStyledItemDelegate;

    QWidget *createEditor(QWidget *parent, const QStyleOptionViewItem &, const QModelIndex &) const override
    {
        auto *combo = new QComboBox(parent);
        combo->setEditable(true);
        combo->addItems(declarationClasses());
        return combo;
    }
    void setEditorData(QWidget *editor, const QModelIndex &index) const override
    {
        static_cast<QComboBox *>(editor)->setCurrentText(index.data(Qt::EditRole).toString());
    }
    void setModelData(QWidget *editor, QAbstractItemModel *model, const QModelIndex &index) const override
    {
        model->setData(index, static_cast<QComboBox *>(editor)->currentText());
    }
};

QList<TextDiagnostic> textDiagnostics(const std::vector<DeclarationProblem> &problems)
{
    QList<TextDiagnostic> diagnostics;
    for (const DeclarationProblem &problem : problems)
        diagnostics.append({problem.line, problem.column, 0, TextDiagnostic::Severity::Error, problem.message});
    return diagnostics;
}

} // namespace

DeclarationEditor::DeclarationEditor(
    model::ProjectModel &projectModel, model::PouId pou, QUndoStack &undoStack, QWidget *parent)
    : QWidget(parent)
    , m_projectModel(projectModel)
    , m_pou(pou)
    , m_undoStack(&undoStack)
    , m_views(new QTabWidget(this))
    , m_tableModel(new DeclarationTableModel(this))
    , m_text(new CodeEditor(TextLanguage::ST))
    , m_problem(new QLabel(this))
{
    setObjectName(QStringLiteral("declarationEditor"));
    m_views->setDocumentMode(true);
    m_views->setTabPosition(QTabWidget::South);
    m_views->addTab(createTablePage(), QString());
    m_views->addTab(m_text, QString());
    retranslate();
    m_text->setObjectName(QStringLiteral("declarationText"));
    m_text->installEventFilter(this);
    m_problem->setObjectName(QStringLiteral("declarationProblem"));
    m_problem->setWordWrap(true);
    m_problem->setStyleSheet(QStringLiteral("color: #b00000;"));
    m_problem->hide();

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addWidget(m_views);
    layout->addWidget(m_problem);

    connect(m_tableModel, &DeclarationTableModel::rowsEdited, this, &DeclarationEditor::applyRows);
    connect(m_text, &CodeEditor::textEdited, this, &DeclarationEditor::applyText);
    connect(&projectModel, &model::ProjectModel::variablesChanged, this, [this](model::PouId changed) {
        if (changed == m_pou)
            refreshFromModel();
    });
    connect(&projectModel, &model::ProjectModel::projectReset, this, &DeclarationEditor::refreshFromModel);
    refreshFromModel();
}

QWidget *DeclarationEditor::createTablePage()
{
    auto *page = new QWidget;
    auto *tools = new QToolBar(page);
    tools->setToolButtonStyle(Qt::ToolButtonTextOnly);
    m_addAction = tools->addAction(QString(), this, &DeclarationEditor::addRow);
    m_removeAction = tools->addAction(QString(), this, &DeclarationEditor::removeCurrentRow);
    m_moveUpAction = tools->addAction(QString(), this, [this] { moveCurrentRow(-1); });
    m_moveDownAction = tools->addAction(QString(), this, [this] { moveCurrentRow(1); });

    m_table = new QTableView(page);
    m_table->setObjectName(QStringLiteral("declarationTable"));
    m_table->setModel(m_tableModel);
    m_table->setItemDelegateForColumn(int(DeclarationColumn::Class), new ClassDelegate(m_table));
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setEditTriggers(
        QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed | QAbstractItemView::AnyKeyPressed);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 6);
    m_table->installEventFilter(this);

    auto *layout = new QVBoxLayout(page);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addWidget(tools);
    layout->addWidget(m_table);
    return page;
}

void DeclarationEditor::retranslate()
{
    m_views->setTabText(0, tr("Table"));
    m_views->setTabText(1, tr("Text"));
    m_addAction->setText(tr("Add Variable"));
    m_removeAction->setText(tr("Remove"));
    m_moveUpAction->setText(tr("Move Up"));
    m_moveDownAction->setText(tr("Move Down"));
    Q_EMIT m_tableModel->headerDataChanged(Qt::Horizontal, 0, kDeclarationColumnCount - 1);
}

void DeclarationEditor::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

QString DeclarationEditor::problemText() const
{
    return m_problem->text();
}

void DeclarationEditor::showTable()
{
    m_views->setCurrentIndex(0);
}

void DeclarationEditor::showText()
{
    m_views->setCurrentIndex(1);
}

model::Interface DeclarationEditor::currentInterface() const
{
    const model::Pou *pou = m_projectModel.project().findPou(m_pou);
    return pou && pou->pouInterface ? *pou->pouInterface : model::Interface {};
}

void DeclarationEditor::refreshFromModel()
{
    const model::Interface declarations = currentInterface();
    const std::vector<DeclarationRow> rows = rowsFromInterface(declarations);
    if (rows != m_tableModel->rows() || !m_tableModel->problems().empty()) {
        m_tableModel->setRows(rows);
        m_tableModel->setProblems({});
    }
    // Text that already says what the model holds stays as typed (its cursor, its layout).
    const DeclarationTextResult shown = readDeclarationText(m_text->toPlainText(), declarations);
    if (shown.declarations != declarations)
        m_text->setBodyText(declarationText(declarations));
    showProblem({});
    m_text->setDiagnostics({});
    if (!m_columnsFitted) { // once: later widths are the user's
        fitColumns();
        m_columnsFitted = true;
    }
}

void DeclarationEditor::fitColumns()
{
    m_table->resizeColumnsToContents();
    // Room for what is typed next, and for headers that another language makes longer.
    const QFontMetrics metrics = m_table->fontMetrics();
    const int roomy = metrics.horizontalAdvance(QStringLiteral("VAR_OUTPUT RETAIN")) + 12;
    for (int column = 0; column < kDeclarationColumnCount - 1; ++column)
        m_table->setColumnWidth(column, std::max(m_table->columnWidth(column), roomy * 3 / 4));
    m_table->setColumnWidth(
        int(DeclarationColumn::Class), std::max(m_table->columnWidth(int(DeclarationColumn::Class)), roomy));
}

void DeclarationEditor::applyRows(const std::vector<DeclarationRow> &rows)
{
    m_tableModel->setRows(rows);
    const RowsResult result = interfaceFromRows(rows, currentInterface());
    m_tableModel->setProblems(result.problems);
    if (!result.declarations) {
        showProblem(tr("Row %1: %2").arg(result.problems.front().row + 1).arg(result.problems.front().message));
        return;
    }
    showProblem({});
    apply(*result.declarations);
}

void DeclarationEditor::applyText()
{
    const DeclarationTextResult result = readDeclarationText(m_text->toPlainText(), currentInterface());
    m_text->setDiagnostics(textDiagnostics(result.problems));
    if (!result.declarations) {
        const DeclarationProblem &first = result.problems.front();
        showProblem(tr("Line %1, column %2: %3").arg(first.line).arg(first.column).arg(first.message));
        return;
    }
    showProblem({});
    apply(*result.declarations);
}

void DeclarationEditor::apply(const model::Interface &declarations)
{
    const model::Pou *pou = m_projectModel.project().findPou(m_pou);
    if (!m_undoStack || !pou || pou->pouInterface.value_or(model::Interface {}) == declarations)
        return;
    // SetInterfaceCommand merges with the next one of the same POU; a parent of its own keeps
    // every gesture a separate step of the undo history.
    auto *gesture = new QUndoCommand;
    auto *command = new model::SetInterfaceCommand(m_projectModel, m_pou, declarations, gesture);
    gesture->setText(command->text());
    // A renamed variable takes its uses along, in the same undo step (as CODESYS users expect).
    const std::vector<model::VariableRename> renames = model::renamedVariables(pou->pouInterface, declarations);
    if (!renames.empty() && m_renameReferences) {
        m_renameReferences(m_pou, renames, gesture);
        gesture->setText(renames.size() == 1
                ? tr("Rename variable %1 to %2").arg(renames.front().oldName, renames.front().newName)
                : tr("Rename %n variable(s)", nullptr, int(renames.size())));
    }
    m_undoStack->push(gesture);
}

void DeclarationEditor::showProblem(const QString &message)
{
    m_problem->setText(message);
    m_problem->setVisible(!message.isEmpty());
}

int DeclarationEditor::currentRow() const
{
    const QModelIndex current = m_table->currentIndex();
    return current.isValid() ? current.row() : -1;
}

void DeclarationEditor::selectRow(int row)
{
    if (row >= 0 && row < m_tableModel->rowCount())
        m_table->setCurrentIndex(m_tableModel->index(row, int(DeclarationColumn::Name)));
}

bool DeclarationEditor::showVariable(const QString &name)
{
    const std::vector<DeclarationRow> &rows = m_tableModel->rows();
    for (size_t row = 0; row < rows.size(); ++row) {
        if (rows[row].name.compare(name, Qt::CaseInsensitive) != 0)
            continue;
        showTable();
        selectRow(int(row));
        m_table->scrollTo(m_table->currentIndex());
        m_table->setFocus(Qt::OtherFocusReason);
        return true;
    }
    return false;
}

void DeclarationEditor::addRow()
{
    std::vector<DeclarationRow> rows = m_tableModel->rows();
    const int current = currentRow();
    const int at = current < 0 ? int(rows.size()) : current + 1;
    DeclarationRow row;
    // Variable names are IEC identifiers, never translated.
    row.name = freeVariableName(rows, QStringLiteral("Var"));
    if (current >= 0)
        row.varClass = rows[size_t(current)].varClass;
    rows.insert(rows.begin() + at, row);
    applyRows(rows);
    selectRow(at);
}

void DeclarationEditor::removeCurrentRow()
{
    std::vector<DeclarationRow> rows = m_tableModel->rows();
    const int current = currentRow();
    if (current < 0)
        return;
    rows.erase(rows.begin() + current);
    applyRows(rows);
    selectRow(std::min(current, int(rows.size()) - 1));
}

void DeclarationEditor::moveCurrentRow(int delta)
{
    std::vector<DeclarationRow> rows = m_tableModel->rows();
    const int current = currentRow();
    const int target = current + delta;
    if (current < 0 || target < 0 || target >= int(rows.size()))
        return;
    std::swap(rows[size_t(current)], rows[size_t(target)]);
    applyRows(rows);
    selectRow(target);
}

void DeclarationEditor::flushPendingEdit()
{
    m_text->flushPendingEdit();
}

bool DeclarationEditor::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_text && event->type() == QEvent::FocusOut)
        flushPendingEdit();
    // The table's edits are on the POU's stack, so Ctrl+Z there undoes them, whatever the
    // window's Undo is bound to at the moment.
    if (watched == m_table && (event->type() == QEvent::ShortcutOverride || event->type() == QEvent::KeyPress)) {
        const auto *key = static_cast<QKeyEvent *>(event);
        const bool undo = key->matches(QKeySequence::Undo);
        const bool redo = key->matches(QKeySequence::Redo);
        if ((undo || redo) && m_undoStack) {
            event->accept();
            if (event->type() == QEvent::KeyPress && undo)
                m_undoStack->undo();
            else if (event->type() == QEvent::KeyPress)
                m_undoStack->redo();
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}

} // namespace iec::editors
