#pragma once

#include "editors/text/calltext.h"

#include <QTreeWidget>
#include <QWidget>

#include <vector>

class QLabel;
class QLineEdit;

namespace iec::model {
class ProjectModel;
struct Project;
} // namespace iec::model

namespace iec::app {

// One block the library pane offers.
struct LibraryEntry {
    QString group;    // "Standard library", "Util library", "Project"
    QString subgroup; // a category ("Timers") or "Functions" / "Function Blocks"
    editors::CallSignature call;
    QStringList pins; // "IN : BOOL", "Q : BOOL" (outputs), in order
    QStringList outputPins;
    QString returnType;
    QString description;
};

// Every block: the standard library's table (editors/text/standardlibrary: every library listed
// there, grouped by its library name) and the project's own functions and function blocks.
[[nodiscard]] std::vector<LibraryEntry> libraryEntries(const model::Project &project);
// What the pane shows below the list for an entry: signature, pins with types, description.
[[nodiscard]] QString libraryEntryDetails(const LibraryEntry &entry);

// The tree of the pane; a dragged entry carries editors::pouMimeData (a call for the text
// editors, the POU's name as application/x-iecstudio-pou for the diagram editors).
class LibraryTree : public QTreeWidget
{
    Q_OBJECT

public:
    using QTreeWidget::QTreeWidget;
    void setEntries(const std::vector<LibraryEntry> *entries) { m_entries = entries; }

    // What a drag of `items` carries (the first entry's call and name).
    QMimeData *mimeData(const QList<QTreeWidgetItem *> &items) const override;
    QStringList mimeTypes() const override;

private:
    const std::vector<LibraryEntry> *m_entries = nullptr;
};

// View → Library: the blocks grouped and searchable, each with its pins, types and a short
// description; drag one into an editor. It follows the project's POUs as they change.
class LibraryPane : public QWidget
{
    Q_OBJECT

public:
    explicit LibraryPane(model::ProjectModel &model, QWidget *parent = nullptr);

    void setFilter(const QString &text);
    [[nodiscard]] LibraryTree *tree() const { return m_tree; }
    [[nodiscard]] QString detailsText() const;
    // The entry an item shows, nullptr for group items.
    [[nodiscard]] const LibraryEntry *entryOf(const QTreeWidgetItem *item) const;
    // Selects the first entry named `name` (case-insensitive); false when it is not shown.
    bool selectEntry(const QString &name);

protected:
    void changeEvent(QEvent *event) override;

private:
    void rebuild();
    void applyFilter();
    void showDetails();

    model::ProjectModel &m_model;
    std::vector<LibraryEntry> m_entries;
    QLineEdit *m_filter;
    LibraryTree *m_tree;
    QLabel *m_details;
};

} // namespace iec::app
