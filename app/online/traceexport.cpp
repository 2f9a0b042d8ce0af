#include "app/online/traceexport.h"

#include "interpreter/runtime/traceformats.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QPainter>
#include <QPdfWriter>
#include <QSaveFile>
#include <QTextStream>

namespace iec::app {

namespace {

bool writeText(const TraceData &data, bool vcd, const QString &path, QString &error)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        error = QCoreApplication::translate("iec::app::TraceExport", "%1 cannot be written: %2").arg(path, file.errorString());
        return false;
    }
    {
        QTextStream out(&file);
        std::unique_ptr<interp::TraceWriter> writer
            = vcd ? interp::makeVcdWriter(out, data.variables, data.cycleNs, QStringLiteral("IEC Studio"))
                  : interp::makeCsvWriter(out, data.variables);
        writer->begin(data.rows.front());
        for (std::size_t i = 1; i < data.rows.size(); ++i)
            writer->write(data.rows[i]);
    }
    if (!file.commit()) {
        error = QCoreApplication::translate("iec::app::TraceExport", "%1 cannot be written: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

bool writePdf(const QImage &picture, const QString &title, const QString &path, QString &error)
{
    QPdfWriter pdf(path);
    pdf.setPageOrientation(QPageLayout::Landscape);
    pdf.setTitle(title);
    pdf.setCreator(QStringLiteral("IEC Studio"));
    QPainter painter;
    if (!painter.begin(&pdf)) {
        error = QCoreApplication::translate("iec::app::TraceExport", "%1 cannot be written.").arg(path);
        return false;
    }
    const QRect page = painter.viewport();
    QFont font = painter.font();
    font.setPointSize(14);
    font.setBold(true);
    painter.setFont(font);
    const int titleHeight = painter.fontMetrics().height() * 2;
    painter.drawText(QRect(page.left(), page.top(), page.width(), titleHeight), Qt::AlignLeft | Qt::AlignVCenter, title);
    const QSize room(page.width(), page.height() - titleHeight);
    const QSize size = picture.size().scaled(room, Qt::KeepAspectRatio);
    painter.drawImage(QRect(QPoint(page.left(), page.top() + titleHeight), size), picture);
    painter.end();
    return true;
}

} // namespace

bool exportTrace(const TraceData &data, const QImage &picture, const QString &title, const QString &path, QString &error)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (data.rows.empty() || data.variables.empty()) {
        error = QCoreApplication::translate("iec::app::TraceExport", "Nothing was recorded yet: choose variables, log in and run the program.");
        return false;
    }
    if (suffix == QLatin1String("csv") || suffix == QLatin1String("vcd"))
        return writeText(data, suffix == QLatin1String("vcd"), path, error);
    if (suffix == QLatin1String("pdf"))
        return writePdf(picture, title, path, error);
    if (suffix == QLatin1String("png")) {
        if (picture.save(path, "PNG"))
            return true;
        error = QCoreApplication::translate("iec::app::TraceExport", "%1 cannot be written.").arg(path);
        return false;
    }
    error = QCoreApplication::translate("iec::app::TraceExport", "%1: a trace is exported as .csv, .vcd, .png or .pdf.").arg(path);
    return false;
}

} // namespace iec::app
