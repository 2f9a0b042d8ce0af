#include "app/addpoudialog.h"

#include "app/addpoupartdialog.h"
#include "app/namerules.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace iec::app {

AddPouDialog::AddPouDialog(const model::Project &project, QWidget *parent)
    : QDialog(parent)
    , m_project(project)
{
    setWindowTitle(tr("Add POU"));

    m_name = new QLineEdit(NameRules::uniquePouName(project, QStringLiteral("POU")), this);
    m_name->setObjectName(QStringLiteral("name"));
    m_name->selectAll();

    m_kind = new QComboBox(this);
    m_kind->setObjectName(QStringLiteral("kind"));
    m_kind->addItem(tr("Program"), int(model::PouKind::Program));
    m_kind->addItem(tr("Function Block"), int(model::PouKind::FunctionBlock));
    m_kind->addItem(tr("Function"), int(model::PouKind::Function));

    m_language = new QComboBox(this);
    m_language->setObjectName(QStringLiteral("language"));
    fillLanguageChoice(m_language);

    m_returnType = new QComboBox(this);
    m_returnType->setObjectName(QStringLiteral("returnType"));
    m_returnType->setEditable(true); // a user data type may be typed in
    m_returnType->addItems(
        {QStringLiteral("BOOL"), QStringLiteral("INT"), QStringLiteral("DINT"), QStringLiteral("UINT"),
            QStringLiteral("UDINT"), QStringLiteral("REAL"), QStringLiteral("LREAL"), QStringLiteral("TIME"),
            QStringLiteral("BYTE"), QStringLiteral("WORD"), QStringLiteral("DWORD"), QStringLiteral("STRING")});
    m_returnType->setCurrentText(QStringLiteral("INT"));

    m_problem = new QLabel(this);
    m_problem->setObjectName(QStringLiteral("problem"));
    m_problem->setWordWrap(true);
    m_problem->setStyleSheet(QStringLiteral("color: #b00020"));

    auto *form = new QFormLayout;
    form->addRow(tr("&Name:"), m_name);
    form->addRow(tr("&Kind:"), m_kind);
    form->addRow(tr("&Language:"), m_language);
    form->addRow(tr("&Return type:"), m_returnType);

    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_problem);
    layout->addWidget(m_buttons);

    connect(m_name, &QLineEdit::textChanged, this, &AddPouDialog::validate);
    connect(m_kind, &QComboBox::currentIndexChanged, this, &AddPouDialog::validate);
    connect(m_returnType, &QComboBox::currentTextChanged, this, &AddPouDialog::validate);
    validate();
}

NewPou AddPouDialog::newPou() const
{
    return {.name = m_name->text().trimmed(),
        .kind = model::PouKind(m_kind->currentData().toInt()),
        .language = editors::EditorLanguage(m_language->currentData().toInt()),
        .returnType = newPouIsFunction() ? m_returnType->currentText().trimmed() : QString()};
}

bool AddPouDialog::newPouIsFunction() const
{
    return model::PouKind(m_kind->currentData().toInt()) == model::PouKind::Function;
}

QString AddPouDialog::problem() const
{
    if (const auto error = NameRules::pouNameError(m_project, m_name->text().trimmed()))
        return *error;
    if (newPouIsFunction() && m_returnType->currentText().trimmed().isEmpty())
        return tr("A function needs a return type.");
    return {};
}

void AddPouDialog::validate()
{
    m_returnType->setEnabled(newPouIsFunction());
    const QString text = problem();
    m_problem->setText(text);
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(text.isEmpty());
}

} // namespace iec::app
