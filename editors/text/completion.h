#pragma once

#include "editors/text/textlanguage.h"

#include <QList>
#include <QString>
#include <QStringView>

namespace iec::editors {

struct CompletionItem {
    enum class Kind { Keyword, TypeName, Variable, Member, Function, FunctionBlock, Program, Operator, Constant };

    QString text;
    Kind kind = Kind::Variable;
    QString detail; // a type, or a signature with the parameters
    QString category; // for the input assistant: "Local variables", "Global variables" ...

    bool operator==(const CompletionItem &) const = default;
};

// What the application knows about the POU being edited; the editor asks it on Ctrl+Space and F2.
// The editor itself adds the keywords and the standard functions and function blocks.
class CompletionProvider
{
public:
    virtual ~CompletionProvider() = default;
    // Variables visible in the POU: its own declarations and the global variables.
    [[nodiscard]] virtual QList<CompletionItem> variables() const = 0;
    // Members of `path` ("Tank", "Main.Tank", "Motors[2]"): struct fields, FB inputs and outputs.
    [[nodiscard]] virtual QList<CompletionItem> members(const QString &path) const = 0;
    // The project's POUs (kind Program, Function or FunctionBlock, detail the signature).
    [[nodiscard]] virtual QList<CompletionItem> pous() const = 0;
    // The declared type of `path`, so the editor can complete members of standard FB instances
    // (T1 : TON → T1.Q, T1.ET ...) that the project does not describe. Empty when unknown.
    [[nodiscard]] virtual QString typeOf(const QString &path) const { return {}; }
};

// Where the cursor is for completion: the word being typed and, after a '.', the path before it.
struct CompletionContext {
    QString prefix; // the identifier characters before the cursor
    QString memberPath; // "Tank" in "Tank.Le|"; empty outside member access
    int prefixStart = 0;

    bool operator==(const CompletionContext &) const = default;
};

[[nodiscard]] CompletionContext completionContext(QStringView line, int column);

// The candidates for a context, those starting with its prefix (case-insensitive), sorted by
// name without duplicates. Outside member access: the provider's variables and POUs, the
// standard functions and FBs, the language's keywords. After a '.': the provider's members of
// the path, or the inputs and outputs of a standard FB type.
[[nodiscard]] QList<CompletionItem> completionItems(
    const CompletionContext &context, const CompletionProvider *provider, TextLanguage language);

[[nodiscard]] bool isIdentifierChar(QChar c);

} // namespace iec::editors
