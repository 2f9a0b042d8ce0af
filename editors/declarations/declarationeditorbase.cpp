#include "editors/declarations/declarationeditorbase.h"

#include "editors/declarations/choicedelegate.h"
#include "editors/declarations/declarationtablemodel.h"
#include "editors/text/codeeditor.h"

#include <QAction>
#include <QCoreApplication>
#include <QHeaderView>
#include <QKeyEvent>
#include <QLabel>
#include <QTabWidget>
#include <QTableView>
#include <QToolBar>
#include <QVBoxLayout>

namespace iec::editors {

namespace {

QList<TextDiagnostic> textDiagnostics(const std::vector<DeclarationProblem> &problems)
{
    QList<TextDiagnostic> diagnostics;
    for (const DeclarationProblem &problem : problems)
        diagnostics.append({problem.line, problem.column, 0, TextDiagnostic::Severity::Error, problem.message});
    return diagnostics;
}

} // namespace

DeclarationEditorBase::DeclarationEditorBase(QUndoStack &undoStack, const QStringList &classes, QWidget *parent)
    : QWidget(parent)
    , m_undoStack(&undoStack)
    , m_newRowClass(classes.value(0, QStringLiteral("VAR")))
    , m_views(new QTabWidget(this))
    , m_tableModel(new DeclarationTableModel(this))
    , m_text(new CodeEditor(TextLanguage::ST))
    , m_problem(new QLabel(this))
{
    m_views->setDocumentMode(true);
    m_views->setTabPosition(QTabWidget::South);
    m_views->addTab(createTablePage(classes), QString());
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

    connect(m_tableModel, &DeclarationTableModel::rowsEdited, this, &DeclarationEditorBase::applyRows);
    connect(m_text, &CodeEditor::textEdited, this, &DeclarationEditorBase::applyText);
}

QWidget *DeclarationEditorBase::createTablePage(const QStringList &classes)
{
    m_classes = classes;
    auto *page = new QWidget;
    auto *tools = new QToolBar(page);
    tools->setToolButtonStyle(Qt::ToolButtonTextOnly);
    m_addAction = tools->addAction(QString(), this, &DeclarationEditorBase::addRow);
    m_removeAction = tools->addAction(QString(), this, &DeclarationEditorBase::removeCurrentRow);
    m_moveUpAction = tools->addAction(QString(), this, [this] { moveCurrentRow(-1); });
    m_moveDownAction = tools->addAction(QString(), this, [this] { moveCurrentRow(1); });

    m_table = new QTableView(page);
    m_table->setObjectName(QStringLiteral("declarationTable"));
    m_table->setModel(m_tableModel);
    m_table->setItemDelegateForColumn(int(DeclarationColumn::Class), new ChoiceDelegate([classes] { return classes; }, m_table));
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

// The texts keep the context they were translated in when the POU's DeclarationEditor was alone.
void DeclarationEditorBase::retranslate()
{
    m_views->setTabText(0, QCoreApplication::translate("iec::editors::DeclarationEditor", "Table"));
    m_views->setTabText(1, QCoreApplication::translate("iec::editors::DeclarationEditor", "Text"));
    m_addAction->setText(QCoreApplication::translate("iec::editors::DeclarationEditor", "Add Variable"));
    m_removeAction->setText(QCoreApplication::translate("iec::editors::DeclarationEditor", "Remove"));
    m_moveUpAction->setText(QCoreApplication::translate("iec::editors::DeclarationEditor", "Move Up"));
    m_moveDownAction->setText(QCoreApplication::translate("iec::editors::DeclarationEditor", "Move Down"));
    Q_EMIT m_tableModel->headerDataChanged(Qt::Horizontal, 0, kDeclarationColumnCount - 1);
}

void DeclarationEditorBase::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

QString DeclarationEditorBase::problemText() const
{
    return m_problem->text();
}

void DeclarationEditorBase::showTable()
{
    m_views->setCurrentIndex(0);
}

void DeclarationEditorBase::showText()
{
    m_views->setCurrentIndex(1);
}

void DeclarationEditorBase::refreshFromModel()
{
    const model::Interface current = declarations();
    const std::vector<DeclarationRow> rows = rowsFromInterface(current);
    if (rows != m_tableModel->rows() || !m_tableModel->problems().empty()) {
        m_tableModel->setRows(rows);
        m_tableModel->setProblems({});
    }
    // Text that already says what the model holds stays as typed (its cursor, its layout).
    const DeclarationTextResult shown = readDeclarationText(m_text->toPlainText(), current);
    if (shown.declarations != current)
        m_text->setBodyText(declarationText(current));
    showProblem({});
    m_text->setDiagnostics({});
    if (!m_columnsFitted) { // once: later widths are the user's
        fitColumns();
        m_columnsFitted = true;
    }
}

void DeclarationEditorBase::fitColumns()
{
    m_table->resizeColumnsToContents();
    // Room for what is typed next, and for headers that another language makes longer.
    const QFontMetrics metrics = m_table->fontMetrics();
    const int roomy = metrics.horizontalAdvance(QStringLiteral("VAR_OUTPUT RETAIN")) + 12;
    for (int column = 0; column < kDeclarationColumnCount - 1; ++column)
        m_table->setColumnWidth(column, std::max(m_table->columnWidth(column), roomy * 3 / 4));
    // The class column holds its longest choice whole ("VAR_GLOBAL RETAIN PERSISTENT"), with
    // room for the drop-down arrow its editor shows.
    int classWidth = roomy;
    for (const QString &choice : m_classes)
        classWidth = std::max(classWidth, metrics.horizontalAdvance(choice) + 12 + metrics.height());
    m_table->setColumnWidth(
        int(DeclarationColumn::Class), std::max(m_table->columnWidth(int(DeclarationColumn::Class)), classWidth));
}

std::vector<DeclarationEditorBase::Placed> DeclarationEditorBase::ownProblems(const model::Interface &declarations) const
{
    std::vector<Placed> problems;
    int variableIndex = 0;
    for (int listIndex = 0; listIndex < int(declarations.varLists.size()); ++listIndex) {
        const model::VarList &list = declarations.varLists[size_t(listIndex)];
        if (QString message = sectionProblem(list); !message.isEmpty())
            problems.push_back({true, listIndex, message});
        for (const model::Variable &variable : list.variables) {
            if (QString message = variableProblem(list, variable); !message.isEmpty())
                problems.push_back({false, variableIndex, message});
            ++variableIndex;
        }
    }
    return problems;
}

void DeclarationEditorBase::applyRows(const std::vector<DeclarationRow> &rows)
{
    m_tableModel->setRows(rows);
    RowsResult result = interfaceFromRows(rows, declarations());
    if (result.declarations) {
        // A list's first row stands for the list (its class cell says what kind of list it is).
        std::vector<int> firstRows;
        int row = 0;
        for (const model::VarList &list : result.declarations->varLists) {
            firstRows.push_back(row);
            row += int(list.variables.size());
        }
        for (const Placed &problem : ownProblems(*result.declarations)) {
            result.problems.push_back(problem.section
                    ? RowProblem {firstRows[size_t(problem.index)], DeclarationColumn::Class, problem.message}
                    : RowProblem {problem.index, DeclarationColumn::Name, problem.message});
        }
    }
    m_tableModel->setProblems(result.problems);
    if (!result.problems.empty()) {
        showProblem(QCoreApplication::translate("iec::editors::DeclarationEditor", "Row %1: %2").arg(result.problems.front().row + 1).arg(result.problems.front().message));
        return;
    }
    showProblem({});
    apply(*result.declarations);
}

void DeclarationEditorBase::applyText()
{
    DeclarationTextResult result = readDeclarationText(m_text->toPlainText(), declarations());
    if (result.declarations) {
        for (const Placed &problem : ownProblems(*result.declarations)) {
            DeclarationProblem placed = problem.section ? result.sectionPlaces.at(size_t(problem.index))
                                                        : result.variablePlaces.at(size_t(problem.index));
            placed.message = problem.message;
            result.problems.push_back(placed);
        }
    }
    m_text->setDiagnostics(textDiagnostics(result.problems));
    if (!result.problems.empty()) {
        const DeclarationProblem &first = result.problems.front();
        showProblem(QCoreApplication::translate("iec::editors::DeclarationEditor", "Line %1, column %2: %3").arg(first.line).arg(first.column).arg(first.message));
        return;
    }
    showProblem({});
    apply(*result.declarations);
}

void DeclarationEditorBase::apply(const model::Interface &changed)
{
    if (!m_undoStack || changed == declarations())
        return;
    applyDeclarations(changed);
}

void DeclarationEditorBase::showProblem(const QString &message)
{
    m_problem->setText(message);
    m_problem->setVisible(!message.isEmpty());
}

int DeclarationEditorBase::currentRow() const
{
    const QModelIndex current = m_table->currentIndex();
    return current.isValid() ? current.row() : -1;
}

void DeclarationEditorBase::selectRow(int row)
{
    if (row >= 0 && row < m_tableModel->rowCount())
        m_table->setCurrentIndex(m_tableModel->index(row, int(DeclarationColumn::Name)));
}

bool DeclarationEditorBase::showVariable(const QString &name)
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

void DeclarationEditorBase::addRow()
{
    std::vector<DeclarationRow> rows = m_tableModel->rows();
    const int current = currentRow();
    const int at = current < 0 ? int(rows.size()) : current + 1;
    DeclarationRow row;
    // Variable names are IEC identifiers, never translated.
    row.name = freeVariableName(rows, QStringLiteral("Var"));
    row.varClass = current >= 0 ? rows[size_t(current)].varClass : m_newRowClass;
    rows.insert(rows.begin() + at, row);
    applyRows(rows);
    selectRow(at);
}

void DeclarationEditorBase::removeCurrentRow()
{
    std::vector<DeclarationRow> rows = m_tableModel->rows();
    const int current = currentRow();
    if (current < 0)
        return;
    rows.erase(rows.begin() + current);
    applyRows(rows);
    selectRow(std::min(current, int(rows.size()) - 1));
}

void DeclarationEditorBase::moveCurrentRow(int delta)
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

void DeclarationEditorBase::flushPendingEdit()
{
    m_text->flushPendingEdit();
}

bool DeclarationEditorBase::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_text && event->type() == QEvent::FocusOut)
        flushPendingEdit();
    // The table's edits are commands on the editor's stack, so Ctrl+Z there undoes them, whatever
    // the window's Undo is bound to at the moment.
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
