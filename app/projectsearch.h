#pragma once

#include "editors/globals/globallists.h"
#include "model/ids.h"
#include "model/project.h"

#include <QCoreApplication>
#include <QString>

#include <optional>
#include <vector>

// Find in Project and the cross-reference list, without widgets: where a text or a variable
// occurs in the project, as places the IDE can open.
namespace iec::app {

// One place: a line of an ST/IL body, a graphical element, a declaration of a POU or of a global
// variable list.
struct SearchHit {
    enum class Access { None, Declared, Read, Written, ReadWritten };

    QString place;                             // "Main", "Main.Fill", "IO": what the list shows
    std::optional<model::BodyRef> body;        // a body's text or element, or a POU's declarations
    std::optional<editors::GlobalListRef> list; // a global variable list's declaration
    QString member;                            // a method or property of body->pou: a line of its text
    QString interfaceName;                     // an INTERFACE (no body): a line of its text
    QString variable;                          // declarations: the variable declared there
    int line = 0;                              // text: 1-based line and column, length of the match
    int column = 0;
    int length = 0;
    std::optional<quint64> localId; // a graphical element
    QString text;                   // the line, the declaration or the element's text
    Access access = Access::None;

    [[nodiscard]] bool isDeclaration() const { return !variable.isEmpty(); }
    bool operator==(const SearchHit &) const = default;
};

struct SearchQuery {
    QString text;
    bool caseSensitive = false;
    bool wholeWord = false;
    bool regularExpression = false;
};

struct SearchResult {
    std::vector<SearchHit> hits;
    QString error; // an invalid regular expression, said for a student
};

class ProjectSearch
{
    Q_DECLARE_TR_FUNCTIONS(iec::app::ProjectSearch)

public:
    // Every match of `query` in the ST/IL bodies of POUs, actions and transitions, the text of
    // methods, properties and interfaces (as their tab shows it, docs/ide.md), the texts of
    // graphical elements (variables, expressions, block types and instances, step names,
    // conditions, action names, comments), the POUs' declarations and the global variable lists.
    // In the order of the project tree; a line with several matches gives several hits.
    [[nodiscard]] static SearchResult find(const model::Project &project, const SearchQuery &query);

    // Where variable `name`, as body `from` sees it, is declared, read and written: the POU's
    // own variable in its bodies, actions and transitions; a global (or `List.Name`) in every
    // POU that does not declare the name itself (an invalid `from`: the global). Text uses are written when assigned (`x :=`,
    // `=> x`, IL ST/S/R), graphical ones when a coil or an output variable.
    [[nodiscard]] static std::vector<SearchHit> crossReferences(
        const model::Project &project, model::PouId from, const QString &name);

    [[nodiscard]] static QString accessText(SearchHit::Access access);
};

} // namespace iec::app
