#pragma once

#include <QByteArray>
#include <QString>

namespace iec::model {

// The one way IEC Studio writes a file (projects, autosaves, exports, iecstudio-cli convert):
// the bytes go to a temporary file beside `path`, which is flushed to the disk and then renamed
// over the old file, so the file is always either the old one or the new one, never a part. On
// failure the old file is untouched, the temporary file is gone, and `error` (when given) holds a
// sentence naming the file and the reason: the disk is full, the folder is read-only, ...
bool saveFileAtomically(const QString &path, const QByteArray &bytes, QString *error = nullptr);

} // namespace iec::model
