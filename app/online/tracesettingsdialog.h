#pragma once

#include "model/savedtrace.h"

#include <QDialog>

class QComboBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QSpinBox;

namespace iec::app {

// Trace Configuration, as CODESYS's: the variables (one per line, Main.Level), how often a
// sample is taken and how many are kept, the trigger (variable, edge or level, samples after
// it), a record condition, and how many scans are kept to go back to. A condition that is no
// expression is refused here, with the reason.
class TraceSettingsDialog : public QDialog
{
    Q_OBJECT

public:
    explicit TraceSettingsDialog(const model::SavedTrace &settings, QWidget *parent = nullptr);

    [[nodiscard]] model::SavedTrace settings() const;

    // For tests.
    [[nodiscard]] QPlainTextEdit *variablesEdit() const { return m_variables; }
    [[nodiscard]] QComboBox *triggerBox() const { return m_trigger; }
    [[nodiscard]] QLineEdit *triggerVariableEdit() const { return m_triggerVariable; }
    [[nodiscard]] QLineEdit *conditionEdit() const { return m_condition; }
    [[nodiscard]] QDialogButtonBox *buttons() const { return m_buttons; }
    [[nodiscard]] QLabel *problemLabel() const { return m_problem; }

private:
    void check();

    model::SavedTrace m_settings;
    QPlainTextEdit *m_variables;
    QSpinBox *m_every;
    QSpinBox *m_capacity;
    QComboBox *m_trigger;
    QLineEdit *m_triggerVariable;
    QDoubleSpinBox *m_level;
    QSpinBox *m_after;
    QLineEdit *m_condition;
    QSpinBox *m_history;
    QLabel *m_problem;
    QDialogButtonBox *m_buttons;
};

} // namespace iec::app
