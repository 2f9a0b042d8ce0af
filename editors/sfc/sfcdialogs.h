#pragma once

#include "editors/sfc/sfcedits.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
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
    StepPropertiesDialog(const StepProperties &properties, const QStringList &actionNames, QWidget *parent = nullptr);
    [[nodiscard]] StepProperties properties() const;

private:
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
// variable), indicator; add, remove, reorder.
class ActionAssociationsDialog : public QDialog
{
    Q_OBJECT

public:
    ActionAssociationsDialog(const std::vector<model::ActionBlockAction> &actions, const QStringList &actionNames,
        QWidget *parent = nullptr);
    [[nodiscard]] std::vector<model::ActionBlockAction> actions() const;

private:
    void addRow(const model::ActionBlockAction &action);
    void moveRow(int delta);

    QTableWidget *m_table;
    QStringList m_actionNames;
    std::vector<model::ActionBlockAction> m_originals;
};

} // namespace iec::editors::sfc
