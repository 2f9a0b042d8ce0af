#pragma once

#include "editors/datatypes/datatypeform.h"
#include "editors/datatypes/datatypevalidation.h"

#include <QWidget>

#include <vector>

class QComboBox;
class QFormLayout;
class QLineEdit;

namespace iec::editors {

class MessageLabel;
class RowTable;

// The part of the data type editor that belongs to one kind. Loads its fields from a form, stores
// them back into one, shows the messages of its fields, and reports each user gesture as edited().
class KindPage : public QWidget
{
    Q_OBJECT

public:
    using QWidget::QWidget;

    virtual void load(const DataTypeForm &form) = 0;
    virtual void store(DataTypeForm &form) const = 0;
    virtual void showErrors(const std::vector<FormError> &errors) = 0;

Q_SIGNALS:
    void edited();

protected:
    // A line edit and its message label as a row of `layout`; editing it is a gesture.
    QLineEdit *addField(QFormLayout *layout, const QString &label, MessageLabel *&message);
};

// Members: name, type, initial value, comment.
class StructPage : public KindPage
{
    Q_OBJECT

public:
    explicit StructPage(QWidget *parent = nullptr);
    void load(const DataTypeForm &form) override;
    void store(DataTypeForm &form) const override;
    void showErrors(const std::vector<FormError> &errors) override;
    [[nodiscard]] RowTable *members() const { return m_members; }

private:
    RowTable *m_members;
};

// Values with optional explicit numbers, and an optional integer base type.
class EnumPage : public KindPage
{
    Q_OBJECT

public:
    explicit EnumPage(QWidget *parent = nullptr);
    void load(const DataTypeForm &form) override;
    void store(DataTypeForm &form) const override;
    void showErrors(const std::vector<FormError> &errors) override;
    [[nodiscard]] RowTable *values() const { return m_values; }

private:
    RowTable *m_values;
    QLineEdit *m_baseType;
    MessageLabel *m_baseTypeMessage = nullptr;
};

// Dimensions (low..high each) and the element type.
class ArrayPage : public KindPage
{
    Q_OBJECT

public:
    explicit ArrayPage(QWidget *parent = nullptr);
    void load(const DataTypeForm &form) override;
    void store(DataTypeForm &form) const override;
    void showErrors(const std::vector<FormError> &errors) override;
    [[nodiscard]] RowTable *dimensions() const { return m_dimensions; }

private:
    RowTable *m_dimensions;
    QLineEdit *m_elementType;
    MessageLabel *m_elementTypeMessage = nullptr;
};

// An integer base type and its low/high bounds.
class SubrangePage : public KindPage
{
    Q_OBJECT

public:
    explicit SubrangePage(QWidget *parent = nullptr);
    void load(const DataTypeForm &form) override;
    void store(DataTypeForm &form) const override;
    void showErrors(const std::vector<FormError> &errors) override;

private:
    QLineEdit *m_baseType;
    QLineEdit *m_low;
    QLineEdit *m_high;
    MessageLabel *m_baseTypeMessage = nullptr;
    MessageLabel *m_lowMessage = nullptr;
    MessageLabel *m_highMessage = nullptr;
};

// Another name for a type.
class AliasPage : public KindPage
{
    Q_OBJECT

public:
    explicit AliasPage(QWidget *parent = nullptr);
    void load(const DataTypeForm &form) override;
    void store(DataTypeForm &form) const override;
    void showErrors(const std::vector<FormError> &errors) override;

private:
    QLineEdit *m_baseType;
    MessageLabel *m_baseTypeMessage = nullptr;
};

// STRING or WSTRING with an optional length.
class StringPage : public KindPage
{
    Q_OBJECT

public:
    explicit StringPage(QWidget *parent = nullptr);
    void load(const DataTypeForm &form) override;
    void store(DataTypeForm &form) const override;
    void showErrors(const std::vector<FormError> &errors) override;

private:
    QComboBox *m_width;
    QLineEdit *m_length;
    MessageLabel *m_lengthMessage = nullptr;
};

} // namespace iec::editors
