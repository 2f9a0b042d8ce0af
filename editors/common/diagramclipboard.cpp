#include "editors/common/diagramclipboard.h"

#include "model/plcopen/fragment.h"

#include <QClipboard>
#include <QCoreApplication>
#include <QGuiApplication>
#include <QMimeData>

namespace iec::editors {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("iec::editors", text); // the context lupdate gives tr() here
}

} // namespace

std::unique_ptr<QMimeData> elementsMimeData(EditorLanguage language, const std::vector<model::Element> &elements)
{
    const QByteArray xml = model::plcopen::writeElementsFragment(editorLanguageName(language), elements);
    auto data = std::make_unique<QMimeData>();
    data->setData(QString::fromLatin1(kElementsMimeType), xml);
    data->setText(QString::fromUtf8(xml));
    return data;
}

void copyElementsToClipboard(EditorLanguage language, const std::vector<model::Element> &elements)
{
    QGuiApplication::clipboard()->setMimeData(elementsMimeData(language, elements).release());
}

PastedElements elementsFromMimeData(const QMimeData *data, EditorLanguage language, quint64 firstFreeId)
{
    const QString name = editorLanguageName(language);
    const QString mimeType = QString::fromLatin1(kElementsMimeType);
    if (!data || (!data->hasFormat(mimeType) && data->text().trimmed().isEmpty()))
        return {tr("There is nothing to paste."), {}};
    // Our own type, or text (another window of an older copy, a file's XML pasted by hand).
    const bool ours = data->hasFormat(mimeType);
    const QByteArray xml = ours ? data->data(mimeType) : data->text().toUtf8();
    if (!ours && !xml.trimmed().startsWith('<'))
        return {tr("The clipboard holds text, not %1 elements: nothing was pasted.").arg(name), {}};
    model::plcopen::FragmentReadResult read = model::plcopen::readElementsFragment(xml);
    if (!read.ok())
        return {tr("The clipboard holds no %1 elements that can be pasted. %2").arg(name, read.error), {}};
    if (read.language.compare(name, Qt::CaseInsensitive) != 0)
        return {tr("The clipboard holds %1 elements, which cannot be pasted into %2.").arg(read.language, name), {}};
    if (read.elements.empty())
        return {tr("There is nothing to paste."), {}};
    renumberElements(read.elements, firstFreeId);
    return {QString(), std::move(read.elements)};
}

PastedElements elementsFromClipboard(EditorLanguage language, quint64 firstFreeId)
{
    return elementsFromMimeData(QGuiApplication::clipboard()->mimeData(), language, firstFreeId);
}

bool clipboardHasElements()
{
    const QMimeData *data = QGuiApplication::clipboard()->mimeData();
    return data && data->hasFormat(QString::fromLatin1(kElementsMimeType));
}

std::unordered_map<quint64, quint64> renumberElements(std::vector<model::Element> &elements, quint64 firstFreeId)
{
    std::unordered_map<quint64, quint64> ids;
    quint64 next = firstFreeId;
    for (const model::Element &element : elements)
        ids.emplace(model::header(element).localId, next++);
    for (model::Element &element : elements) {
        model::ElementHeader &head = model::header(element);
        head.localId = ids.at(head.localId);
        for (model::ConnectionPointIn *point : model::inputPoints(element)) {
            std::erase_if(point->connections, [&](const model::Connection &c) { return !ids.contains(c.refLocalId); });
            for (model::Connection &connection : point->connections)
                connection.refLocalId = ids.at(connection.refLocalId);
        }
        // Actions of an action block carry localIds of their own in the same space.
        if (auto *block = std::get_if<model::ActionBlock>(&element)) {
            for (model::ActionBlockAction &action : block->actions)
                action.localId = next++;
        }
    }
    return ids;
}

} // namespace iec::editors
