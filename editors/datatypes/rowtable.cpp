#include "editors/datatypes/rowtable.h"

#include "editors/datatypes/messagelabel.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QTableWidget>
#include <QToolButton>
#include <QVBoxLayout>

namespace iec::editors {

namespace {

const QColor kErrorTint(255, 205, 210);

} // namespace

RowTable::RowTable(const QStringList &headers, QWidget *parent)
    : QWidget(parent)
    , m_table(new QTableWidget(0, int(headers.size()), this))
    , m_messages(new MessageLabel(this))
{
    m_table->setHorizontalHeaderLabels(headers);
    // Two short columns (bounds, enum values) share the width; wider tables give the rest to the last.
    if (headers.size() <= 2)
        m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    else
        m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 8);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    connect(m_table, &QTableWidget::itemChanged, this, [this] {
        if (!m_filling)
            Q_EMIT edited();
    });

    auto *buttons = new QHBoxLayout;
    connect(
        addButton(tr("Add"), tr("Add a row below the current one")), &QToolButton::clicked, this, &RowTable::addRow);
    connect(addButton(tr("Remove"), tr("Remove the current row")), &QToolButton::clicked, this,
        &RowTable::removeCurrentRow);
    connect(addButton(tr("Up"), tr("Move the current row up")), &QToolButton::clicked, this,
        [this] { moveCurrentRow(-1); });
    connect(addButton(tr("Down"), tr("Move the current row down")), &QToolButton::clicked, this,
        [this] { moveCurrentRow(1); });
    for (QToolButton *button : findChildren<QToolButton *>())
        buttons->addWidget(button);
    buttons->addStretch();

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_table);
    layout->addLayout(buttons);
    layout->addWidget(m_messages);
}

QToolButton *RowTable::addButton(const QString &text, const QString &toolTip)
{
    auto *button = new QToolButton(this);
    button->setText(text);
    button->setToolTip(toolTip);
    return button;
}

void RowTable::writeRow(int row, const Row &content)
{
    // Existing items are updated, not replaced: a refresh may run inside the itemChanged() of one.
    for (int column = 0; column < m_table->columnCount(); ++column) {
        QTableWidgetItem *item = m_table->item(row, column);
        if (!item) {
            item = new QTableWidgetItem;
            m_table->setItem(row, column, item);
        }
        item->setText(content.cells.value(column));
        if (column == 0)
            item->setData(Qt::UserRole, content.tag);
    }
}

void RowTable::setRows(const std::vector<Row> &rows)
{
    m_filling = true;
    m_table->setRowCount(int(rows.size()));
    for (int row = 0; row < int(rows.size()); ++row)
        writeRow(row, rows[size_t(row)]);
    m_filling = false;
}

std::vector<RowTable::Row> RowTable::rows() const
{
    std::vector<Row> result;
    for (int row = 0; row < m_table->rowCount(); ++row) {
        Row content;
        for (int column = 0; column < m_table->columnCount(); ++column) {
            const QTableWidgetItem *item = m_table->item(row, column);
            content.cells << (item ? item->text() : QString());
            if (column == 0 && item)
                content.tag = item->data(Qt::UserRole).toInt();
        }
        result.push_back(content);
    }
    return result;
}

void RowTable::showMessages(const std::vector<CellMessage> &messages)
{
    m_filling = true;
    for (int row = 0; row < m_table->rowCount(); ++row) {
        for (int column = 0; column < m_table->columnCount(); ++column) {
            if (QTableWidgetItem *item = m_table->item(row, column)) {
                item->setBackground(QBrush());
                item->setToolTip({});
            }
        }
    }
    QStringList lines;
    for (const CellMessage &message : messages) {
        QTableWidgetItem *item = m_table->item(message.row, message.column);
        if (item) {
            item->setBackground(kErrorTint);
            item->setToolTip(message.message);
        }
        const QString header = m_table->horizontalHeaderItem(message.column)->text();
        lines << (message.row < 0 ? message.message
                                  : tr("Row %1, %2: %3").arg(message.row + 1).arg(header, message.message));
    }
    m_filling = false;
    m_messages->showMessage(lines.join(QLatin1Char('\n')));
}

void RowTable::addRow()
{
    const int row = m_table->currentRow() < 0 ? m_table->rowCount() : m_table->currentRow() + 1;
    m_filling = true;
    m_table->insertRow(row);
    writeRow(row, {m_newRow, -1});
    m_filling = false;
    m_table->setCurrentCell(row, 0);
    Q_EMIT edited();
}

void RowTable::removeCurrentRow()
{
    const int row = m_table->currentRow();
    if (row < 0)
        return;
    m_table->removeRow(row);
    Q_EMIT edited();
}

void RowTable::moveCurrentRow(int delta)
{
    const int row = m_table->currentRow();
    const int target = row + delta;
    if (row < 0 || target < 0 || target >= m_table->rowCount())
        return;
    m_filling = true;
    for (int column = 0; column < m_table->columnCount(); ++column) {
        QTableWidgetItem *moving = m_table->takeItem(row, column);
        m_table->setItem(row, column, m_table->takeItem(target, column));
        m_table->setItem(target, column, moving);
    }
    m_filling = false;
    m_table->setCurrentCell(target, m_table->currentColumn());
    Q_EMIT edited();
}

} // namespace iec::editors
