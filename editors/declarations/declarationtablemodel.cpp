#include "editors/declarations/declarationtablemodel.h"

#include <QBrush>
#include <QColor>

namespace iec::editors {

namespace {

// One switch for reading and writing: Row is DeclarationRow or const DeclarationRow.
template<typename Row> auto *cell(Row &row, DeclarationColumn column)
{
    switch (column) {
    case DeclarationColumn::Name:
        return &row.name;
    case DeclarationColumn::Class:
        return &row.varClass;
    case DeclarationColumn::Type:
        return &row.type;
    case DeclarationColumn::InitialValue:
        return &row.initialValue;
    case DeclarationColumn::Address:
        return &row.address;
    case DeclarationColumn::Comment:
        return &row.comment;
    }
    return &row.comment;
}

} // namespace

QString cellText(const DeclarationRow &row, DeclarationColumn column)
{
    return *cell(row, column);
}

void setCellText(DeclarationRow &row, DeclarationColumn column, const QString &text)
{
    *cell(row, column) = text;
}

DeclarationTableModel::DeclarationTableModel(QObject *parent)
    : QAbstractTableModel(parent)
{ }

void DeclarationTableModel::setRows(std::vector<DeclarationRow> rows)
{
    if (rows.size() == m_rows.size()) {
        m_rows = std::move(rows);
        if (!m_rows.empty())
            Q_EMIT dataChanged(index(0, 0), index(rowCount() - 1, kDeclarationColumnCount - 1));
        return;
    }
    beginResetModel();
    m_rows = std::move(rows);
    m_problems.clear();
    endResetModel();
}

void DeclarationTableModel::setProblems(std::vector<RowProblem> problems)
{
    m_problems = std::move(problems);
    if (!m_rows.empty())
        Q_EMIT dataChanged(index(0, 0), index(rowCount() - 1, kDeclarationColumnCount - 1));
}

int DeclarationTableModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_rows.size());
}

int DeclarationTableModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : kDeclarationColumnCount;
}

const RowProblem *DeclarationTableModel::problemAt(const QModelIndex &index) const
{
    for (const RowProblem &problem : m_problems) {
        if (problem.row == index.row() && int(problem.column) == index.column())
            return &problem;
    }
    return nullptr;
}

QVariant DeclarationTableModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= rowCount())
        return {};
    const auto column = DeclarationColumn(index.column());
    switch (role) {
    case Qt::DisplayRole:
    case Qt::EditRole:
        return cellText(m_rows[size_t(index.row())], column);
    case Qt::BackgroundRole:
        return problemAt(index) ? QVariant(QBrush(QColor(255, 205, 205))) : QVariant();
    case Qt::ToolTipRole:
        return problemAt(index) ? QVariant(problemAt(index)->message) : QVariant();
    default:
        return {};
    }
}

QVariant DeclarationTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (role != Qt::DisplayRole)
        return {};
    if (orientation == Qt::Vertical)
        return section + 1;
    switch (DeclarationColumn(section)) {
    case DeclarationColumn::Name:
        return tr("Name");
    case DeclarationColumn::Class:
        return tr("Class");
    case DeclarationColumn::Type:
        return tr("Type");
    case DeclarationColumn::InitialValue:
        return tr("Initial Value");
    case DeclarationColumn::Address:
        return tr("Address");
    case DeclarationColumn::Comment:
        return tr("Comment");
    }
    return {};
}

Qt::ItemFlags DeclarationTableModel::flags(const QModelIndex &index) const
{
    return QAbstractTableModel::flags(index) | Qt::ItemIsEditable;
}

bool DeclarationTableModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    if (!index.isValid() || role != Qt::EditRole || index.row() >= rowCount())
        return false;
    const auto column = DeclarationColumn(index.column());
    DeclarationRow &row = m_rows[size_t(index.row())];
    // Cells are IEC text; surrounding blanks mean nothing there, except in the comment.
    const QString text = column == DeclarationColumn::Comment ? value.toString() : value.toString().trimmed();
    if (cellText(row, column) == text)
        return false;
    setCellText(row, column, text);
    Q_EMIT dataChanged(index, index);
    Q_EMIT rowsEdited(m_rows);
    return true;
}

} // namespace iec::editors
