#include "app/membereditor.h"

#include "app/messagespane.h"
#include "editors/text/codeeditor.h"
#include "editors/text/texteditorwidget.h"
#include "interpreter/frontend/codesysmembers.h"
#include "model/plcopen/codesysoop.h"
#include "model/projectmodel.h"

#include <QVBoxLayout>

#include <algorithm>

namespace iec::app {

namespace {

bool sameName(const QString &a, const QString &b)
{
    return a.compare(b, Qt::CaseInsensitive) == 0;
}

editors::TextDiagnostic toText(const interp::Diagnostic &d)
{
    editors::TextDiagnostic mark;
    mark.line = std::max(d.location.line, 1);
    mark.column = std::max(d.location.column, 1);
    mark.severity = d.severity == interp::Diagnostic::Severity::Error ? editors::TextDiagnostic::Severity::Error
                                                                       : editors::TextDiagnostic::Severity::Warning;
    mark.message = d.hint.isEmpty() ? d.message : d.message + QStringLiteral(" (") + d.hint + QLatin1Char(')');
    return mark;
}

} // namespace

MemberEditor::MemberEditor(model::ProjectModel &model, model::PouId pou, const QString &name, QWidget *parent)
    : QWidget(parent)
    , m_model(model)
    , m_pou(pou)
    , m_name(name)
    , m_text(new editors::TextEditorWidget(editors::TextLanguage::ST, this))
{
    setObjectName(QStringLiteral("memberEditor"));
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_text);
    if (const model::Pou *found = model.project().findPou(pou)) {
        bool editable = true;
        editor()->setBodyText(interp::frontend::printCodesysMember(*found, name, &editable));
        editor()->setReadOnly(!editable); // a graphical body has no text to edit
        m_written = found->addData;
    }
    m_shown = editor()->toPlainText();
    editor()->document()->setModified(false);
    connect(editor(), &editors::CodeEditor::textEdited, this, &MemberEditor::apply);
    connect(&model, &model::ProjectModel::pouAddDataChanged, this, &MemberEditor::followModel);
    connect(&model, &model::ProjectModel::pouRenamed, this, &MemberEditor::titleChanged);
    connect(&model, &model::ProjectModel::pouRemoved, this, [this](model::PouId id) {
        if (id == m_pou)
            Q_EMIT removed();
    });
    connect(&model, &model::ProjectModel::projectReset, this, &MemberEditor::removed);
}

QString MemberEditor::title() const
{
    const model::Pou *pou = m_model.project().findPou(m_pou);
    return pou ? pou->name + QLatin1Char('.') + m_name : m_name;
}

editors::CodeEditor *MemberEditor::editor() const
{
    return m_text->editor();
}

void MemberEditor::apply()
{
    const model::Pou *pou = m_model.project().findPou(m_pou);
    if (!pou)
        return;
    const interp::frontend::CodesysMemberText read = interp::frontend::readCodesysMemberText(editor()->toPlainText(), pou->name);
    QList<editors::TextDiagnostic> marks;
    for (const interp::Diagnostic &d : read.diagnostics.all())
        marks << toText(d);
    const bool taken = read.definition && !sameName(read.definition->name, m_name)
        && std::ranges::any_of(interp::frontend::codesysMembers(*pou),
            [&](const interp::frontend::CodesysMemberSummary &m) { return sameName(m.name, read.definition->name); });
    if (taken) {
        editors::TextDiagnostic mark;
        mark.message = tr("%1 already has a method or property called %2.").arg(pou->name, read.definition->name);
        marks << mark;
    }
    editor()->setDiagnostics(marks);
    if (!read.definition || taken)
        return;
    const bool renamed = read.definition->name != m_name;
    m_written = model::plcopen::addDataWithMember(pou->addData, m_name, *read.definition);
    m_name = read.definition->name;
    m_shown = editor()->toPlainText();
    m_model.setPouAddData(m_pou, m_written);
    if (renamed)
        Q_EMIT titleChanged();
}

void MemberEditor::followModel(model::PouId id)
{
    const model::Pou *pou = m_model.project().findPou(m_pou);
    if (id != m_pou || !pou || pou->addData == m_written)
        return; // another POU, or this editor's own change
    m_written = pou->addData;
    const QString text = interp::frontend::printCodesysMember(*pou, m_name);
    if (text.isEmpty()) {
        Q_EMIT removed();
        return;
    }
    // A change made elsewhere (an undo, a rename): its text replaces the editor's when it differs
    // in meaning, not only in layout.
    const interp::frontend::CodesysMemberText shown = interp::frontend::readCodesysMemberText(editor()->toPlainText(), pou->name);
    if (shown.definition && model::plcopen::addDataWithMember(pou->addData, m_name, *shown.definition) == pou->addData)
        return;
    const bool typedBefore = editor()->document()->isModified();
    editor()->setBodyTextKeepingCursor(text);
    editor()->document()->setModified(typedBefore);
    m_shown = text;
}

int MemberEditor::bodyLineOf(const QString &codeName) const
{
    const interp::frontend::MemberBodyLines lines = interp::frontend::memberBodyLines(editor()->toPlainText());
    if (codeName.endsWith(QLatin1String(".GET"), Qt::CaseInsensitive))
        return lines.getter;
    if (codeName.endsWith(QLatin1String(".SET"), Qt::CaseInsensitive))
        return lines.setter;
    return lines.body;
}

bool MemberEditor::isMine(const QString &codeName) const
{
    const QString own = title();
    if (codeName.compare(own, Qt::CaseInsensitive) == 0)
        return true;
    return codeName.size() == own.size() + 4 && codeName.startsWith(own, Qt::CaseInsensitive)
        && (codeName.endsWith(QLatin1String(".GET"), Qt::CaseInsensitive)
            || codeName.endsWith(QLatin1String(".SET"), Qt::CaseInsensitive));
}

Message MemberEditor::atTextLine(Message message) const
{
    const int first = bodyLineOf(message.pouName);
    const bool placed = first > 0 && message.line > 0;
    message.line = placed ? first + message.line - 1 : 1;
    message.column = placed ? std::max(message.column, 1) : 1;
    return message;
}

std::optional<QList<Message>> MemberEditor::messagesAtLines(const QList<Message> &messages) const
{
    if (editor()->toPlainText() != m_shown)
        return std::nullopt;
    QList<Message> own;
    for (const Message &message : messages) {
        if (!isMine(message.pouName))
            continue;
        Message placed = atTextLine(message);
        placed.pouName = title(); // its lines are now the tab's, whichever body it was in
        own << placed;
    }
    return own;
}

} // namespace iec::app
