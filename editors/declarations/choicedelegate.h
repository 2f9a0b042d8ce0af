#pragma once

#include <QStyledItemDelegate>

#include <functional>

namespace iec::editors {

// A cell edited in an editable combo box: the choices are offered (asked for each time the cell
// is edited, so they follow the project), and other text may be typed; the table's own checks
// say whether it is valid. The declaration class cell and the program cell of a task use it.
class ChoiceDelegate : public QStyledItemDelegate
{
public:
    ChoiceDelegate(std::function<QStringList()> choices, QObject *parent);

    QWidget *createEditor(QWidget *parent, const QStyleOptionViewItem &, const QModelIndex &) const override;
    void setEditorData(QWidget *editor, const QModelIndex &index) const override;
    void setModelData(QWidget *editor, QAbstractItemModel *model, const QModelIndex &index) const override;

private:
    std::function<QStringList()> m_choices;
};

} // namespace iec::editors
