#include "editors/common/diagramexport.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QGraphicsItem>
#include <QGraphicsScene>
#include <QImage>
#include <QPainter>
#include <QPdfWriter>
#include <QPrinter>
#include <QSvgGenerator>

namespace iec::editors {

namespace {

// Selection marks are for the screen, not for a document.
class SelectionHidden
{
public:
    explicit SelectionHidden(QGraphicsScene &scene)
        : m_scene(scene)
        , m_selected(scene.selectedItems())
    {
        m_scene.clearSelection();
    }
    ~SelectionHidden()
    {
        for (QGraphicsItem *item : m_selected)
            item->setSelected(true);
    }
    SelectionHidden(const SelectionHidden &) = delete;
    SelectionHidden &operator=(const SelectionHidden &) = delete;

private:
    QGraphicsScene &m_scene;
    QList<QGraphicsItem *> m_selected;
};

QRectF drawingRect(QGraphicsScene &scene)
{
    return scene.itemsBoundingRect().adjusted(-10, -10, 10, 10);
}

void render(QGraphicsScene &scene, QPainter &painter, const QRectF &target, const QRectF &source)
{
    painter.setRenderHint(QPainter::Antialiasing);
    painter.fillRect(target, Qt::white);
    scene.render(&painter, target, source, Qt::KeepAspectRatio);
}

} // namespace

QString exportScene(QGraphicsScene &scene, const QString &path)
{
    const SelectionHidden hidden(scene);
    const QRectF source = drawingRect(scene);
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == QLatin1String("svg")) {
        QSvgGenerator generator;
        generator.setFileName(path);
        generator.setSize(source.size().toSize());
        generator.setViewBox(QRectF(QPointF(0, 0), source.size()));
        generator.setTitle(QFileInfo(path).completeBaseName());
        QPainter painter;
        if (!painter.begin(&generator))
            return QCoreApplication::translate("iec::editors::DiagramExport", "Cannot write %1.").arg(path);
        render(scene, painter, QRectF(QPointF(0, 0), source.size()), source);
        painter.end();
        return QFileInfo::exists(path) ? QString() : QCoreApplication::translate("iec::editors::DiagramExport", "Cannot write %1.").arg(path);
    }
    if (suffix == QLatin1String("png")) {
        constexpr double scale = 2; // crisp on paper and on high-density screens
        QImage image((source.size() * scale).toSize(), QImage::Format_ARGB32);
        image.fill(Qt::white);
        QPainter painter(&image);
        render(scene, painter, QRectF(QPointF(0, 0), source.size() * scale), source);
        painter.end();
        return image.save(path) ? QString() : QCoreApplication::translate("iec::editors::DiagramExport", "Cannot write %1.").arg(path);
    }
    if (suffix == QLatin1String("pdf")) {
        QPdfWriter writer(path);
        writer.setTitle(QFileInfo(path).completeBaseName());
        writer.setPageSize(QPageSize(QPageSize::A4));
        writer.setPageOrientation(source.width() > source.height() ? QPageLayout::Landscape : QPageLayout::Portrait);
        QPainter painter;
        if (!painter.begin(&writer))
            return QCoreApplication::translate("iec::editors::DiagramExport", "Cannot write %1.").arg(path);
        const QRectF page = QRectF(painter.viewport());
        render(scene, painter, page, source);
        painter.end();
        return QString();
    }
    return QCoreApplication::translate("iec::editors::DiagramExport", "Unknown picture type '%1': use .svg, .png or .pdf.").arg(suffix);
}

void printScene(QGraphicsScene &scene, QPrinter &printer)
{
    const SelectionHidden hidden(scene);
    QPainter painter(&printer);
    render(scene, painter, QRectF(painter.viewport()), drawingRect(scene));
}

} // namespace iec::editors
