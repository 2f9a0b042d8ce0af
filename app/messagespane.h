#pragma once

#include "model/diagnostic.h"

#include <QAbstractTableModel>
#include <QWidget>

#include <optional>

class QLabel;
class QTreeView;

namespace iec::app {

// One line of the messages pane: a diagnostic of the reader, the compiler or the runtime, with
// the place it points to (a line of a text body or an element of a graphical one).
struct Message {
    enum class Severity { Info, Warning, Error };

    Severity severity = Severity::Error;
    QString text;
    QString pouName; // empty when the message concerns the whole project or file
    int line = 0;    // 1-based; 0 when the message has no text position
    int column = 0;
    std::optional<quint64> localId; // graphical element

    bool operator==(const Message &) const = default;
};

// The messages of every source (import, build, runtime), each source replaced as a whole.
class MessageListModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    enum Column { SeverityColumn, TextColumn, LocationColumn, ColumnCount };

    explicit MessageListModel(QObject *parent = nullptr);

    void setMessages(const QString &source, const QList<Message> &messages);
    void clear();
    [[nodiscard]] const Message &message(int row) const { return m_entries.at(row).message; }
    [[nodiscard]] int count(Message::Severity severity) const;

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

private:
    struct Entry {
        QString source;
        Message message;
    };
    QList<Entry> m_entries;
};

// The dock's content: the list and a summary line; a double-click asks the app to open the place.
class MessagesPane : public QWidget
{
    Q_OBJECT

public:
    explicit MessagesPane(QWidget *parent = nullptr);

    [[nodiscard]] MessageListModel &model() { return *m_model; }
    [[nodiscard]] QString summary() const;

Q_SIGNALS:
    void messageActivated(const iec::app::Message &message);

protected:
    void changeEvent(QEvent *event) override;

private:
    void updateSummary();

    MessageListModel *m_model = nullptr;
    QTreeView *m_view = nullptr;
    QLabel *m_summary = nullptr;
};

QString locationText(const Message &message);
// The pane's severity of a reader diagnostic (PLCopen XML or IEC text).
Message::Severity messageSeverity(model::Diagnostic::Severity severity);

} // namespace iec::app
