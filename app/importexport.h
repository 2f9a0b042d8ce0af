#pragma once

#include "app/messagespane.h"
#include "model/ids.h"
#include "model/project.h"

#include <QCoreApplication>
#include <QList>
#include <QString>

#include <optional>
#include <vector>

class QUndoCommand;

namespace iec::model {
class ProjectModel;
}

namespace iec::app {

// File → Import and File → Export without dialogs (MainWindow wraps them; tests call them).
class ImportExport
{
    Q_DECLARE_TR_FUNCTIONS(ImportExport)

public:
    enum class Format { PlcOpenXml, IecText };

    // The format a file name says (.st, .iec, .txt: IEC text; anything else PLCopen XML).
    [[nodiscard]] static Format formatOf(const QString &path);

    struct Read {
        std::optional<model::Project> project; // empty when nothing could be read
        QList<Message> messages; // the reader's diagnostics, located in the file
        // Every part of the file is in `project`: no error but the text's own {error} pragmas
        // (such as the one over a body CoDeSys 2.3 exported in its graphical form).
        bool whole = true;
    };
    // Reads a PLCopen XML file (from any tool) or IEC 61131-3 text.
    [[nodiscard]] static Read read(const QString &path);

    struct Merge {
        QUndoCommand *command = nullptr; // one undo step; nullptr when there is nothing to add
        QList<Message> messages; // what was renamed or left out, one sentence each
        int pous = 0;
        int dataTypes = 0;
        int configurations = 0; // imported configurations merged into the project's
    };
    // Adds the imported data types, POUs and configurations to the project in one undo step. A
    // POU, data type or global variable whose name is taken gets the first free "<name>_N" (and
    // says so); the imported bodies, declarations and tasks follow the new names.
    // Configurations merge as mergeConfigurations says.
    [[nodiscard]] static Merge merge(model::ProjectModel &model, const model::Project &imported);
    // Adds imported configurations to `into`: one with the name of a project configuration joins
    // it, any other joins the project's first (only that one runs), and a project without
    // configurations takes them as they are. Resources of the same name merge their global
    // variables, tasks and program instances (a taken task or instance name gets a free one);
    // other resources are added. The globals are expected free of clashes already (merge()).
    static void mergeConfigurations(model::Instances &into, const model::Instances &imported, QList<Message> &messages);

    // The project, or only `pous` (with every data type, which they may use), as PLCopen XML or
    // IEC text; written atomically. False with a sentence in `error` when the file cannot be written.
    static bool write(const model::Project &project, const std::vector<model::PouId> &pous, Format format,
        const QString &path, QString *error = nullptr, QList<Message> *warnings = nullptr);
    // The part of the project that write() exports.
    [[nodiscard]] static model::Project selection(const model::Project &project, const std::vector<model::PouId> &pous);
};

} // namespace iec::app
