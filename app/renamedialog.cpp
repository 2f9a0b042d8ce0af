#include "app/renamedialog.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace iec::app {

RenameDialog::RenameDialog(const QString &currentName, Check check, QWidget *parent)
    : QDialog(parent)
    , m_check(std::move(check))
    , m_currentName(currentName)
{
    setWindowTitle(tr("Rename %1").arg(currentName));
    m_name = new QLineEdit(currentName, this);
    m_name->setObjectName(QStringLiteral("name"));
    m_name->selectAll();
    m_problem = new QLabel(this);
    m_problem->setObjectName(QStringLiteral("problem"));
    m_problem->setWordWrap(true);
    m_problem->setStyleSheet(QStringLiteral("color: #b00020"));

    auto *form = new QFormLayout;
    form->addRow(tr("&New name:"), m_name);
    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_problem);
    layout->addWidget(m_buttons);
    connect(m_name, &QLineEdit::textChanged, this, &RenameDialog::validate);
    validate();
}

QString RenameDialog::newName() const
{
    return m_name->text().trimmed();
}

QString RenameDialog::problem() const
{
    // Keeping the name is no error, but there is nothing to do either (OK stays disabled).
    if (newName() == m_currentName)
        return {};
    return m_check(newName()).value_or(QString());
}

void RenameDialog::validate()
{
    const QString text = problem();
    m_problem->setText(text);
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(text.isEmpty() && newName() != m_currentName);
}

} // namespace iec::app
