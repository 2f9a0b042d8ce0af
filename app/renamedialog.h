#pragma once

#include <QDialog>

#include <functional>
#include <optional>

class QDialogButtonBox;
class QLabel;
class QLineEdit;

namespace iec::app {

// Asks for a new name; `check` says why a name cannot be used (nullopt: it can), and OK stays
// disabled until it can.
class RenameDialog : public QDialog
{
    Q_OBJECT

public:
    using Check = std::function<std::optional<QString>(const QString &)>;

    RenameDialog(const QString &currentName, Check check, QWidget *parent = nullptr);

    [[nodiscard]] QString newName() const;
    [[nodiscard]] QString problem() const;

private:
    void validate();

    Check m_check;
    QString m_currentName;
    QLineEdit *m_name = nullptr;
    QLabel *m_problem = nullptr;
    QDialogButtonBox *m_buttons = nullptr;
};

} // namespace iec::app
