#pragma once

#include "editors/declarations/declarationrows.h"

#include <QAbstractTableModel>

namespace iec::editors {

// The rows of the declaration table as an item model. Edits change the row the table shows and
// are announced with rowsEdited; whoever owns the table decides whether they reach the project
// (DeclarationEditor validates them first). Cells with a problem are tinted and explain it in
// their tooltip.
class DeclarationTableModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    explicit DeclarationTableModel(QObject *parent = nullptr);

    [[nodiscard]] const std::vector<DeclarationRow> &rows() const { return m_rows; }
    // Shows `rows`; keeps the views' selection and editors when only cell texts changed.
    void setRows(std::vector<DeclarationRow> rows);
    void setProblems(std::vector<RowProblem> problems);
    [[nodiscard]] const std::vector<RowProblem> &problems() const { return m_problems; }

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role = Qt::EditRole) override;

Q_SIGNALS:
    // The user changed a cell; `rows` is the whole table after the change.
    void rowsEdited(const std::vector<iec::editors::DeclarationRow> &rows);

private:
    [[nodiscard]] const RowProblem *problemAt(const QModelIndex &index) const;

    std::vector<DeclarationRow> m_rows;
    std::vector<RowProblem> m_problems;
};

// The text of one cell, and a row with one cell replaced.
[[nodiscard]] QString cellText(const DeclarationRow &row, DeclarationColumn column);
void setCellText(DeclarationRow &row, DeclarationColumn column, const QString &text);

} // namespace iec::editors
