#include "app/online/breakpointdialog.h"

#include "interpreter/runtime/conditionexpression.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

namespace iec::app {

BreakpointDialog::BreakpointDialog(const QString &place, const interp::Breakpoint &settings, QWidget *parent)
    : QDialog(parent)
    , m_settings(settings)
    , m_hitRule(new QComboBox(this))
    , m_hitTarget(new QSpinBox(this))
    , m_condition(new QLineEdit(this))
    , m_enabled(new QCheckBox(tr("Enabled"), this))
    , m_problem(new QLabel(this))
    , m_buttons(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this))
{
    setWindowTitle(tr("Breakpoint Properties"));
    // In the order of interp::HitRule.
    m_hitRule->addItems({tr("Break always"), tr("Break when the hit count is equal to"),
                         tr("Break when the hit count is a multiple of"), tr("Break when the hit count is greater than or equal to")});
    m_hitRule->setCurrentIndex(int(settings.hitRule));
    m_hitTarget->setRange(1, 1'000'000);
    m_hitTarget->setValue(std::max(1, settings.hitTarget));
    m_condition->setText(settings.condition);
    m_condition->setPlaceholderText(tr("for example  Count = 5 AND NOT Alarm"));
    m_enabled->setChecked(settings.enabled);
    m_problem->setStyleSheet(QStringLiteral("color: #b00000;"));
    m_problem->setWordWrap(true);

    auto *form = new QFormLayout;
    form->addRow(tr("Place:"), new QLabel(place, this));
    form->addRow(tr("Hit count:"), m_hitRule);
    form->addRow(QString(), m_hitTarget);
    form->addRow(tr("Break when TRUE:"), m_condition);
    form->addRow(QString(), m_enabled);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_problem);
    layout->addWidget(m_buttons);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_hitRule, &QComboBox::currentIndexChanged, this, &BreakpointDialog::check);
    connect(m_condition, &QLineEdit::textChanged, this, &BreakpointDialog::check);
    check();
}

void BreakpointDialog::check()
{
    m_hitTarget->setEnabled(m_hitRule->currentIndex() != int(interp::HitRule::Always));
    const QString condition = m_condition->text().trimmed();
    const QString problem = condition.isEmpty() ? QString() : interp::conditionSyntaxError(condition);
    m_problem->setText(problem);
    m_problem->setVisible(!problem.isEmpty());
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(problem.isEmpty());
}

interp::Breakpoint BreakpointDialog::settings() const
{
    interp::Breakpoint b = m_settings;
    b.hitRule = interp::HitRule(m_hitRule->currentIndex());
    b.hitTarget = m_hitTarget->value();
    b.condition = m_condition->text().trimmed();
    b.enabled = m_enabled->isChecked();
    return b;
}

} // namespace iec::app
