#include "app/adddatatexteditor.h"

#include "editors/text/codeeditor.h"
#include "editors/text/texteditorwidget.h"
#include "interpreter/compiler/diagnostics.h"
#include "model/projectmodel.h"

#include <QVBoxLayout>

#include <algorithm>

namespace iec::app {

AddDataTextEditor::AddDataTextEditor(model::ProjectModel &model, const QString &name, QWidget *parent)
    : QWidget(parent)
    , m_model(model)
    , m_name(name)
    , m_text(new editors::TextEditorWidget(editors::TextLanguage::ST, this))
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_text);
    connect(editor(), &editors::CodeEditor::textEdited, this, &AddDataTextEditor::apply);
    connect(&model, &model::ProjectModel::projectReset, this, &AddDataTextEditor::removed);
}

editors::CodeEditor *AddDataTextEditor::editor() const
{
    return m_text->editor();
}

void AddDataTextEditor::load()
{
    if (const model::AddData *addData = kept()) {
        bool editable = true;
        editor()->setBodyText(print(&editable));
        editor()->setReadOnly(!editable);
        m_written = *addData;
    }
    m_shown = editor()->toPlainText();
    editor()->document()->setModified(false);
}

bool AddDataTextEditor::showsModelText() const
{
    return editor()->toPlainText() == m_shown;
}

QList<editors::TextDiagnostic> AddDataTextEditor::marksOf(const interp::Diagnostics &diagnostics)
{
    QList<editors::TextDiagnostic> marks;
    for (const interp::Diagnostic &d : diagnostics.all()) {
        editors::TextDiagnostic mark;
        mark.line = std::max(d.location.line, 1);
        mark.column = std::max(d.location.column, 1);
        mark.severity = d.severity == interp::Diagnostic::Severity::Error ? editors::TextDiagnostic::Severity::Error
                                                                           : editors::TextDiagnostic::Severity::Warning;
        mark.message = d.hint.isEmpty() ? d.message : d.message + QStringLiteral(" (") + d.hint + QLatin1Char(')');
        marks << mark;
    }
    return marks;
}

void AddDataTextEditor::apply()
{
    // Gone from the model (an undo removed it while typing was pending): the tab is closing, and
    // its text must not bring it back.
    if (!kept() || print(nullptr).isEmpty())
        return;
    const QString text = editor()->toPlainText();
    const Reading reading = read(text);
    editor()->setDiagnostics(reading.marks);
    if (!reading.addData)
        return;
    const bool renamed = reading.name != m_name;
    m_written = *reading.addData;
    m_name = reading.name;
    m_shown = text;
    store(m_written);
    if (renamed)
        Q_EMIT titleChanged();
}

void AddDataTextEditor::followModel()
{
    const model::AddData *now = kept();
    if (!now || *now == m_written)
        return; // its owner is gone (reported elsewhere), or this editor's own change
    m_written = *now;
    const QString text = print(nullptr);
    if (text.isEmpty()) {
        Q_EMIT removed();
        return;
    }
    // A change made elsewhere (an undo, a rename): its text replaces the editor's when it differs
    // in meaning, not only in layout.
    const Reading shown = read(editor()->toPlainText());
    if (shown.addData && *shown.addData == *now)
        return;
    const bool typedBefore = editor()->document()->isModified();
    editor()->setBodyTextKeepingCursor(text);
    editor()->document()->setModified(typedBefore);
    m_shown = text;
}

} // namespace iec::app
