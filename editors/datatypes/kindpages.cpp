#include "editors/datatypes/kindpages.h"

#include "editors/datatypes/messagelabel.h"
#include "editors/datatypes/rowtable.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QVBoxLayout>

#include <algorithm>

namespace iec::editors {

namespace {

// The table's messages: `whole` for the table as a whole, `columns[i]` for cells of column i.
std::vector<RowTable::CellMessage> cellMessages(
    const std::vector<FormError> &errors, FormField whole, const std::vector<FormField> &columns)
{
    std::vector<RowTable::CellMessage> messages;
    for (const FormError &error : errors) {
        if (error.field == whole) {
            messages.push_back({-1, 0, error.message});
            continue;
        }
        const auto column = std::find(columns.begin(), columns.end(), error.field);
        if (column != columns.end())
            messages.push_back({error.row, int(column - columns.begin()), error.message});
    }
    return messages;
}

QFormLayout *formLayout()
{
    auto *layout = new QFormLayout;
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setFieldGrowthPolicy(QFormLayout::ExpandingFieldsGrow);
    return layout;
}

// A page made of a titled table above a form.
QFormLayout *tableAndForm(QWidget *page, const QString &title, RowTable *table)
{
    auto *layout = new QVBoxLayout(page);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(new QLabel(title, page));
    layout->addWidget(table, 1);
    QFormLayout *form = formLayout();
    layout->addLayout(form);
    return form;
}

QFormLayout *formOnly(QWidget *page)
{
    auto *layout = new QVBoxLayout(page);
    layout->setContentsMargins(0, 0, 0, 0);
    QFormLayout *form = formLayout();
    layout->addLayout(form);
    layout->addStretch();
    return form;
}

} // namespace

QLineEdit *KindPage::addField(QFormLayout *layout, const QString &label, MessageLabel *&message)
{
    const CheckedField field = addCheckedField(layout, label, this);
    message = field.message;
    connect(field.edit, &QLineEdit::editingFinished, this, &KindPage::edited);
    return field.edit;
}

// ---- struct

StructPage::StructPage(QWidget *parent)
    : KindPage(parent)
    , m_members(new RowTable({tr("Name"), tr("Type"), tr("Initial value"), tr("Comment")}, this))
{
    m_members->setNewRow({QString(), QStringLiteral("INT"), QString(), QString()});
    tableAndForm(this, tr("Members"), m_members);
    connect(m_members, &RowTable::edited, this, &KindPage::edited);
}

void StructPage::load(const DataTypeForm &form)
{
    std::vector<RowTable::Row> rows;
    for (const MemberRow &member : form.members)
        rows.push_back({{member.name, member.type, member.initialValue, member.comment}, member.origin});
    m_members->setRows(rows);
}

void StructPage::store(DataTypeForm &form) const
{
    form.members.clear();
    for (const RowTable::Row &row : m_members->rows())
        form.members.push_back({row.cells[0], row.cells[1], row.cells[2], row.cells[3], row.tag});
}

void StructPage::showErrors(const std::vector<FormError> &errors)
{
    m_members->showMessages(cellMessages(
        errors, FormField::Members, {FormField::MemberName, FormField::MemberType, FormField::MemberValue}));
}

// ---- enum

EnumPage::EnumPage(QWidget *parent)
    : KindPage(parent)
    , m_values(new RowTable({tr("Name"), tr("Value (optional)")}, this))
{
    QFormLayout *form = tableAndForm(this, tr("Values"), m_values);
    m_baseType = addField(form, tr("Base type (optional):"), m_baseTypeMessage);
    m_baseType->setPlaceholderText(QStringLiteral("INT"));
    connect(m_values, &RowTable::edited, this, &KindPage::edited);
}

void EnumPage::load(const DataTypeForm &form)
{
    std::vector<RowTable::Row> rows;
    for (const EnumRow &value : form.enumValues)
        rows.push_back({{value.name, value.value}, -1});
    m_values->setRows(rows);
    m_baseType->setText(form.enumBaseType);
}

void EnumPage::store(DataTypeForm &form) const
{
    form.enumValues.clear();
    for (const RowTable::Row &row : m_values->rows())
        form.enumValues.push_back({row.cells[0], row.cells[1]});
    form.enumBaseType = m_baseType->text();
}

void EnumPage::showErrors(const std::vector<FormError> &errors)
{
    m_values->showMessages(cellMessages(errors, FormField::EnumValues, {FormField::EnumName, FormField::EnumValue}));
    m_baseTypeMessage->showErrors(errors, FormField::EnumBaseType);
}

// ---- array

ArrayPage::ArrayPage(QWidget *parent)
    : KindPage(parent)
    , m_dimensions(new RowTable({tr("Low"), tr("High")}, this))
{
    m_dimensions->setNewRow({QStringLiteral("1"), QStringLiteral("10")});
    QFormLayout *form = tableAndForm(this, tr("Dimensions"), m_dimensions);
    m_elementType = addField(form, tr("Element type:"), m_elementTypeMessage);
    connect(m_dimensions, &RowTable::edited, this, &KindPage::edited);
}

void ArrayPage::load(const DataTypeForm &form)
{
    std::vector<RowTable::Row> rows;
    for (const model::Range &range : form.dimensions)
        rows.push_back({{range.lower, range.upper}, -1});
    m_dimensions->setRows(rows);
    m_elementType->setText(form.elementType);
}

void ArrayPage::store(DataTypeForm &form) const
{
    form.dimensions.clear();
    for (const RowTable::Row &row : m_dimensions->rows())
        form.dimensions.push_back({row.cells[0], row.cells[1]});
    form.elementType = m_elementType->text();
}

void ArrayPage::showErrors(const std::vector<FormError> &errors)
{
    m_dimensions->showMessages(
        cellMessages(errors, FormField::Dimensions, {FormField::DimensionLow, FormField::DimensionHigh}));
    m_elementTypeMessage->showErrors(errors, FormField::ElementType);
}

// ---- subrange

SubrangePage::SubrangePage(QWidget *parent)
    : KindPage(parent)
{
    QFormLayout *form = formOnly(this);
    m_baseType = addField(form, tr("Base type:"), m_baseTypeMessage);
    m_low = addField(form, tr("Low:"), m_lowMessage);
    m_high = addField(form, tr("High:"), m_highMessage);
}

void SubrangePage::load(const DataTypeForm &form)
{
    m_baseType->setText(form.baseType);
    m_low->setText(form.range.lower);
    m_high->setText(form.range.upper);
}

void SubrangePage::store(DataTypeForm &form) const
{
    form.baseType = m_baseType->text();
    form.range = {m_low->text(), m_high->text()};
}

void SubrangePage::showErrors(const std::vector<FormError> &errors)
{
    m_baseTypeMessage->showErrors(errors, FormField::BaseType);
    m_lowMessage->showErrors(errors, FormField::RangeLow);
    m_highMessage->showErrors(errors, FormField::RangeHigh);
}

// ---- alias

AliasPage::AliasPage(QWidget *parent)
    : KindPage(parent)
{
    m_baseType = addField(formOnly(this), tr("Base type:"), m_baseTypeMessage);
}

void AliasPage::load(const DataTypeForm &form)
{
    m_baseType->setText(form.baseType);
}

void AliasPage::store(DataTypeForm &form) const
{
    form.baseType = m_baseType->text();
}

void AliasPage::showErrors(const std::vector<FormError> &errors)
{
    m_baseTypeMessage->showErrors(errors, FormField::BaseType);
}

// ---- string

StringPage::StringPage(QWidget *parent)
    : KindPage(parent)
    , m_width(new QComboBox(this))
{
    QFormLayout *form = formOnly(this);
    m_width->addItem(QStringLiteral("STRING"));
    m_width->addItem(QStringLiteral("WSTRING"));
    form->addRow(tr("Characters:"), m_width);
    connect(m_width, &QComboBox::activated, this, &KindPage::edited);
    m_length = addField(form, tr("Length (optional):"), m_lengthMessage);
    m_length->setPlaceholderText(QStringLiteral("80"));
}

void StringPage::load(const DataTypeForm &form)
{
    m_width->setCurrentIndex(form.wideString ? 1 : 0);
    m_length->setText(form.stringLength);
}

void StringPage::store(DataTypeForm &form) const
{
    form.wideString = m_width->currentIndex() == 1;
    form.stringLength = m_length->text();
}

void StringPage::showErrors(const std::vector<FormError> &errors)
{
    m_lengthMessage->showErrors(errors, FormField::StringLength);
}

} // namespace iec::editors
