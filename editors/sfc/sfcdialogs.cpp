#include "editors/sfc/sfcdialogs.h"

#include "editors/sfc/sfcgeometry.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCompleter>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QStyle>
#include <QTableWidget>
#include <QVBoxLayout>

namespace iec::editors::sfc {

namespace {

QComboBox *actionCombo(const QStringList &names, const QString &current)
{
    auto *combo = new QComboBox;
    combo->setEditable(true);
    combo->addItem(QString());
    combo->addItems(names);
    combo->setCurrentText(current);
    return combo;
}

} // namespace

StepPropertiesDialog::StepPropertiesDialog(const StepProperties &p, const QStringList &actionNames, Check check, QWidget *parent)
    : QDialog(parent)
    , m_check(std::move(check))
    , m_problem(new QLabel)
    , m_name(new QLineEdit(p.name))
    , m_initial(new QCheckBox(tr("Initial step")))
    , m_simplified(new QCheckBox(tr("Simplified step (no IEC actions)")))
    , m_entry(actionCombo(actionNames, p.options.entryAction))
    , m_exit(actionCombo(actionNames, p.options.exitAction))
    , m_active(actionCombo(actionNames, p.options.activeAction))
    , m_minTime(new QLineEdit(p.options.minTime))
    , m_maxTime(new QLineEdit(p.options.maxTime))
    , m_comment(new QPlainTextEdit(p.comment))
    , m_initialBefore(p.initial)
{
    setWindowTitle(tr("Step Properties"));
    setObjectName(QStringLiteral("stepPropertiesDialog"));
    m_name->setObjectName(QStringLiteral("stepName"));
    m_entry->setObjectName(QStringLiteral("entryAction"));
    m_exit->setObjectName(QStringLiteral("exitAction"));
    m_active->setObjectName(QStringLiteral("activeAction"));
    m_problem->setObjectName(QStringLiteral("stepPropertiesProblem"));
    m_problem->setWordWrap(true);
    m_problem->setStyleSheet(QStringLiteral("color: #a03000;"));
    m_problem->hide();
    m_initial->setChecked(p.initial);
    m_simplified->setChecked(p.options.simplified);
    m_minTime->setPlaceholderText(tr("e.g. T#2s"));
    m_maxTime->setPlaceholderText(tr("e.g. T#10s"));
    auto *form = new QFormLayout;
    form->addRow(tr("Name:"), m_name);
    form->addRow(QString(), m_initial);
    form->addRow(QString(), m_simplified);
    form->addRow(tr("Entry action (E):"), m_entry);
    form->addRow(tr("Exit action (X):"), m_exit);
    form->addRow(tr("Active action:"), m_active);
    form->addRow(tr("Minimum time:"), m_minTime);
    form->addRow(tr("Maximum time:"), m_maxTime);
    form->addRow(tr("Comment:"), m_comment);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_problem);
    layout->addWidget(buttons);
}

void StepPropertiesDialog::accept()
{
    const QString problem = m_check ? m_check(properties()) : QString();
    m_problem->setText(problem);
    m_problem->setVisible(!problem.isEmpty());
    if (problem.isEmpty())
        QDialog::accept();
}

StepProperties StepPropertiesDialog::properties() const
{
    StepProperties p;
    p.name = m_name->text().trimmed();
    p.initial = m_initial->isChecked();
    p.options.simplified = m_simplified->isChecked();
    p.options.entryAction = m_entry->currentText().trimmed();
    p.options.exitAction = m_exit->currentText().trimmed();
    p.options.activeAction = m_active->currentText().trimmed();
    p.options.minTime = m_minTime->text().trimmed();
    p.options.maxTime = m_maxTime->text().trimmed();
    p.comment = m_comment->toPlainText();
    return p;
}

