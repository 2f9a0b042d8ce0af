#pragma once

#include "editors/declarations/declarationrows.h"

#include <QDialog>

#include <functional>

class QComboBox;
class QLabel;
class QLineEdit;
class QDialogButtonBox;

namespace iec::app {

// CODESYS's "Declare Variable" dialog: the name, its class, a type (the guess preselected, any
// type text accepted), an initial value and a comment. `check` says what is wrong with a row
// (empty: it can be declared); OK stays disabled while something is.
class AutoDeclareDialog : public QDialog
{
    Q_OBJECT

public:
    AutoDeclareDialog(const editors::DeclarationRow &proposal, QStringList typeNames,
        std::function<QString(const editors::DeclarationRow &)> check, QWidget *parent = nullptr);

    [[nodiscard]] editors::DeclarationRow row() const;

    [[nodiscard]] QLineEdit *nameEdit() const { return m_name; }
    [[nodiscard]] QComboBox *classBox() const { return m_class; }
    [[nodiscard]] QComboBox *typeBox() const { return m_type; }
    [[nodiscard]] QLineEdit *initialValueEdit() const { return m_initialValue; }

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void validate();

    std::function<QString(const editors::DeclarationRow &)> m_check;
    QLineEdit *m_name;
    QComboBox *m_class;
    QComboBox *m_type;
    QLineEdit *m_initialValue;
    QLineEdit *m_comment;
    QLabel *m_problem;
    QDialogButtonBox *m_buttons;
};

} // namespace iec::app
