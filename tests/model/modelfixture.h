#pragma once

#include "model/plcopen/reader.h"
#include "model/projectmodel.h"

#include <QFile>

// The every_element.xml fixture loaded into a ProjectModel: a project with every kind of POU,
// body, element and declaration to edit in the model and undo tests.
namespace iec::test {

inline model::Project everyElementProject()
{
    QFile file(QStringLiteral(IEC_SOURCE_DIR "/tests/model/fixtures/every_element.xml"));
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return model::plcopen::readProject(file.readAll()).project;
}

inline model::PouId pouId(const model::ProjectModel &model, const char *name)
{
    const model::Pou *pou = model.project().findPou(QLatin1String(name));
    return pou ? pou->id : model::PouId {};
}

inline model::BodyRef bodyOf(const model::ProjectModel &model, const char *pou)
{
    return {pouId(model, pou), model::BodyRef::Part::Pou, {}};
}

} // namespace iec::test
