#pragma once

#include "model/diagnostic.h"
#include "model/project.h"

#include <QByteArray>
#include <QString>

#include <vector>

namespace iec::model::plcopen {

struct ReadResult {
    Project project;
    std::vector<Diagnostic> diagnostics;
    bool ok = false; // a PLCopen project was read and no diagnostic is an error
    bool fileError = false; // the file could not be opened or read at all
    bool isProject = false; // well-formed XML with a <project> root (possibly with errors inside)

    [[nodiscard]] bool hasErrors() const;
};

// Reads PLCopen TC6 XML (namespaces tc6_0201, tc6_0200 or none). Never throws and never stops at
// the first problem: whatever cannot be used is reported in `diagnostics` with its line.
// POUs and data types that CODESYS/TwinCAT keep in addData are read into the model (see
// Pou::addDataSlot); diagrams whose positions are all (0,0) get a generated layout.
ReadResult readProject(const QByteArray &bytes);
ReadResult readProjectFile(const QString &path);

} // namespace iec::model::plcopen
