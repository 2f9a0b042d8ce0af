#pragma once

#include "editors/text/completion.h"
#include "model/ids.h"

#include <QCoreApplication>
#include <QString>

#include <optional>
#include <vector>

namespace iec::model {
class ProjectModel;
struct DataType;
struct Project;
struct Variable;
enum class VarListKind;
} // namespace iec::model

namespace iec::app {

// A name a POU body can use: one of the POU's own variables or a global variable.
struct VisibleVariable {
    const model::Variable *variable = nullptr;
    model::VarListKind kind;
    bool global = false;
};

// What a body sees, looked up in the model as it is now (nothing cached, so edits elsewhere are
// seen at once): the POU's own declarations first, then the configurations' and resources'
// global variables. Names compare case-insensitively, as IEC names do.
[[nodiscard]] std::vector<VisibleVariable> visibleVariables(const model::Project &project, model::PouId pou);
[[nodiscard]] std::optional<VisibleVariable> findVisibleVariable(
    const model::Project &project, model::PouId pou, const QString &name);

// The declared type of a dotted path ("Tank", "Tank.Level", "Motors[2].Speed", "T1"): array
// indexes step into the element type, members are struct fields or a function block's
// variables. The type's name as written ("TON", "INT", "Tank_t"); empty when unknown.
[[nodiscard]] QString typeNameOfPath(const model::Project &project, model::PouId pou, const QString &path);

// Completion candidates from the project for the POU being edited (the editor adds keywords
// and the standard library itself).
class ModelCompletionProvider : public editors::CompletionProvider
{
    Q_DECLARE_TR_FUNCTIONS(ModelCompletionProvider)

public:
    ModelCompletionProvider(const model::ProjectModel &model, model::PouId pou);

    [[nodiscard]] QList<editors::CompletionItem> variables() const override;
    [[nodiscard]] QList<editors::CompletionItem> members(const QString &path) const override;
    [[nodiscard]] QList<editors::CompletionItem> pous() const override;
    [[nodiscard]] QString typeOf(const QString &path) const override;

private:
    const model::ProjectModel &m_model;
    model::PouId m_pou;
};

} // namespace iec::app
