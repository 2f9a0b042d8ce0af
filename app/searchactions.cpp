#include "app/searchactions.h"

#include "app/documentarea.h"
#include "app/searchresultspane.h"
#include "editors/declarations/declarationeditor.h"
#include "editors/declarations/declarationtablemodel.h"
#include "editors/globals/globallisteditor.h"
#include "editors/text/codeeditor.h"
#include "model/projectmodel.h"

#include <QAction>
#include <QApplication>
#include <QMenu>
#include <QTableView>

#include <algorithm>

namespace iec::app {

namespace {

// The declaration editor the focus is in, and the name of its current row.
struct DeclarationFocus {
    editors::DeclarationEditorBase *editor = nullptr;
    QString name;
};

DeclarationFocus declarationFocus(QWidget *focus)
{
    for (QWidget *widget = focus; widget; widget = widget->parentWidget()) {
        auto *editor = qobject_cast<editors::DeclarationEditorBase *>(widget);
        if (!editor)
            continue;
        const int row = editor->table()->currentIndex().row();
        const auto &rows = editor->tableModel()->rows();
        return {editor, row >= 0 && row < int(rows.size()) ? rows[size_t(row)].name : QString()};
    }
    return {};
}

} // namespace

SearchActions::SearchActions(model::ProjectModel &model, DocumentArea &documents, SearchResultsPane &results, QWidget *window)
    : QObject(window)
    , m_model(model)
    , m_documents(documents)
    , m_results(results)
    , m_window(window)
    , m_findInProject(new QAction(this))
    , m_goToDefinition(new QAction(this))
    , m_crossReferences(new QAction(this))
{
    m_findInProject->setObjectName(QStringLiteral("findInProjectAction"));
    m_findInProject->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F));
    connect(m_findInProject, &QAction::triggered, this, &SearchActions::findInProjectInteractive);
    m_goToDefinition->setObjectName(QStringLiteral("goToDefinitionAction"));
    m_goToDefinition->setShortcut(QKeySequence(Qt::Key_F12));
    // The text editors handle F12 themselves; the menu shows the key (see EditActions).
    m_goToDefinition->setShortcutContext(Qt::WidgetShortcut);
    connect(m_goToDefinition, &QAction::triggered, this, &SearchActions::goToDefinition);
    m_crossReferences->setObjectName(QStringLiteral("crossReferencesAction"));
    m_crossReferences->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F12));
    connect(m_crossReferences, &QAction::triggered, this, &SearchActions::showCrossReferences);
    connect(&results, &SearchResultsPane::hitActivated, this, [this](const SearchHit &hit) { showSearchHit(m_documents, hit); });
    retranslate();
}

void SearchActions::addTo(QMenu *menu) const
{
    menu->addAction(m_findInProject);
    menu->addSeparator();
    menu->addAction(m_goToDefinition);
    menu->addAction(m_crossReferences);
}

void SearchActions::retranslate()
{
    m_findInProject->setText(tr("Find in &Project..."));
    m_goToDefinition->setText(tr("&Go to Definition"));
    m_crossReferences->setText(tr("Cross &References"));
}

int SearchActions::findInProject(const SearchQuery &query)
{
    m_lastQuery = query;
    m_documents.flushEdits();
    const SearchResult result = ProjectSearch::find(m_model.project(), query);
    const QString title = result.error.isEmpty()
        ? tr("%1 matches of \"%2\"").arg(result.hits.size()).arg(query.text)
        : result.error;
    m_results.showHits(title, result.hits);
    Q_EMIT resultsShown();
    return result.error.isEmpty() ? int(result.hits.size()) : -1;
}

void SearchActions::findInProjectInteractive()
{
    SearchQuery initial = m_lastQuery;
    // The word under the cursor is what one usually looks for.
    if (const auto body = m_documents.currentBody()) {
        if (editors::CodeEditor *editor = m_documents.textEditorFor(*body)) {
            const QString selected = editor->textCursor().selectedText();
            initial.text = !selected.isEmpty() && !selected.contains(QChar::ParagraphSeparator)
                ? selected
                : editor->identifierPathAt(editor->textCursor().position()).section(QLatin1Char('.'), -1);
            if (initial.text.isEmpty())
                initial.text = m_lastQuery.text;
        }
    }
    FindInProjectDialog dialog(initial, m_window);
    if (dialog.exec() == QDialog::Accepted)
        findInProject(dialog.query());
}

void SearchActions::goToDefinition()
{
    if (auto *focused = qobject_cast<editors::CodeEditor *>(QApplication::focusWidget())) {
        focused->requestDefinition();
        return;
    }
    if (const auto body = m_documents.currentBody()) {
        if (editors::CodeEditor *editor = m_documents.textEditorFor(*body))
            editor->requestDefinition();
    }
}

bool SearchActions::showCrossReferences()
{
    const DeclarationFocus declaration = declarationFocus(QApplication::focusWidget());
    if (declaration.editor && !declaration.name.isEmpty()) {
        auto *pouEditor = qobject_cast<editors::DeclarationEditor *>(declaration.editor);
        showCrossReferencesOf(pouEditor ? pouEditor->pou() : model::PouId {}, declaration.name);
        return true;
    }
    const auto body = m_documents.currentBody();
    editors::CodeEditor *editor = body ? m_documents.textEditorFor(*body) : nullptr;
    if (!editor)
        return false;
    const QString path = editor->identifierPathAt(editor->textCursor().position());
    // `IO.Valve` is the global Valve of list IO; `Tank.Level` stands for Tank.
    QString name = path.section(QLatin1Char('.'), 0, 0).section(QLatin1Char('['), 0, 0).trimmed();
    const bool isListName = std::ranges::any_of(editors::globalLists(m_model.project().instances),
        [&](const editors::GlobalListRef &list) { return list.name.compare(name, Qt::CaseInsensitive) == 0; });
    if (isListName && path.count(QLatin1Char('.')) >= 1)
        name = path.section(QLatin1Char('.'), 1, 1);
    if (name.isEmpty())
        return false;
    m_documents.flushEdits();
    showCrossReferencesOf(body->pou, name);
    return true;
}

void SearchActions::showCrossReferencesOf(model::PouId from, const QString &name)
{
    const std::vector<SearchHit> hits = ProjectSearch::crossReferences(m_model.project(), from, name);
    m_results.showHits(tr("Cross references of %1: %2 places").arg(name).arg(hits.size()), hits);
    Q_EMIT resultsShown();
}

} // namespace iec::app
