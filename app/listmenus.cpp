#include "app/listmenus.h"

#include "app/documentarea.h"
#include "app/examples.h"
#include "app/recentfiles.h"

#include <QDir>
#include <QSettings>

namespace iec::app {

RecentFilesMenu::RecentFilesMenu(QWidget *parent)
    : QMenu(parent)
{
    setObjectName(QStringLiteral("recentFilesMenu"));
    connect(this, &QMenu::aboutToShow, this, &RecentFilesMenu::rebuild);
}

void RecentFilesMenu::rebuild()
{
    clear();
    const QStringList files = RecentFiles::load(QSettings());
    for (int index = 0; index < files.size(); ++index) {
        const QString &path = files[index];
        // &1 ... &8 as accelerators, as desktop applications number their recent files.
        QAction *action = addAction(QStringLiteral("&%1 %2").arg(index + 1).arg(QDir::toNativeSeparators(path)));
        connect(action, &QAction::triggered, this, [this, path] { Q_EMIT fileChosen(path); });
    }
    if (files.isEmpty())
        addAction(tr("(none)"))->setEnabled(false);
}

ExamplesMenu::ExamplesMenu(QWidget *parent)
    : QMenu(parent)
{
    setObjectName(QStringLiteral("examplesMenu"));
    connect(this, &QMenu::aboutToShow, this, &ExamplesMenu::rebuild);
}

void ExamplesMenu::rebuild()
{
    clear();
    for (const Example &example : Examples::list()) {
        const QString path = example.resourcePath;
        connect(addAction(example.title), &QAction::triggered, this, [this, path] { Q_EMIT exampleChosen(path); });
    }
}

WindowMenu::WindowMenu(DocumentArea &documents, QWidget *parent)
    : QMenu(parent)
    , m_documents(documents)
    , m_next(addAction(QString(), &documents, &DocumentArea::activateNext))
    , m_previous(addAction(QString(), &documents, &DocumentArea::activatePrevious))
    , m_closeAll(addAction(QString(), &documents, &DocumentArea::closeAll))
{
    setObjectName(QStringLiteral("windowMenu"));
    m_next->setShortcut(QKeySequence::NextChild);
    m_previous->setShortcut(QKeySequence::PreviousChild);
    addSeparator();
    connect(this, &QMenu::aboutToShow, this, &WindowMenu::rebuild);
    retranslate();
}

void WindowMenu::retranslate()
{
    m_next->setText(tr("&Next Document"));
    m_previous->setText(tr("&Previous Document"));
    m_closeAll->setText(tr("&Close All Documents"));
}

void WindowMenu::rebuild()
{
    qDeleteAll(m_documentEntries);
    m_documentEntries.clear();
    for (int index = 0; index < m_documents.count(); ++index) {
        // No icon: the check mark shows the current document, and an icon would take its place.
        QAction *action = addAction(m_documents.tabText(index));
        action->setCheckable(true);
        action->setChecked(index == m_documents.currentIndex());
        QWidget *document = m_documents.widget(index);
        connect(action, &QAction::triggered, this, [this, document] { m_documents.setCurrentWidget(document); });
        m_documentEntries.append(action);
    }
}

} // namespace iec::app
