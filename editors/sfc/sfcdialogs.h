#pragma once

#include "editors/sfc/sfcedits.h"

#include <QDialog>

#include <functional>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QTableWidget;

namespace iec::editors::sfc {

// Step properties: name, initial step, IEC or simplified step, entry/exit/active actions,
// minimum and maximum time, comment.
class StepPropertiesDialog : public QDialog
{
    Q_OBJECT

public:
    // Why the editor would refuse the properties typed (empty: it accepts them).
    using Check = std::function<QString(const StepProperties &)>;

    // OK is refused, with `check`'s message shown in the dialog, while `check` refuses.
    StepPropertiesDialog(const StepProperties &properties, const QStringList &actionNames, Check check = {},
        QWidget *parent = nullptr);
    [[nodiscard]] StepProperties properties() const;
    void accept() override;

private:
    Check m_check;
    QLabel *m_problem;
    QLineEdit *m_name;
    QCheckBox *m_initial;
    QCheckBox *m_simplified;
    QComboBox *m_entry;
    QComboBox *m_exit;
    QComboBox *m_active;
    QLineEdit *m_minTime;
    QLineEdit *m_maxTime;
    QPlainTextEdit *m_comment;
    bool m_initialBefore;
};

// The IEC action associations of a step: qualifier, time, action (a POU action or a Boolean
// variable), indicator; add, remove, reorder. The action field offers and completes the POU's
// actions and the BOOL variables it sees.
class ActionAssociationsDialog : public QDialog
{
    Q_OBJECT

public:
    ActionAssociationsDialog(const std::vector<model::ActionBlockAction> &actions, const QStringList &actionNames,
        const QStringList &booleanNames = {}, QWidget *parent = nullptr);
    [[nodiscard]] std::vector<model::ActionBlockAction> actions() const;

private:
    void addRow(const model::ActionBlockAction &action);
    void moveRow(int delta);
    void fitColumns();

    QTableWidget *m_table;
    QStringList m_actionNames;
    QStringList m_booleanNames;
    std::vector<model::ActionBlockAction> m_originals;
};

} // namespace iec::editors::sfc
