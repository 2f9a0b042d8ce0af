#pragma once

#include "model/project.h"

#include <QByteArray>
#include <QString>

namespace iec::model::plcopen {

// Writes PLCopen TC6 XML 2.01 (namespace tc6_0201). Deterministic: the same project always gives
// the same bytes (fixed attribute order, two-space indentation, elements in the XSD's order).
QByteArray writeProject(const Project &project);

// Writes with saveFileAtomically (model/savefile.h), so a failed save leaves the old file as it
// was. On failure returns false and, when `error` is given, a sentence saying why.
bool saveProjectFile(const Project &project, const QString &path, QString *error = nullptr);

} // namespace iec::model::plcopen
