#include "app/newprojectdialog.h"

#include <QDialogButtonBox>
#include <QLabel>
#include <QListWidget>
#include <QVBoxLayout>

namespace iec::app {

NewProjectDialog::NewProjectDialog(QWidget *parent)
    : QDialog(parent)
    , m_templates(new QListWidget(this))
    , m_description(new QLabel(this))
{
    setWindowTitle(tr("New Project"));
    m_templates->setObjectName(QStringLiteral("templateList"));
    for (const ProjectTemplate projectTemplate : ProjectTemplates::all()) {
        auto *item = new QListWidgetItem(ProjectTemplates::name(projectTemplate), m_templates);
        item->setData(Qt::UserRole, int(projectTemplate));
    }
    m_description->setWordWrap(true);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_templates, &QListWidget::itemDoubleClicked, this, &QDialog::accept);
    connect(m_templates, &QListWidget::currentRowChanged, this,
        [this] { m_description->setText(ProjectTemplates::description(chosen())); });
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(new QLabel(tr("Start the project from:"), this));
    layout->addWidget(m_templates);
    layout->addWidget(m_description);
    layout->addWidget(buttons);
    // Most projects start with one program; ST is the language every course begins with.
    choose(ProjectTemplate::ST);
}

ProjectTemplate NewProjectDialog::chosen() const
{
    const QListWidgetItem *item = m_templates->currentItem();
    return item ? ProjectTemplate(item->data(Qt::UserRole).toInt()) : ProjectTemplate::Empty;
}

void NewProjectDialog::choose(ProjectTemplate projectTemplate)
{
    m_templates->setCurrentRow(int(ProjectTemplates::all().indexOf(projectTemplate)));
}

} // namespace iec::app
