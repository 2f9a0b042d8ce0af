#pragma once

#include "model/ids.h"

#include <QCoreApplication>
#include <QImage>
#include <QString>

#include <functional>
#include <memory>
#include <vector>

class QPagedPaintDevice;
class QPrinter;
class QTextDocument;

namespace iec::model {
class ProjectModel;
}

namespace iec::app {

// File → Print Documentation and Export Documentation as PDF: the whole project as a document for
// lab reports and handing in. A cover page (project, author, date), a table of contents with page
// numbers, then each POU (its declarations, its body as text or as a picture, its actions and
// transitions), the data types, the global variable lists and the configurations with their
// tasks. Each part starts on a new page.
class ProjectDocumentation
{
    Q_DECLARE_TR_FUNCTIONS(iec::app::ProjectDocumentation)

public:
    // A picture of a diagram body (LD, FBD, CFC, SFC); a null image when there is none (the
    // document says so in a line instead). The default draws it as its editor does, through the
    // editor registry's policy, as `iecstudio-cli render` does.
    using BodyPicture = std::function<QImage(model::ProjectModel &, const model::BodyRef &)>;

    // Reads `model` only (a diagram scene needs it writable).
    explicit ProjectDocumentation(model::ProjectModel &model, BodyPicture picture = defaultBodyPicture);

    // The document laid out for `printer`'s pages, with the contents' page numbers filled in.
    [[nodiscard]] std::unique_ptr<QTextDocument> document(QPrinter &printer) const;
    // Prints on `printer` (a PDF when its output format says so), with page numbers at the bottom.
    void print(QPrinter &printer) const;
    // Writes a PDF; an empty string or why it failed.
    [[nodiscard]] QString exportPdf(const QString &path) const;

    // The HTML before pagination (for tests): the contents carry page number placeholders.
    [[nodiscard]] QString html() const;
    // The titles of the contents, in order.
    [[nodiscard]] QStringList contents() const;

    [[nodiscard]] static QImage defaultBodyPicture(model::ProjectModel &model, const model::BodyRef &ref);

private:
    struct Section;
    [[nodiscard]] std::vector<Section> sections() const;
    [[nodiscard]] QString htmlWithPages(const std::vector<Section> &parts, const std::vector<int> &pages) const;
    static void addImages(QTextDocument &document, const std::vector<Section> &parts);

    model::ProjectModel &m_model;
    BodyPicture m_picture;
};

} // namespace iec::app
