#pragma once

#include "app/projectsearch.h"

#include <QObject>

class QAction;
class QMenu;
class QWidget;

namespace iec::model {
class ProjectModel;
}

namespace iec::app {

class DocumentArea;
class SearchResultsPane;

// Edit → Find in Project (Ctrl+Shift+F), Go to Definition (F12) and Cross References
// (Ctrl+Shift+F12, CODESYS's cross-reference list). Results go to the search results pane, whose
// entries open their place.
class SearchActions : public QObject
{
    Q_OBJECT

public:
    SearchActions(model::ProjectModel &model, DocumentArea &documents, SearchResultsPane &results, QWidget *window);

    [[nodiscard]] QAction *findInProjectAction() const { return m_findInProject; }
    [[nodiscard]] QAction *goToDefinitionAction() const { return m_goToDefinition; }
    [[nodiscard]] QAction *crossReferencesAction() const { return m_crossReferences; }
    void addTo(QMenu *menu) const;
    void retranslate();

    // Searches and shows the hits; returns how many there are (-1: the query is invalid, the pane
    // says why).
    int findInProject(const SearchQuery &query);
    // The cross references of the variable under the cursor of the current text body, or of the
    // current row of a declaration table (a POU's or a global list's); false when there is none.
    bool showCrossReferences();
    // Shows the cross references of `name` as body `from` sees it (an invalid POU: a global).
    void showCrossReferencesOf(model::PouId from, const QString &name);

Q_SIGNALS:
    // Results were shown: the window shows their pane.
    void resultsShown();

public Q_SLOTS:
    void findInProjectInteractive();
    void goToDefinition();

private:
    model::ProjectModel &m_model;
    DocumentArea &m_documents;
    SearchResultsPane &m_results;
    QWidget *m_window;
    SearchQuery m_lastQuery;
    QAction *m_findInProject;
    QAction *m_goToDefinition;
    QAction *m_crossReferences;
};

} // namespace iec::app
