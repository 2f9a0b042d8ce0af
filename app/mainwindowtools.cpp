// The main window's project-wide tools, apart from the window's own setup in mainwindow.cpp:
// global lists and configurations opened from the tree, the Edit menu's commands and the search
// results, live diagnostics, the library pane, the IL Insert menu, project templates and printed
// documentation.

#include "app/mainwindow.h"

#include "app/buildcontroller.h"
#include "app/documentarea.h"
#include "app/editactions.h"
#include "app/librarypane.h"
#include "app/livediagnostics.h"
#include "app/messagespane.h"
#include "app/projectdocumentation.h"
#include "app/projecttreeactions.h"
#include "app/projecttreemodel.h"
#include "app/projecttreeview.h"
#include "app/searchactions.h"
#include "app/searchresultspane.h"
#include "app/undostacks.h"
#include "editors/text/texteditorwidget.h"
#include "model/plcopen/writer.h"
#include "model/projectmodel.h"

#include <QAction>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QPrintDialog>
#include <QPrinter>
#include <QStatusBar>

namespace iec::app {

void MainWindow::connectInstanceDocuments()
{
    connect(m_projectTree, &ProjectTreeView::openGlobalListRequested, m_documents, &DocumentArea::openGlobalList);
    connect(m_projectTree, &ProjectTreeView::openConfigurationRequested, m_documents, &DocumentArea::openConfiguration);
    connect(m_documents, &DocumentArea::addGlobalListRequested, m_treeActions,
        [this](const editors::GlobalListRef &owner) { m_treeActions->addGlobalListInteractive(owner); });
    connect(m_treeActions, &ProjectTreeActions::configurationRequested, m_documents,
        [this](const QString &configuration) { m_documents->openConfiguration(configuration); });
    connect(m_treeActions, &ProjectTreeActions::globalListCreated, this, [this](const editors::GlobalListRef &list) {
        m_projectTree->selectKey(ProjectTreeModel::globalListKey(list));
        m_documents->openGlobalList(list);
    });
}

void MainWindow::createProjectTools()
{
    m_editActions = new EditActions(*m_documents, this);
    m_searchResults = new SearchResultsPane(this);
    m_searchResults->setObjectName(QStringLiteral("searchResultsPane"));
    m_searchDock = new QDockWidget(this);
    m_searchDock->setObjectName(QStringLiteral("searchDock"));
    m_searchDock->setWidget(m_searchResults);
    addDockWidget(Qt::BottomDockWidgetArea, m_searchDock);
    tabifyDockWidget(m_messagesDock, m_searchDock);
    m_messagesDock->raise();
    m_searchActions = new SearchActions(*m_projectModel, *m_documents, *m_searchResults, this);
    connect(m_searchActions, &SearchActions::resultsShown, this, [this] {
        m_searchDock->show();
        m_searchDock->raise();
    });
    m_liveDiagnostics = new LiveDiagnostics(*m_projectModel, *m_build, this);
    m_library = new LibraryPane(*m_projectModel, this);
    m_library->setObjectName(QStringLiteral("libraryPane"));
    m_libraryDock = new QDockWidget(this);
    m_libraryDock->setObjectName(QStringLiteral("libraryDock"));
    m_libraryDock->setWidget(m_library);
    addDockWidget(Qt::RightDockWidgetArea, m_libraryDock);
    m_printDocumentationAction = new QAction(this);
    m_printDocumentationAction->setObjectName(QStringLiteral("printDocumentationAction"));
    // Ctrl+P prints the current diagram (its editor's Print…, as CODESYS's File → Print); two
    // actions on one key would make Qt run neither.
    m_printDocumentationAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_P));
    connect(m_printDocumentationAction, &QAction::triggered, this, &MainWindow::printDocumentationInteractive);
    m_exportDocumentationAction = new QAction(this);
    m_exportDocumentationAction->setObjectName(QStringLiteral("exportDocumentationAction"));
    connect(m_exportDocumentationAction, &QAction::triggered, this, &MainWindow::exportDocumentationInteractive);
}

void MainWindow::extendMenus()
{
    m_fileMenu->insertAction(m_quitAction, m_printDocumentationAction);
    m_fileMenu->insertAction(m_quitAction, m_exportDocumentationAction);
    m_fileMenu->insertSeparator(m_quitAction);
    m_editMenu->addSeparator();
    m_editActions->addTo(m_editMenu);
    m_searchActions->addTo(m_editMenu);
    m_viewMenu->addAction(m_searchDock->toggleViewAction());
    m_viewMenu->addAction(m_libraryDock->toggleViewAction());
    m_textInsert = MenuSection::atEndOf(*m_insertMenu);
    connect(m_documents, &QTabWidget::currentChanged, this, &MainWindow::showTextInsertActions);
}

void MainWindow::showTextInsertActions()
{
    QWidget *current = m_documents->currentWidget();
    auto *text = qobject_cast<editors::TextEditorWidget *>(current);
    if (!text && current)
        text = current->findChild<editors::TextEditorWidget *>();
    m_textInsert.show(text ? text->insertActions() : QList<QAction *> {});
}

void MainWindow::retranslateProjectTools()
{
    m_editActions->retranslate();
    m_searchActions->retranslate();
    m_searchDock->setWindowTitle(tr("Search Results"));
    m_libraryDock->setWindowTitle(tr("Library"));
    m_printDocumentationAction->setText(tr("&Print Documentation..."));
    m_exportDocumentationAction->setText(tr("Export Documentation as P&DF..."));
}

void MainWindow::printDocumentationInteractive()
{
    m_documents->flushEdits();
    QPrinter printer(QPrinter::HighResolution);
    QPrintDialog dialog(&printer, this);
    dialog.setWindowTitle(tr("Print Documentation"));
    if (dialog.exec() == QDialog::Accepted)
        ProjectDocumentation(*m_projectModel).print(printer);
}

void MainWindow::exportDocumentationInteractive()
{
    m_documents->flushEdits();
    const QString suggested = m_currentFile.isEmpty() ? QString() : QFileInfo(m_currentFile).path() + QLatin1Char('/')
            + QFileInfo(m_currentFile).completeBaseName() + QStringLiteral(".pdf");
    QString path = QFileDialog::getSaveFileName(this, tr("Export Documentation"), suggested, tr("PDF documents (*.pdf)"));
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".pdf");
    const QString problem = ProjectDocumentation(*m_projectModel).exportPdf(path);
    if (!problem.isEmpty())
        QMessageBox::critical(this, tr("Export Documentation"), problem);
    else
        statusBar()->showMessage(tr("The documentation was written to %1.").arg(QDir::toNativeSeparators(path)), 10000);
}

void MainWindow::newProjectFromTemplate(ProjectTemplate projectTemplate)
{
    newProject();
    model::Project project = ProjectTemplates::create(projectTemplate);
    model::plcopen::stampCreationTime(project.fileHeader, QDateTime::currentDateTimeUtc());
    m_projectModel->reset(std::move(project));
    m_undoStacks->clear();
    openMainProgram();
}

void MainWindow::openMainProgram()
{
    const model::Pou *main = m_projectModel->project().findPou(mainProgramName(m_projectModel->project()));
    if (main && main->body())
        m_documents->openBody({main->id, model::BodyRef::Part::Pou, {}});
}

} // namespace iec::app
