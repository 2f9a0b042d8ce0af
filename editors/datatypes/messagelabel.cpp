#include "editors/datatypes/messagelabel.h"

#include <QFormLayout>
#include <QLineEdit>
#include <QVBoxLayout>

namespace iec::editors {

MessageLabel::MessageLabel(QWidget *parent)
    : QLabel(parent)
{
    setWordWrap(true);
    setStyleSheet(QStringLiteral("color: #c62828;"));
    setTextFormat(Qt::PlainText);
    hide();
}

void MessageLabel::showMessage(const QString &message)
{
    setText(message);
    setVisible(!message.isEmpty());
}

void MessageLabel::showErrors(const std::vector<FormError> &errors, FormField field)
{
    QStringList messages;
    for (const FormError &error : errors) {
        if (error.field == field && error.row < 0)
            messages << error.message;
    }
    showMessage(messages.join(QLatin1Char('\n')));
}

CheckedField addCheckedField(QFormLayout *layout, const QString &label, QWidget *parent)
{
    auto *box = new QWidget(parent);
    auto *column = new QVBoxLayout(box);
    column->setContentsMargins(0, 0, 0, 0);
    column->setSpacing(2);
    CheckedField field {new QLineEdit(box), new MessageLabel(box)};
    column->addWidget(field.edit);
    column->addWidget(field.message);
    layout->addRow(label, box);
    return field;
}

} // namespace iec::editors
