#pragma once

#include "app/online/tracechart.h"

#include <QImage>
#include <QString>

namespace iec::app {

// Writes a recorded trace by the file's suffix: .csv and .vcd as `iecstudio-cli run --trace`
// writes them (interp::makeCsvWriter, makeVcdWriter), .png as the picture of the lanes, .pdf
// as a page with a title and that picture, for lab reports. False and `error` (a sentence)
// when the file cannot be written or nothing was recorded; an old file is then left as it was.
bool exportTrace(const TraceData &data, const QImage &picture, const QString &title, const QString &path,
                 QString &error);

} // namespace iec::app
