#include "app/librarypane.h"

#include "editors/text/standardlibrary.h"
#include "interpreter/frontend/iecprinter.h"
#include "model/projectmodel.h"

#include <QEvent>
#include <QHash>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMimeData>
#include <QTreeWidgetItemIterator>
#include <QVBoxLayout>

namespace iec::app {

namespace {

QStringList pinTexts(const QList<editors::StdParameter> &parameters)
{
    QStringList texts;
    for (const editors::StdParameter &parameter : parameters)
        texts << parameter.name + QStringLiteral(" : ") + parameter.type;
    return texts;
}

QStringList names(const QList<editors::StdParameter> &parameters)
{
    QStringList result;
    for (const editors::StdParameter &parameter : parameters)
        result << parameter.name;
    return result;
}

LibraryEntry standardEntry(const editors::StdPou &pou)
{
    LibraryEntry entry;
    entry.group = pou.library == QLatin1String("Standard") ? LibraryPane::tr("Standard library")
                                                           : LibraryPane::tr("%1 library").arg(pou.library);
    entry.subgroup = editors::stdCategoryName(pou.category);
    entry.call = {pou.name, pou.kind == editors::StdPou::Kind::FunctionBlock, names(pou.inputs), names(pou.outputs)};
    entry.pins = pinTexts(pou.inputs);
    entry.outputPins = pinTexts(pou.outputs);
    entry.returnType = pou.returnType;
    entry.description = pou.translatedDescription();
    return entry;
}

LibraryEntry projectEntry(const model::Pou &pou)
{
    LibraryEntry entry;
    entry.group = LibraryPane::tr("Project");
    const bool block = pou.kind == model::PouKind::FunctionBlock;
    entry.subgroup = block ? LibraryPane::tr("Function Blocks") : LibraryPane::tr("Functions");
    entry.call = {pou.name, block, {}, {}};
    if (pou.pouInterface) {
        if (pou.pouInterface->returnType)
            entry.returnType = interp::frontend::printDataType(*pou.pouInterface->returnType);
        for (const model::VarList &list : pou.pouInterface->varLists) {
            const bool input = list.kind == model::VarListKind::Input || list.kind == model::VarListKind::InOut;
            const bool output = list.kind == model::VarListKind::Output;
            for (const model::Variable &variable : list.variables) {
                const QString pin = variable.name + QStringLiteral(" : ") + interp::frontend::printDataType(variable.type);
                if (input) {
                    entry.call.inputs << variable.name;
                    entry.pins << pin;
                } else if (output) {
                    entry.call.outputs << variable.name;
                    entry.outputPins << pin;
                }
            }
        }
    }
    entry.description = pou.documentation && !pou.documentation->text.trimmed().isEmpty()
        ? pou.documentation->text.trimmed()
        : block ? LibraryPane::tr("A function block of this project.") : LibraryPane::tr("A function of this project.");
    return entry;
}

} // namespace

std::vector<LibraryEntry> libraryEntries(const model::Project &project)
{
    std::vector<LibraryEntry> entries;
    for (const editors::StdPou &pou : editors::standardPous())
        entries.push_back(standardEntry(pou));
    for (const model::Pou &pou : project.types.pous) {
        if (pou.kind != model::PouKind::Program)
            entries.push_back(projectEntry(pou));
    }
    return entries;
}

QString libraryEntryDetails(const LibraryEntry &entry)
{
    QString html = QStringLiteral("<b>%1</b> ").arg(entry.call.name.toHtmlEscaped());
    html += entry.call.functionBlock ? LibraryPane::tr("(function block)") : LibraryPane::tr("(function)");
    html += QStringLiteral("<br>") + entry.description.toHtmlEscaped();
    const auto list = [](const QString &title, const QStringList &pins) {
        return pins.isEmpty() ? QString()
                              : QStringLiteral("<br><i>%1</i> %2").arg(title.toHtmlEscaped(), pins.join(QStringLiteral(", ")).toHtmlEscaped());
    };
    html += list(LibraryPane::tr("Inputs:"), entry.pins);
    html += list(LibraryPane::tr("Outputs:"), entry.outputPins);
    if (!entry.returnType.isEmpty())
        html += list(LibraryPane::tr("Returns:"), {entry.returnType});
    return html;
}

QStringList LibraryTree::mimeTypes() const
{
    return {QString::fromLatin1(editors::kPouMimeType), QString::fromLatin1(editors::kStCallMimeType),
        QString::fromLatin1(editors::kIlCallMimeType), QStringLiteral("text/plain")};
}

QMimeData *LibraryTree::mimeData(const QList<QTreeWidgetItem *> &items) const
{
    if (items.isEmpty() || !m_entries)
        return nullptr;
    const int index = items.front()->data(0, Qt::UserRole).toInt();
    if (index < 0 || index >= int(m_entries->size()))
        return nullptr;
    return editors::pouMimeData((*m_entries)[size_t(index)].call);
}

LibraryPane::LibraryPane(model::ProjectModel &model, QWidget *parent)
    : QWidget(parent)
    , m_model(model)
    , m_filter(new QLineEdit(this))
    , m_tree(new LibraryTree(this))
    , m_details(new QLabel(this))
{
    m_filter->setObjectName(QStringLiteral("libraryFilter"));
    m_filter->setClearButtonEnabled(true);
    m_tree->setObjectName(QStringLiteral("libraryTree"));
    m_tree->setHeaderHidden(true);
    m_tree->setUniformRowHeights(true);
    m_tree->setDragEnabled(true);
    m_tree->setDragDropMode(QAbstractItemView::DragOnly);
    m_tree->setEntries(&m_entries);
    m_details->setObjectName(QStringLiteral("libraryDetails"));
    m_details->setWordWrap(true);
    m_details->setTextFormat(Qt::RichText);
    m_details->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    m_details->setMinimumHeight(m_details->fontMetrics().height() * 5);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_filter);
    layout->addWidget(m_tree, 1);
    layout->addWidget(m_details);
    connect(m_filter, &QLineEdit::textChanged, this, &LibraryPane::applyFilter);
    connect(m_tree, &QTreeWidget::currentItemChanged, this, &LibraryPane::showDetails);
    const auto refresh = [this] { rebuild(); };
    connect(&model, &model::ProjectModel::projectReset, this, refresh);
    connect(&model, &model::ProjectModel::pouAdded, this, refresh);
    connect(&model, &model::ProjectModel::pouRemoved, this, refresh);
    connect(&model, &model::ProjectModel::pouRenamed, this, refresh);
    connect(&model, &model::ProjectModel::variablesChanged, this, refresh);
    m_filter->setPlaceholderText(tr("Search blocks"));
    rebuild();
}

