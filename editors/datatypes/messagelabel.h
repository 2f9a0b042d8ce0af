#pragma once

#include "editors/datatypes/datatypevalidation.h"

#include <QLabel>

#include <vector>

class QFormLayout;
class QLineEdit;

namespace iec::editors {

// A validation message under a field: red, wrapped, hidden while there is nothing to say.
class MessageLabel : public QLabel
{
public:
    explicit MessageLabel(QWidget *parent = nullptr);
    void showMessage(const QString &message);
    // Shows the messages of `field` (the whole field, row -1) from `errors`.
    void showErrors(const std::vector<FormError> &errors, FormField field);
};

// A line edit with its message label below it, as one row of a form layout.
struct CheckedField {
    QLineEdit *edit = nullptr;
    MessageLabel *message = nullptr;
};
CheckedField addCheckedField(QFormLayout *layout, const QString &label, QWidget *parent);

} // namespace iec::editors
