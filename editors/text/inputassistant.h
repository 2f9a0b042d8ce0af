#pragma once

#include "editors/text/completion.h"
#include "editors/text/textlanguage.h"

#include <QDialog>

class QLineEdit;
class QListWidget;
class QTreeWidget;
class QTreeWidgetItem;

namespace iec::editors {

// The input assistant (F2), as RunPro's IL Insert menu and CODESYS's input help: categories on
// the left (operators, operands, functions, function blocks), their items grouped on the right,
// a filter on top. Choosing an item emits itemChosen; the editor inserts it at the cursor.
class InputAssistantDialog : public QDialog
{
    Q_OBJECT

public:
    enum class Category { Operators, Operands, Functions, FunctionBlocks };

    InputAssistantDialog(TextLanguage language, const CompletionProvider *provider, QWidget *parent = nullptr);

    void setCategory(Category category);
    [[nodiscard]] Category category() const;
    void setFilter(const QString &text);

    // The items of the current category that pass the filter, in display order.
    [[nodiscard]] QStringList itemTexts() const;
    // Selects the first item whose text is `text`; false when there is none.
    bool selectItem(const QString &text);
    [[nodiscard]] QString selectedText() const;

Q_SIGNALS:
    void itemChosen(const QString &text);

private:
    struct Entry {
        QString group;
        QString text;
        QString description;
    };

    void buildEntries(TextLanguage language, const CompletionProvider *provider);
    void populate();
    void chooseCurrent();

    QList<Entry> m_entries[4];
    QListWidget *m_categories = nullptr;
    QLineEdit *m_filter = nullptr;
    QTreeWidget *m_items = nullptr;
};

} // namespace iec::editors