ActionAssociationsDialog::ActionAssociationsDialog(const std::vector<model::ActionBlockAction> &actions,
    const QStringList &actionNames, const QStringList &booleanNames, QWidget *parent)
    : QDialog(parent)
    , m_table(new QTableWidget(0, 4))
    , m_actionNames(actionNames)
    , m_booleanNames(booleanNames)
    , m_originals(actions)
{
    setWindowTitle(tr("IEC Actions of the Step"));
    setObjectName(QStringLiteral("actionAssociationsDialog"));
    m_table->setObjectName(QStringLiteral("actionTable"));
    m_table->setHorizontalHeaderLabels({tr("Qualifier"), tr("Time"), tr("Action or variable"), tr("Indicator")});
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    for (const model::ActionBlockAction &action : actions)
        addRow(action);
    fitColumns();
    auto *add = new QPushButton(tr("Add"));
    auto *remove = new QPushButton(tr("Remove"));
    auto *up = new QPushButton(tr("Move Up"));
    auto *down = new QPushButton(tr("Move Down"));
    connect(add, &QPushButton::clicked, this, [this] { addRow(actionAssociation(QStringLiteral("N"), QString())); });
    connect(remove, &QPushButton::clicked, this, [this] {
        if (m_table->currentRow() >= 0)
            m_table->removeRow(m_table->currentRow());
    });
    connect(up, &QPushButton::clicked, this, [this] { moveRow(-1); });
    connect(down, &QPushButton::clicked, this, [this] { moveRow(1); });
    auto *side = new QVBoxLayout;
    for (QPushButton *button : {add, remove, up, down})
        side->addWidget(button);
    side->addStretch();
    auto *middle = new QHBoxLayout;
    middle->addWidget(m_table);
    middle->addLayout(side);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(middle);
    layout->addWidget(buttons);
    resize(560, 300);
}

void ActionAssociationsDialog::addRow(const model::ActionBlockAction &action)
{
    const int row = m_table->rowCount();
    m_table->insertRow(row);
    auto *qualifier = new QComboBox;
    qualifier->addItems({QStringLiteral("N"), QStringLiteral("R"), QStringLiteral("S"), QStringLiteral("L"),
        QStringLiteral("D"), QStringLiteral("P"), QStringLiteral("SD"), QStringLiteral("DS"), QStringLiteral("SL"),
        QStringLiteral("P0"), QStringLiteral("P1")});
    qualifier->setCurrentText(action.qualifier.value_or(QStringLiteral("N")));
    m_table->setCellWidget(row, 0, qualifier);
    m_table->setItem(row, 1, new QTableWidgetItem(action.duration.value_or(QString())));
    auto *name = new QComboBox;
    name->setEditable(true);
    name->addItems(m_actionNames);
    for (const QString &variable : m_booleanNames) {
        name->addItem(variable);
        name->setItemData(name->count() - 1, tr("BOOL variable"), Qt::ToolTipRole);
    }
    // Typing offers what starts with the letters typed, in any case, in a list.
    name->completer()->setCompletionMode(QCompleter::PopupCompletion);
    name->completer()->setCaseSensitivity(Qt::CaseInsensitive);
    name->setCurrentText(actionName(action));
    m_table->setCellWidget(row, 2, name);
    m_table->setItem(row, 3, new QTableWidgetItem(action.indicator.value_or(QString())));
}

void ActionAssociationsDialog::fitColumns()
{
    // Every column at least as wide as its header (translations are longer than English), the
    // action names wider; the table, and so the dialog, wide enough to show them all.
    m_table->resizeColumnsToContents();
    const QFontMetrics metrics = m_table->horizontalHeader()->fontMetrics();
    m_table->setColumnWidth(2, std::max(m_table->columnWidth(2), metrics.horizontalAdvance(QLatin1Char('M')) * 14));
    int width = 0;
    for (int column = 0; column < m_table->columnCount(); ++column)
        width += m_table->columnWidth(column);
    width += m_table->verticalHeader()->sizeHint().width() + 2 * m_table->frameWidth()
        + m_table->style()->pixelMetric(QStyle::PM_ScrollBarExtent);
    m_table->setMinimumWidth(width);
}

void ActionAssociationsDialog::moveRow(int delta)
{
    const int row = m_table->currentRow();
    const int to = row + delta;
    if (row < 0 || to < 0 || to >= m_table->rowCount())
        return;
    std::vector<model::ActionBlockAction> list = actions();
    std::swap(list[std::size_t(row)], list[std::size_t(to)]);
    m_table->setRowCount(0);
    for (const auto &action : list)
        addRow(action);
    m_table->setCurrentCell(to, 0);
}

std::vector<model::ActionBlockAction> ActionAssociationsDialog::actions() const
{
    std::vector<model::ActionBlockAction> list;
    for (int row = 0; row < m_table->rowCount(); ++row) {
        const QString qualifier = static_cast<QComboBox *>(m_table->cellWidget(row, 0))->currentText();
        const QString name = static_cast<QComboBox *>(m_table->cellWidget(row, 2))->currentText().trimmed();
        const QString duration = m_table->item(row, 1) ? m_table->item(row, 1)->text().trimmed() : QString();
        const QString indicator = m_table->item(row, 3) ? m_table->item(row, 3)->text().trimmed() : QString();
        list.push_back(actionAssociation(qualifier, name, duration, indicator));
    }
    return list;
}

} // namespace iec::editors::sfc
