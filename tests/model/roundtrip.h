#pragma once

#include "model/plcopen/reader.h"

#include <QByteArray>
#include <QString>

// Helpers shared by the PLCopen tests.
namespace iec::test {

// Runs xmllint against the PLCopen XSD; returns its messages, empty when the bytes validate.
QString schemaErrors(const QByteArray &xml);
// The project as File → Save writes it, checked the same way.
QString savedSchemaErrors(const model::Project &project);

// A short description of the first difference between two projects ("" when equal), so a failed
// comparison says where to look.
QString firstDifference(const model::Project &a, const model::Project &b);

QString diagnosticsText(const std::vector<model::Diagnostic> &diagnostics);

QString corpusPath(const QString &file);

} // namespace iec::test
