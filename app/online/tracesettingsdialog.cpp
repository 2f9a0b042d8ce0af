#include "app/online/tracesettingsdialog.h"

#include "interpreter/runtime/conditionexpression.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSpinBox>

namespace iec::app {

TraceSettingsDialog::TraceSettingsDialog(const model::SavedTrace &settings, QWidget *parent)
    : QDialog(parent)
    , m_settings(settings)
    , m_variables(new QPlainTextEdit(this))
    , m_every(new QSpinBox(this))
    , m_capacity(new QSpinBox(this))
    , m_trigger(new QComboBox(this))
    , m_triggerVariable(new QLineEdit(this))
    , m_level(new QDoubleSpinBox(this))
    , m_after(new QSpinBox(this))
    , m_condition(new QLineEdit(this))
    , m_history(new QSpinBox(this))
    , m_problem(new QLabel(this))
    , m_buttons(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this))
{
    setWindowTitle(tr("Trace Configuration"));
    m_variables->setPlainText(settings.variables.join(QLatin1Char('\n')));
    m_variables->setPlaceholderText(tr("One variable per line, e.g. Main.Level"));
    m_variables->setTabChangesFocus(true);
    m_every->setRange(1, 1'000'000);
    m_every->setValue(settings.everyCycles);
    m_every->setSuffix(tr(" cycle(s)"));
    m_capacity->setRange(2, 10'000'000);
    m_capacity->setSingleStep(1000);
    m_capacity->setValue(settings.capacity);
    m_trigger->addItems({tr("None (record all the time)"), tr("Rising edge"), tr("Falling edge"), tr("Level reached")});
    m_trigger->setCurrentIndex(std::clamp(settings.trigger, 0, 3));
    m_triggerVariable->setText(settings.triggerVariable);
    m_triggerVariable->setPlaceholderText(tr("e.g. Main.Start"));
    m_level->setRange(-1e12, 1e12);
    m_level->setDecimals(3);
    m_level->setValue(settings.triggerLevel);
    m_level->setToolTip(tr("A BOOL is 1 when TRUE: the level 0.5 triggers on its edges."));
    m_after->setRange(0, 10'000'000);
    m_after->setValue(settings.samplesAfterTrigger);
    m_condition->setText(settings.recordCondition);
    m_condition->setPlaceholderText(tr("Record only while TRUE, e.g. Main.Running"));
    m_history->setRange(1, 1'000'000);
    m_history->setSingleStep(100);
    m_history->setValue(settings.historyScans);
    m_history->setSuffix(tr(" scans"));
    m_problem->setStyleSheet(QStringLiteral("color: #b00000;"));
    m_problem->setWordWrap(true);

    auto *form = new QFormLayout(this);
    form->addRow(tr("&Variables:"), m_variables);
    form->addRow(tr("Sample &every:"), m_every);
    form->addRow(tr("Samples &kept:"), m_capacity);
    form->addRow(tr("&Trigger:"), m_trigger);
    form->addRow(tr("Trigger v&ariable:"), m_triggerVariable);
    form->addRow(tr("Trigger &level:"), m_level);
    form->addRow(tr("Samples &after the trigger:"), m_after);
    form->addRow(tr("Record &condition:"), m_condition);
    form->addRow(tr("&Scan history keeps:"), m_history);
    form->addRow(m_problem);
    form->addRow(m_buttons);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_condition, &QLineEdit::textChanged, this, &TraceSettingsDialog::check);
    connect(m_trigger, &QComboBox::currentIndexChanged, this, &TraceSettingsDialog::check);
    connect(m_triggerVariable, &QLineEdit::textChanged, this, &TraceSettingsDialog::check);
    check();
}

void TraceSettingsDialog::check()
{
    const bool triggered = m_trigger->currentIndex() != 0;
    m_triggerVariable->setEnabled(triggered);
    m_level->setEnabled(triggered);
    m_after->setEnabled(triggered);
    QString problem;
    const QString condition = m_condition->text().trimmed();
    if (!condition.isEmpty()) {
        const QString error = interp::conditionSyntaxError(condition);
        if (!error.isEmpty())
            problem = tr("The record condition is not an expression: %1").arg(error);
    }
    if (problem.isEmpty() && triggered && m_triggerVariable->text().trimmed().isEmpty())
        problem = tr("Name the variable that triggers the recording.");
    m_problem->setText(problem);
    m_problem->setVisible(!problem.isEmpty());
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(problem.isEmpty());
}

model::SavedTrace TraceSettingsDialog::settings() const
{
    model::SavedTrace settings = m_settings;
    settings.variables.clear();
    for (const QString &line : m_variables->toPlainText().split(QLatin1Char('\n'))) {
        const QString name = line.trimmed();
        if (!name.isEmpty() && !settings.variables.contains(name, Qt::CaseInsensitive))
            settings.variables << name;
    }
    settings.hidden.removeIf([&](const QString &name) { return !settings.variables.contains(name); });
    settings.everyCycles = m_every->value();
    settings.capacity = m_capacity->value();
    settings.trigger = m_trigger->currentIndex();
    settings.triggerVariable = m_triggerVariable->text().trimmed();
    settings.triggerLevel = m_level->value();
    settings.samplesAfterTrigger = m_after->value();
    settings.recordCondition = m_condition->text().trimmed();
    settings.historyScans = m_history->value();
    return settings;
}

} // namespace iec::app
