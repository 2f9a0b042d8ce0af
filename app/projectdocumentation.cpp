#include "app/projectdocumentation.h"

#include "editors/declarations/declarationtext.h"
#include "editors/globals/globallists.h"
#include "editors/common/diagramscene.h"
#include "editors/common/editorregistry.h"
#include "editors/standardeditors.h"
#include "editors/tasks/taskrows.h"
#include "interpreter/frontend/iecprinter.h"
#include "model/projectmodel.h"

#include <QAbstractTextDocumentLayout>
#include <QDate>
#include <QLocale>
#include <QPainter>
#include <QPrinter>
#include <QTextBlock>
#include <QTextDocument>
#include <QTextFrame>
#include <QUrl>

namespace iec::app {

using model::BodyRef;

struct ProjectDocumentation::Section {
    QString title;
    QString html;
    std::vector<std::pair<QString, QImage>> images; // resource name, picture
};

namespace {

// Widest picture on the page, in document pixels (an A4 page less its margins).
constexpr int kPictureWidth = 620;

QString escaped(const QString &text)
{
    return text.toHtmlEscaped();
}

QString pre(const QString &text)
{
    // pre-wrap: a long declaration comment wraps at the margin instead of running off the page.
    return QStringLiteral("<pre style=\"white-space: pre-wrap; font-family: monospace; font-size: 9pt;\">%1</pre>").arg(escaped(text));
}

QString kindText(model::PouKind kind)
{
    switch (kind) {
    case model::PouKind::Program:
        return ProjectDocumentation::tr("program");
    case model::PouKind::FunctionBlock:
        return ProjectDocumentation::tr("function block");
    case model::PouKind::Function:
        return ProjectDocumentation::tr("function");
    }
    return {};
}

QString anchorOf(int section)
{
    return QStringLiteral("section%1").arg(section);
}

// The page (1-based) each section's heading lands on when QTextDocument::print lays the document
// out on `printer` (a copy on the printer's page with 2 cm margins: Qt's own rule for a document
// that has no page size).
std::vector<int> headingPages(QTextDocument &document, QPrinter &printer, int sections)
{
    document.documentLayout()->setPaintDevice(&printer);
    const int dpi = printer.logicalDpiY();
    QTextFrameFormat format = document.rootFrame()->frameFormat();
    format.setMargin(int((2 / 2.54) * dpi));
    document.rootFrame()->setFrameFormat(format);
    const QSizeF page(printer.width(), printer.height());
    document.setPageSize(page);
    std::vector<int> pages(size_t(sections), 0);
    for (QTextBlock block = document.begin(); block.isValid(); block = block.next()) {
        for (QTextBlock::iterator it = block.begin(); !it.atEnd(); ++it) {
            for (const QString &name : it.fragment().charFormat().anchorNames()) {
                bool ok = false;
                const int section = name.mid(int(QStringLiteral("section").size())).toInt(&ok);
                if (ok && section >= 0 && section < sections)
                    pages[size_t(section)] = int(document.documentLayout()->blockBoundingRect(block).top() / page.height()) + 1;
            }
        }
    }
    return pages;
}

} // namespace

ProjectDocumentation::ProjectDocumentation(model::ProjectModel &model, BodyPicture picture)
    : m_model(model)
    , m_picture(std::move(picture))
{
}

QImage ProjectDocumentation::defaultBodyPicture(model::ProjectModel &model, const BodyRef &ref)
{
    const model::Body *body = model.body(ref);
    editors::registerStandardEditors();
    const editors::EditorFactory *factory = body ? editors::EditorRegistry::instance().forBody(*body) : nullptr;
    if (!factory || !factory->createPolicy)
        return {};
    const std::unique_ptr<editors::DiagramPolicy> policy = factory->createPolicy();
    editors::DiagramScene scene(model, ref, *policy);
    scene.rebuild();
    const QRectF source = scene.itemsBoundingRect().adjusted(-10, -10, 10, 10);
    if (source.isEmpty())
        return {};
    // Twice the scene's size, so the print stays sharp.
    QImage image((source.size() * 2).toSize(), QImage::Format_ARGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    scene.render(&painter, QRectF(image.rect()), source, Qt::KeepAspectRatio);
    return image;
}

std::vector<ProjectDocumentation::Section> ProjectDocumentation::sections() const
{
    const model::Project &project = m_model.project();
    std::vector<Section> result;
    const auto bodyHtml = [&](Section &section, const BodyRef &ref, const model::Body &body) {
        // A diagram is drawn, also CODESYS's CFC (an empty ST body with the chart in addData).
        const editors::EditorLanguage language = editors::editorLanguage(body);
        if (language == editors::EditorLanguage::ST || language == editors::EditorLanguage::IL)
            return body.text().trimmed().isEmpty() ? QStringLiteral("<p><i>%1</i></p>").arg(tr("The body is empty."))
                                                   : pre(body.text());
        const QImage picture = m_picture ? m_picture(m_model, ref) : QImage();
        const bool empty = body.isGraphical() && body.elements() && body.elements()->empty();
        if (picture.isNull() && empty)
            return QStringLiteral("<p><i>%1</i></p>").arg(tr("The body is empty."));
        if (picture.isNull())
            return QStringLiteral("<p><i>%1</i></p>")
                .arg(tr("The %1 body is drawn in the editor; this version cannot print it as a picture.").arg(editors::editorLanguageName(language)));
        const QString name = QStringLiteral("body%1.png").arg(result.size() * 100 + section.images.size());
        section.images.emplace_back(name, picture);
        const int width = std::min(kPictureWidth, picture.width() / 2);
        return QStringLiteral("<p><img src=\"%1\" width=\"%2\"></p>").arg(name).arg(width);
    };
    for (const model::Pou &pou : project.types.pous) {
        Section section;
        section.title = tr("%1 (%2, %3)").arg(pou.name, kindText(pou.kind),
            pou.body() ? editors::editorLanguageName(editors::editorLanguage(*pou.body())) : interp::frontend::languageName(pou.language()));
        QString &html = section.html;
        if (pou.documentation && !pou.documentation->text.trimmed().isEmpty())
            html += QStringLiteral("<p>%1</p>").arg(escaped(pou.documentation->text));
        html += QStringLiteral("<h3>%1</h3>").arg(tr("Declarations"));
        const model::Interface declarations = pou.pouInterface.value_or(model::Interface {});
        if (pou.kind == model::PouKind::Function && declarations.returnType)
            html += QStringLiteral("<p>%1</p>").arg(
                escaped(tr("Returns %1.").arg(interp::frontend::printDataType(*declarations.returnType))));
        html += declarations.varLists.empty() ? QStringLiteral("<p><i>%1</i></p>").arg(tr("No variables."))
                                              : pre(editors::declarationText(declarations));
        html += QStringLiteral("<h3>%1</h3>").arg(tr("Body"));
        if (const model::Body *body = pou.body())
            html += bodyHtml(section, {pou.id, BodyRef::Part::Pou, {}}, *body);
        for (const model::PouPart &action : pou.actions) {
            html += QStringLiteral("<h3>%1</h3>").arg(escaped(tr("Action %1").arg(action.name)));
            html += bodyHtml(section, {pou.id, BodyRef::Part::Action, action.name}, action.body);
        }
        for (const model::PouPart &transition : pou.transitions) {
            html += QStringLiteral("<h3>%1</h3>").arg(escaped(tr("Transition %1").arg(transition.name)));
            html += bodyHtml(section, {pou.id, BodyRef::Part::Transition, transition.name}, transition.body);
        }
        result.push_back(std::move(section));
    }
    if (!project.types.dataTypes.empty()) {
        Section section {tr("Data types"), {}, {}};
        for (const model::DataTypeDecl &type : project.types.dataTypes)
            section.html += QStringLiteral("<h3>%1</h3>").arg(escaped(type.name)) + pre(interp::frontend::printTypeDeclaration(type));
        result.push_back(std::move(section));
    }
    const std::vector<editors::GlobalListRef> lists = editors::globalLists(project.instances);
    if (!lists.empty()) {
        Section section {tr("Global variables"), {}, {}};
        for (const editors::GlobalListRef &list : lists) {
            const QString owner = list.resource.isEmpty() ? list.configuration : list.configuration + QLatin1Char('.') + list.resource;
            section.html += QStringLiteral("<h3>%1</h3>").arg(escaped(tr("%1 (in %2)").arg(list.displayName(), owner)));
            section.html += pre(editors::declarationText(editors::globalListDeclarations(project.instances, list)));
        }
        result.push_back(std::move(section));
    }
    for (const model::Configuration &configuration : project.instances.configurations) {
        Section section {tr("Configuration %1").arg(configuration.name), {}, {}};
        for (const model::Resource &resource : configuration.resources) {
            section.html += QStringLiteral("<h3>%1</h3>").arg(escaped(tr("Resource %1").arg(resource.name)));
            if (resource.tasks.empty()) {
                section.html += QStringLiteral("<p><i>%1</i></p>").arg(tr("No tasks."));
                continue;
            }
            section.html += QStringLiteral("<table border=\"1\" cellspacing=\"0\" cellpadding=\"4\"><tr>");
            for (const QString &header : {tr("Task"), tr("Interval"), tr("SINGLE"), tr("Priority"), tr("Watchdog"), tr("Programs")})
                section.html += QStringLiteral("<th>%1</th>").arg(escaped(header));
            section.html += QStringLiteral("</tr>");
            for (const model::Task &task : resource.tasks) {
                QStringList programs;
                for (const model::PouInstance &instance : task.pouInstances)
                    programs << instance.name + QStringLiteral(" : ") + instance.typeName;
                const QStringList cells {task.name, editors::shownTime(task.interval.value_or(QString())),
                    task.single.value_or(QString()), QString::number(task.priority), editors::taskWatchdog(task),
                    programs.join(QStringLiteral(", "))};
                section.html += QStringLiteral("<tr>");
                for (const QString &cell : cells)
                    section.html += QStringLiteral("<td>%1</td>").arg(escaped(cell));
                section.html += QStringLiteral("</tr>");
            }
            section.html += QStringLiteral("</table>");
        }
        result.push_back(std::move(section));
    }
    return result;
}

QStringList ProjectDocumentation::contents() const
{
    QStringList titles;
    for (const Section &section : sections())
        titles << section.title;
    return titles;
}

QString ProjectDocumentation::htmlWithPages(const std::vector<Section> &parts, const std::vector<int> &pages) const
{
    const model::Project &project = m_model.project();
    const QString name = project.contentHeader.name.isEmpty() ? tr("Untitled project") : project.contentHeader.name;
    QString html = QStringLiteral("<html><body>");
    // The cover page.
    html += QStringLiteral("<p style=\"margin-top: 200px; font-size: 28pt; font-weight: bold;\" align=\"center\">%1</p>").arg(escaped(name));
    html += QStringLiteral("<p align=\"center\" style=\"font-size: 14pt;\">%1</p>").arg(tr("Project documentation"));
    QStringList facts;
    if (project.contentHeader.author && !project.contentHeader.author->isEmpty())
        facts << tr("Author: %1").arg(*project.contentHeader.author);
    if (project.contentHeader.organization && !project.contentHeader.organization->isEmpty())
        facts << tr("Organization: %1").arg(*project.contentHeader.organization);
    if (project.contentHeader.version && !project.contentHeader.version->isEmpty())
        facts << tr("Version: %1").arg(*project.contentHeader.version);
    facts << tr("Printed on %1").arg(QLocale().toString(QDate::currentDate(), QLocale::LongFormat));
    for (const QString &fact : std::as_const(facts))
        html += QStringLiteral("<p align=\"center\">%1</p>").arg(escaped(fact));
    // The contents.
    html += QStringLiteral("<h1 style=\"page-break-before: always;\">%1</h1><table width=\"100%\">").arg(tr("Contents"));
    for (size_t i = 0; i < parts.size(); ++i) {
        html += QStringLiteral("<tr><td>%1</td><td align=\"right\">%2</td></tr>")
                    .arg(escaped(parts[i].title))
                    .arg(i < pages.size() && pages[i] > 0 ? QString::number(pages[i]) : QStringLiteral("00"));
    }
    html += QStringLiteral("</table>");
    for (size_t i = 0; i < parts.size(); ++i) {
        html += QStringLiteral("<h1 style=\"page-break-before: always;\"><a name=\"%1\"></a>%2</h1>")
                    .arg(anchorOf(int(i)), escaped(parts[i].title));
        html += parts[i].html;
    }
    return html + QStringLiteral("</body></html>");
}

QString ProjectDocumentation::html() const
{
    return htmlWithPages(sections(), {});
}

void ProjectDocumentation::addImages(QTextDocument &document, const std::vector<Section> &parts)
{
    for (const Section &section : parts) {
        for (const auto &[name, image] : section.images)
            document.addResource(QTextDocument::ImageResource, QUrl(name), image);
    }
}

std::unique_ptr<QTextDocument> ProjectDocumentation::document(QPrinter &printer) const
{
    // Laid out once with placeholders to find the pages, then again with the page numbers (the
    // numbers take the placeholders' room, so nothing moves).
    const std::vector<Section> parts = sections();
    QTextDocument measured;
    addImages(measured, parts);
    measured.setHtml(htmlWithPages(parts, {}));
    const std::vector<int> pages = headingPages(measured, printer, int(parts.size()));
    auto document = std::make_unique<QTextDocument>();
    addImages(*document, parts);
    document->setHtml(htmlWithPages(parts, pages));
    return document;
}

void ProjectDocumentation::print(QPrinter &printer) const
{
    document(printer)->print(&printer);
}

QString ProjectDocumentation::exportPdf(const QString &path) const
{
    QPrinter printer(QPrinter::HighResolution);
    printer.setOutputFormat(QPrinter::PdfFormat);
    printer.setOutputFileName(path);
    printer.setPageSize(QPageSize(QPageSize::A4));
    print(printer);
    if (printer.printerState() == QPrinter::Error)
        return tr("The PDF could not be written to %1.").arg(path);
    return {};
}

} // namespace iec::app
