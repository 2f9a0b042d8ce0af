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

// Project → Add POU: name, kind, language and (for functions) the return type. OK stays disabled
// while the name is not a free IEC identifier; the label under the fields says why.
class AddPouDialog : public QDialog
{
    Q_OBJECT

public:
    explicit AddPouDialog(const model::Project &project, QWidget *parent = nullptr);

    [[nodiscard]] NewPou newPou() const;
    // Why the input cannot be accepted; empty when it can.
    [[nodiscard]] QString problem() const;

private:
    void validate();
    [[nodiscard]] bool newPouIsFunction() const;

    const model::Project &m_project;
    QLineEdit *m_name = nullptr;
    QComboBox *m_kind = nullptr;
    QComboBox *m_language = nullptr;
    QComboBox *m_returnType = nullptr;
    QLabel *m_problem = nullptr;
    QDialogButtonBox *m_buttons = nullptr;
};

} // namespace iec::app
