#include "app/autodeclaredialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace iec::app {

AutoDeclareDialog::AutoDeclareDialog(const editors::DeclarationRow &proposal, QStringList typeNames,
    std::function<QString(const editors::DeclarationRow &)> check, QWidget *parent)
    : QDialog(parent)
    , m_check(std::move(check))
    , m_name(new QLineEdit(proposal.name))
    , m_class(new QComboBox)
    , m_type(new QComboBox)
    , m_initialValue(new QLineEdit(proposal.initialValue))
    , m_comment(new QLineEdit(proposal.comment))
    , m_problem(new QLabel)
    , m_buttons(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel))
{
    setWindowTitle(tr("Declare Variable"));
    setObjectName(QStringLiteral("autoDeclareDialog"));
    // Classes and types are IEC keywords and names: never translated.
    m_class->addItems(editors::declarationClasses());
    m_class->setCurrentText(proposal.varClass);
    m_type->setEditable(true);
    if (!typeNames.contains(proposal.type, Qt::CaseInsensitive))
        typeNames.prepend(proposal.type);
    m_type->addItems(typeNames);
    m_type->setCurrentText(proposal.type);
    m_problem->setWordWrap(true);
    m_problem->setStyleSheet(QStringLiteral("color: #b00020"));

    auto *form = new QFormLayout;
    form->addRow(tr("&Name:"), m_name);
    form->addRow(tr("&Class:"), m_class);
    form->addRow(tr("&Type:"), m_type);
    form->addRow(tr("&Initial value:"), m_initialValue);
    form->addRow(tr("C&omment:"), m_comment);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_problem);
    layout->addWidget(m_buttons);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    for (QLineEdit *edit : {m_name, m_initialValue, m_comment})
        connect(edit, &QLineEdit::textChanged, this, &AutoDeclareDialog::validate);
    connect(m_class, &QComboBox::currentTextChanged, this, &AutoDeclareDialog::validate);
    connect(m_type, &QComboBox::currentTextChanged, this, &AutoDeclareDialog::validate);
    validate();
    // The type is what most often needs a look; the name was typed in the body already.
    m_type->setFocus();
    m_type->lineEdit()->installEventFilter(this);
}

bool AutoDeclareDialog::eventFilter(QObject *watched, QEvent *event)
{
    // Enter in the type field declares, also while the field shows an inline completion ("IN"
    // completed to "INT"): the line edit would take that first Enter only to accept the completion.
    if (watched == m_type->lineEdit() && event->type() == QEvent::KeyPress) {
        const int key = static_cast<QKeyEvent *>(event)->key();
        if (key == Qt::Key_Return || key == Qt::Key_Enter) {
            m_type->lineEdit()->deselect();
            validate();
            if (m_buttons->button(QDialogButtonBox::Ok)->isEnabled())
                accept();
            return true;
        }
    }
    return QDialog::eventFilter(watched, event);
}

editors::DeclarationRow AutoDeclareDialog::row() const
{
    return {.name = m_name->text().trimmed(),
        .varClass = m_class->currentText(),
        .type = m_type->currentText().trimmed(),
        .initialValue = m_initialValue->text().trimmed(),
        .address = {},
        .comment = m_comment->text().trimmed()};
}

void AutoDeclareDialog::validate()
{
    const QString problem = m_check ? m_check(row()) : QString();
    m_problem->setText(problem);
    m_problem->setVisible(!problem.isEmpty());
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(problem.isEmpty());
}

} // namespace iec::app
