#pragma once

#include "app/projectcommands.h"

#include <QDialog>

class QComboBox;
class QDialogButtonBox;
class QLabel;
class QLineEdit;

namespace iec::model {
struct Project;
}

namespace iec::app {

// Add Action / Add Transition on a POU: a name (a free IEC identifier among the POU's actions and
// transitions) and the language of its body.
class AddPouPartDialog : public QDialog
{
    Q_OBJECT

public:
    AddPouPartDialog(
        const model::Project &project, model::PouId pou, model::BodyRef::Part part, QWidget *parent = nullptr);

    [[nodiscard]] NewPouPart newPart() const;
    [[nodiscard]] QString problem() const;

private:
    void validate();

    const model::Project &m_project;
    model::PouId m_pou;
    model::BodyRef::Part m_part;
    QLineEdit *m_name = nullptr;
    QComboBox *m_language = nullptr;
    QLabel *m_problem = nullptr;
    QDialogButtonBox *m_buttons = nullptr;
};

// Fills a combo box with the languages a body can be written in: the five IEC languages and CFC
// (icon, name, editors::EditorLanguage as data).
void fillLanguageChoice(QComboBox *combo);

} // namespace iec::app
