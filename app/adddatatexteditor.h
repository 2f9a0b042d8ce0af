#pragma once

#include "editors/text/textlanguage.h"
#include "model/opaque.h"

#include <QList>
#include <QString>
#include <QWidget>

#include <optional>

namespace iec::model {
class ProjectModel;
}

namespace iec::editors {
class CodeEditor;
class TextEditorWidget;
} // namespace iec::editors

namespace iec::interp {
class Diagnostics;
}

namespace iec::app {

// A text the project keeps in CODESYS's addData (a function block's method or property, an
// INTERFACE), edited as one text in the form of IEC 61131-3 edition 3. What is typed goes into the
// model after a pause, as a body's text does: the text document's own undo is the authority while
// typing. Text that does not read is marked where it goes wrong and not taken: the model keeps the
// last text that read. A new name in the header renames. A subclass says where the text is kept,
// how it prints and how it reads; it calls load() once it can print, and followModel() when the
// addData it keeps may have changed elsewhere (an undo, a rename).
class AddDataTextEditor : public QWidget
{
    Q_OBJECT

public:
    [[nodiscard]] QString name() const { return m_name; }
    [[nodiscard]] virtual QString title() const = 0;
    [[nodiscard]] editors::CodeEditor *editor() const;

Q_SIGNALS:
    void titleChanged();
    // What it shows, or its owner, is gone (an undo, a removal): the tab closes.
    void removed();

protected:
    AddDataTextEditor(model::ProjectModel &model, const QString &name, QWidget *parent);

    // What a text makes of the addData the model keeps: the new addData and the name the text
    // gives, or the marks that say why it is not taken.
    struct Reading {
        std::optional<model::AddData> addData;
        QString name;
        QList<editors::TextDiagnostic> marks;
    };
    [[nodiscard]] virtual Reading read(const QString &text) const = 0;
    [[nodiscard]] virtual const model::AddData *kept() const = 0; // null: its owner is gone
    [[nodiscard]] virtual QString print(bool *editable) const = 0; // empty: it is gone
    virtual void store(const model::AddData &addData) = 0;

    void load();
    void followModel();
    // False when typed text has not been taken yet (messages of older text are not shown on it).
    [[nodiscard]] bool showsModelText() const;
    static QList<editors::TextDiagnostic> marksOf(const interp::Diagnostics &diagnostics);

    model::ProjectModel &m_model;

private:
    void apply();

    QString m_name;
    model::AddData m_written; // the addData as this editor last wrote it
    QString m_shown;          // the text the model holds (as loaded, or last taken)
    editors::TextEditorWidget *m_text = nullptr;
};

} // namespace iec::app
