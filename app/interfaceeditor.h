#pragma once

#include "app/adddatatexteditor.h"

namespace iec::app {

// An INTERFACE, which CODESYS keeps in the project's addData, edited as one text
// (interp::frontend::printCodesysInterface): INTERFACE Name [EXTENDS ...], the prototypes of its
// methods and properties, END_INTERFACE. One kept in a configuration's or resource's addData is
// shown, not edited.
class InterfaceEditor : public AddDataTextEditor
{
    Q_OBJECT

public:
    InterfaceEditor(model::ProjectModel &model, const QString &name, QWidget *parent = nullptr);

    [[nodiscard]] QString title() const override { return name(); }

protected:
    [[nodiscard]] Reading read(const QString &text) const override;
    [[nodiscard]] const model::AddData *kept() const override;
    [[nodiscard]] QString print(bool *editable) const override;
    void store(const model::AddData &addData) override;
};

} // namespace iec::app
