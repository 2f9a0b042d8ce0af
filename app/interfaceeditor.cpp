#include "app/interfaceeditor.h"

#include "app/namerules.h"
#include "editors/text/codeeditor.h"
#include "interpreter/frontend/codesysmembers.h"
#include "interpreter/frontend/iecreader.h"
#include "model/plcopen/codesysoop.h"
#include "model/projectmodel.h"

namespace iec::app {

InterfaceEditor::InterfaceEditor(model::ProjectModel &model, const QString &name, QWidget *parent)
    : AddDataTextEditor(model, name, parent)
{
    setObjectName(QStringLiteral("interfaceEditor"));
    load();
    connect(&model, &model::ProjectModel::projectAddDataChanged, this, &InterfaceEditor::followModel);
}

const model::AddData *InterfaceEditor::kept() const
{
    return &m_model.project().addData;
}

QString InterfaceEditor::print(bool *editable) const
{
    const model::Project &project = m_model.project();
    if (editable)
        *editable = model::plcopen::keepsInterface(project.addData, name());
    return interp::frontend::printCodesysInterface(project, name());
}

void InterfaceEditor::store(const model::AddData &addData)
{
    m_model.setProjectAddData(addData);
}

AddDataTextEditor::Reading InterfaceEditor::read(const QString &text) const
{
    const interp::frontend::InterfaceText read = interp::frontend::readInterfaceText(text);
    Reading reading;
    reading.marks = marksOf(read.diagnostics);
    if (!read.definition)
        return reading;
    const model::Project &project = m_model.project();
    if (const auto problem = NameRules::interfaceNameError(project, read.definition->name, name())) {
        editors::TextDiagnostic mark;
        mark.message = *problem;
        reading.marks << mark;
        return reading;
    }
    reading.addData = model::plcopen::addDataWithInterface(project.addData, name(), *read.definition);
    reading.name = read.definition->name;
    return reading;
}

} // namespace iec::app
