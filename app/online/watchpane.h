#pragma once

#include "interpreter/runtime/snapshot.h"

#include <QAbstractTableModel>
#include <QWidget>

#include <memory>
#include <optional>

class QAction;
class QCompleter;
class QLineEdit;
class QStringListModel;
class QToolButton;
class QTreeView;

namespace iec::interp {
struct Module;
}

namespace iec::app {

// Every name the watch pane can complete: globals, program instances and their members down to
// a few levels ("Main", "Main.Tank", "Main.Tank.Level"), sorted, at most `limit`.
QStringList watchableNames(const interp::Module &module, int limit = 20000);

// The watched variables: name, type, current value, and the value prepared for the next write
// or force (CODESYS: type the new value, then Write or Force).
class WatchModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    enum Column { NameColumn, TypeColumn, ValueColumn, PreparedColumn, ColumnCount };

    explicit WatchModel(QObject *parent = nullptr);

    // False when the name is empty or already watched (names compare case-insensitively).
    bool addName(const QString &name, const QString &type = {});
    void removeName(const QString &name);
    [[nodiscard]] QStringList names() const;
    [[nodiscard]] int rowOf(const QString &name) const;
    [[nodiscard]] QString value(int row) const { return m_rows.at(row).value; }
    [[nodiscard]] bool isForced(int row) const { return m_rows.at(row).forced; }
    [[nodiscard]] QString prepared(int row) const { return m_rows.at(row).prepared; }
    void setPrepared(int row, const QString &literal);
    void setType(int row, const QString &type);
    // Values and forced markers from a snapshot; nullptr (offline) clears the values.
    void setSnapshot(const interp::RuntimeSnapshot *snapshot);

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role) override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

Q_SIGNALS:
    void namesChanged();

private:
    struct Row {
        QString name;
        QString type;
        QString value;
        QString prepared;
        bool forced = false;
        bool known = true; // the last snapshot had the name
    };
    QList<Row> m_rows;
    bool m_online = false;
    std::optional<int> m_historyCycle; // the values are those after this earlier scan
};

// The Watch dock: a line to add a variable by name (with completion from the compiled program's
// symbols), the list of watched variables with live values, and Write / Force / Release.
class WatchPane : public QWidget
{
    Q_OBJECT

public:
    explicit WatchPane(QWidget *parent = nullptr);

    [[nodiscard]] WatchModel &model() { return *m_model; }
    [[nodiscard]] QTreeView *view() const { return m_view; }
    [[nodiscard]] QLineEdit *nameEdit() const { return m_nameEdit; }
    [[nodiscard]] QCompleter *completer() const { return m_completer; }

    // The compiled program: completion names and types of the watched variables.
    void setModule(std::shared_ptr<const interp::Module> module);
    bool addVariable(const QString &name);
    void setSnapshot(const interp::RuntimeSnapshot *snapshot);

    void retranslate();
    // Watches the name (if it is not yet) and puts the literal in its prepared column.
    void prepareValue(const QString &name, const QString &literal);

public Q_SLOTS:
    // Writes / forces every prepared value and clears them (CODESYS: Ctrl+F7 / F7).
    void writePrepared();
    void forcePrepared();
    // Releases the forces of the selected rows (all forced rows when none is selected).
    void releaseSelected();
    void removeSelected();

Q_SIGNALS:
    void writeRequested(const QString &name, const QString &literal);
    void forceRequested(const QString &name, const QString &literal);
    void releaseRequested(const QString &name);
    void releaseAllRequested();
    void namesChanged();

protected:
    void changeEvent(QEvent *event) override;

private:
    void addFromLine();
    [[nodiscard]] QList<int> selectedRows() const;
    void sendPrepared(void (WatchPane::*request)(const QString &, const QString &));

    WatchModel *m_model = nullptr;
    QTreeView *m_view = nullptr;
    QLineEdit *m_nameEdit = nullptr;
    QCompleter *m_completer = nullptr;
    QStringListModel *m_completionModel = nullptr;
    QToolButton *m_addButton = nullptr;
    QAction *m_writeAction = nullptr;
    QAction *m_forceAction = nullptr;
    QAction *m_releaseAction = nullptr;
    QAction *m_releaseAllAction = nullptr;
    QAction *m_removeAction = nullptr;
    std::shared_ptr<const interp::Module> m_module;
};

} // namespace iec::app
