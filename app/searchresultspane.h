#pragma once

#include "app/projectsearch.h"

#include <QDialog>
#include <QWidget>

class QCheckBox;
class QLabel;
class QLineEdit;
class QTreeWidget;

namespace iec::app {

class DocumentArea;

// The dock that lists what Find in Project or the cross-reference list found: place, where in
// it (line and column, element, declaration), how the variable is used, and the text. Activating
// an entry asks to open the place (showSearchHit).
class SearchResultsPane : public QWidget
{
    Q_OBJECT

public:
    explicit SearchResultsPane(QWidget *parent = nullptr);

    // Shows `hits` under `title` ("12 matches of Count", "Cross references of Count").
    void showHits(const QString &title, const std::vector<SearchHit> &hits);
    [[nodiscard]] const std::vector<SearchHit> &hits() const { return m_hits; }
    [[nodiscard]] QString title() const;
    [[nodiscard]] QTreeWidget *list() const { return m_list; }

Q_SIGNALS:
    void hitActivated(const iec::app::SearchHit &hit);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();

    QLabel *m_title;
    QTreeWidget *m_list;
    std::vector<SearchHit> m_hits;
};

// Edit → Find in Project: the text and the options; the window runs the search.
class FindInProjectDialog : public QDialog
{
    Q_OBJECT

public:
    explicit FindInProjectDialog(const SearchQuery &initial, QWidget *parent = nullptr);
    [[nodiscard]] SearchQuery query() const;

private:
    QLineEdit *m_text;
    QCheckBox *m_case;
    QCheckBox *m_word;
    QCheckBox *m_regex;
};

// Where a hit is in a location text: "line 3, column 5", "element 12", "declaration".
[[nodiscard]] QString hitLocationText(const SearchHit &hit);

// Opens the place of a hit: the body at the line with the match selected, the declaration row
// of the variable (a POU's or a global list's), or the body of a graphical element. For the
// element itself, a widget of the opened document that has an invokable `showElement(quint64)`
// is asked to select and show it (the diagram editors' hook).
bool showSearchHit(DocumentArea &documents, const SearchHit &hit);

} // namespace iec::app
