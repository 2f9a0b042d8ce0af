#pragma once

#include "model/project.h"

#include <QByteArray>
#include <QDateTime>
#include <QString>

namespace iec::model::plcopen {

// Writes PLCopen TC6 XML 2.01 (namespace tc6_0201). Deterministic: the same project always gives
// the same bytes (fixed attribute order, two-space indentation, elements in the XSD's order).
QByteArray writeProject(const Project &project);

// Writes with saveFileAtomically (model/savefile.h), so a failed save leaves the old file as it
// was. On failure returns false and, when `error` is given, a sentence saying why.
// A project saved without a creation time (a new project, or one read from a file that had
// none) is stamped with the time of this save, in UTC: the XSD requires an xsd:dateTime there.
bool saveProjectFile(const Project &project, const QString &path, QString *error = nullptr);

// Sets an empty creationDateTime to `now` (UTC, ISO 8601); a time already there is kept.
void stampCreationTime(FileHeader &header, const QDateTime &now);

} // namespace iec::model::plcopen
