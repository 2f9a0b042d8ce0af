#pragma once

#include <QStringList>
#include <QWidget>

#include <vector>

class QTableWidget;
class QToolButton;

namespace iec::editors {

class MessageLabel;

// A table of text rows with Add / Remove / Up / Down buttons and a message line below it. Each row
// carries a tag (the editor stores where the row came from) that travels with it when it moves.
// edited() is one user gesture: a cell edit committed, a row added, removed or moved.
class RowTable : public QWidget
{
    Q_OBJECT

public:
    RowTable(const QStringList &headers, QWidget *parent = nullptr);

    struct Row {
        QStringList cells;
        int tag = -1;
    };
    void setRows(const std::vector<Row> &rows);
    [[nodiscard]] std::vector<Row> rows() const;
    // The cells of a new row (Add).
    void setNewRow(const QStringList &cells) { m_newRow = cells; }

    // Marks cells with a message (tooltip, tinted background) and lists the messages below.
    struct CellMessage {
        int row = -1; // -1: the table as a whole
        int column = 0;
        QString message;
    };
    void showMessages(const std::vector<CellMessage> &messages);

    [[nodiscard]] QTableWidget *table() const { return m_table; }
    [[nodiscard]] MessageLabel *messageLabel() const { return m_messages; }
    void addRow();
    void removeCurrentRow();
    void moveCurrentRow(int delta);

Q_SIGNALS:
    void edited();

private:
    QToolButton *addButton(const QString &text, const QString &toolTip);
    void writeRow(int row, const Row &content);

    QTableWidget *m_table;
    MessageLabel *m_messages;
    QStringList m_newRow;
    bool m_filling = false;
};

} // namespace iec::editors