void LibraryPane::changeEvent(QEvent *event)
{
    // Group names and descriptions are translated texts: build them again.
    if (event->type() == QEvent::LanguageChange) {
        m_filter->setPlaceholderText(tr("Search blocks"));
        rebuild();
    }
    QWidget::changeEvent(event);
}

void LibraryPane::rebuild()
{
    const QString current = m_tree->currentItem() ? m_tree->currentItem()->text(0) : QString();
    m_entries = libraryEntries(m_model.project());
    m_tree->clear();
    QHash<QString, QTreeWidgetItem *> groups;
    for (int index = 0; index < int(m_entries.size()); ++index) {
        const LibraryEntry &entry = m_entries[size_t(index)];
        QTreeWidgetItem *group = groups.value(entry.group);
        if (!group) {
            group = new QTreeWidgetItem(m_tree, {entry.group});
            group->setFlags(Qt::ItemIsEnabled);
            groups.insert(entry.group, group);
        }
        const QString subgroupKey = entry.group + QLatin1Char('/') + entry.subgroup;
        QTreeWidgetItem *subgroup = groups.value(subgroupKey);
        if (!subgroup) {
            subgroup = new QTreeWidgetItem(group, {entry.subgroup});
            subgroup->setFlags(Qt::ItemIsEnabled);
            groups.insert(subgroupKey, subgroup);
        }
        auto *item = new QTreeWidgetItem(subgroup, {entry.call.name});
        item->setData(0, Qt::UserRole, index);
        item->setToolTip(0, entry.description);
        item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsDragEnabled);
    }
    for (int row = 0; row < m_tree->topLevelItemCount(); ++row)
        m_tree->topLevelItem(row)->setExpanded(true);
    applyFilter();
    if (!current.isEmpty())
        selectEntry(current);
}

void LibraryPane::setFilter(const QString &text)
{
    m_filter->setText(text);
}

void LibraryPane::applyFilter()
{
    const QString text = m_filter->text().trimmed();
    // An entry shows when its name or description contains the text; a group when one of its
    // entries shows. While filtering, every group with matches is open.
    for (int top = 0; top < m_tree->topLevelItemCount(); ++top) {
        QTreeWidgetItem *group = m_tree->topLevelItem(top);
        bool groupShown = false;
        for (int sub = 0; sub < group->childCount(); ++sub) {
            QTreeWidgetItem *subgroup = group->child(sub);
            bool subShown = false;
            for (int row = 0; row < subgroup->childCount(); ++row) {
                QTreeWidgetItem *item = subgroup->child(row);
                const LibraryEntry *entry = entryOf(item);
                const bool shown = text.isEmpty() || item->text(0).contains(text, Qt::CaseInsensitive)
                    || (entry && entry->description.contains(text, Qt::CaseInsensitive));
                item->setHidden(!shown);
                subShown = subShown || shown;
            }
            subgroup->setHidden(!subShown);
            subgroup->setExpanded(!text.isEmpty() && subShown);
            groupShown = groupShown || subShown;
        }
        group->setHidden(!groupShown);
    }
}

const LibraryEntry *LibraryPane::entryOf(const QTreeWidgetItem *item) const
{
    if (!item)
        return nullptr;
    const QVariant index = item->data(0, Qt::UserRole);
    if (!index.isValid() || index.toInt() < 0 || index.toInt() >= int(m_entries.size()))
        return nullptr;
    return &m_entries[size_t(index.toInt())];
}

bool LibraryPane::selectEntry(const QString &name)
{
    for (QTreeWidgetItemIterator it(m_tree); *it; ++it) {
        if (entryOf(*it) && !(*it)->isHidden() && (*it)->text(0).compare(name, Qt::CaseInsensitive) == 0) {
            for (QTreeWidgetItem *parent = (*it)->parent(); parent; parent = parent->parent())
                parent->setExpanded(true);
            m_tree->setCurrentItem(*it);
            return true;
        }
    }
    return false;
}

QString LibraryPane::detailsText() const
{
    return m_details->text();
}

void LibraryPane::showDetails()
{
    const LibraryEntry *entry = entryOf(m_tree->currentItem());
    m_details->setText(entry ? libraryEntryDetails(*entry) : tr("Choose a block to see its pins; drag it into an editor to call it."));
}

} // namespace iec::app
