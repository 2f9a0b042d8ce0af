#pragma once

#include "app/projecttemplates.h"

#include <QDialog>

class QLabel;
class QListWidget;

namespace iec::app {

// File → New: choose what the project starts from (ProjectTemplates).
class NewProjectDialog : public QDialog
{
    Q_OBJECT

public:
    explicit NewProjectDialog(QWidget *parent = nullptr);

    [[nodiscard]] ProjectTemplate chosen() const;
    void choose(ProjectTemplate projectTemplate);

private:
    QListWidget *m_templates;
    QLabel *m_description;
};

} // namespace iec::app
