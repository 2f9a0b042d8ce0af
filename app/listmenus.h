#pragma once

#include <QMenu>

namespace iec::app {

class DocumentArea;

// Menus whose entries are a list that changes while the program runs; each rebuilds itself
// just before it is shown, so it never needs to be told about changes.

// File → Recent Projects (RecentFiles, newest first).
class RecentFilesMenu : public QMenu
{
    Q_OBJECT

public:
    explicit RecentFilesMenu(QWidget *parent = nullptr);
    void rebuild();

Q_SIGNALS:
    void fileChosen(const QString &path);
};

// Help → Examples (Examples::list()).
class ExamplesMenu : public QMenu
{
    Q_OBJECT

public:
    explicit ExamplesMenu(QWidget *parent = nullptr);
    void rebuild();

Q_SIGNALS:
    void exampleChosen(const QString &resourcePath);
};

// Window: next / previous document, close all, then one entry per open tab (the current checked).
class WindowMenu : public QMenu
{
    Q_OBJECT

public:
    WindowMenu(DocumentArea &documents, QWidget *parent = nullptr);
    void rebuild();
    void retranslate();

private:
    DocumentArea &m_documents;
    // Always there, so their shortcuts work before the menu was ever opened.
    QAction *m_next;
    QAction *m_previous;
    QAction *m_closeAll;
    QList<QAction *> m_documentEntries;
};

} // namespace iec::app
