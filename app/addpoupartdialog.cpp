#include "app/addpoupartdialog.h"

#include "app/namerules.h"
#include "app/treeicons.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace iec::app {

using editors::EditorLanguage;

void fillLanguageChoice(QComboBox *combo)
{
    for (const EditorLanguage language :
        {EditorLanguage::ST, EditorLanguage::IL, EditorLanguage::LD, EditorLanguage::FBD, EditorLanguage::CFC, EditorLanguage::SFC})
        combo->addItem(languageIcon(language), languageName(language), int(language));
}

AddPouPartDialog::AddPouPartDialog(
    const model::Project &project, model::PouId pou, model::BodyRef::Part part, QWidget *parent)
    : QDialog(parent)
    , m_project(project)
    , m_pou(pou)
    , m_part(part)
{
    const bool isAction = part == model::BodyRef::Part::Action;
    setWindowTitle(isAction ? tr("Add Action") : tr("Add Transition"));

    const QString base = isAction ? QStringLiteral("Action") : QStringLiteral("Transition");
    m_name = new QLineEdit(NameRules::uniquePartName(project, pou, base), this);
    m_name->setObjectName(QStringLiteral("name"));
    m_name->selectAll();
    m_language = new QComboBox(this);
    m_language->setObjectName(QStringLiteral("language"));
    fillLanguageChoice(m_language);

    m_problem = new QLabel(this);
    m_problem->setObjectName(QStringLiteral("problem"));
    m_problem->setWordWrap(true);
    m_problem->setStyleSheet(QStringLiteral("color: #b00020"));

    auto *form = new QFormLayout;
    form->addRow(tr("&Name:"), m_name);
    form->addRow(tr("&Language:"), m_language);

    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_problem);
    layout->addWidget(m_buttons);

    connect(m_name, &QLineEdit::textChanged, this, &AddPouPartDialog::validate);
    validate();
}

NewPouPart AddPouPartDialog::newPart() const
{
    return {
        .part = m_part, .name = m_name->text().trimmed(), .language = EditorLanguage(m_language->currentData().toInt())};
}

QString AddPouPartDialog::problem() const
{
    return NameRules::partNameError(m_project, m_pou, m_name->text().trimmed()).value_or(QString());
}

void AddPouPartDialog::validate()
{
    const QString text = problem();
    m_problem->setText(text);
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(text.isEmpty());
}

} // namespace iec::app
