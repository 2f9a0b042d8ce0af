#pragma once

#include "interpreter/runtime/debugging.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace iec::app {

// Breakpoint Properties, as in CODESYS: when a reached breakpoint halts (always, on the n-th
// hit, every n-th hit, from the n-th hit on), a Boolean condition ("break when TRUE"), and
// whether it is on. A condition that is no expression is refused here, with the reason.
class BreakpointDialog : public QDialog
{
    Q_OBJECT

public:
    BreakpointDialog(const QString &place, const interp::Breakpoint &settings, QWidget *parent = nullptr);

    [[nodiscard]] interp::Breakpoint settings() const;

    // For tests.
    [[nodiscard]] QComboBox *hitRuleBox() const { return m_hitRule; }
    [[nodiscard]] QSpinBox *hitTargetBox() const { return m_hitTarget; }
    [[nodiscard]] QLineEdit *conditionEdit() const { return m_condition; }
    [[nodiscard]] QCheckBox *enabledBox() const { return m_enabled; }
    [[nodiscard]] QLabel *problemLabel() const { return m_problem; }
    [[nodiscard]] QDialogButtonBox *buttons() const { return m_buttons; }

private:
    void check();

    interp::Breakpoint m_settings;
    QComboBox *m_hitRule;
    QSpinBox *m_hitTarget;
    QLineEdit *m_condition;
    QCheckBox *m_enabled;
    QLabel *m_problem;
    QDialogButtonBox *m_buttons;
};

} // namespace iec::app
