#include "app/buildcontroller.h"

#include "app/documentarea.h"
#include "app/membereditor.h"
#include "editors/common/diagrameditor.h"
#include "editors/common/diagramview.h"
#include "editors/text/codeeditor.h"
#include "interpreter/compiler/lexer.h"
#include "interpreter/frontend/projectsource.h"
#include "model/projectmodel.h"

#include <QTextBlock>
#include <QTextDocument>

namespace iec::app {

using model::BodyRef;

namespace {

const QString kBuildSource = QStringLiteral("build");

// "Main" names a POU's body, "Main.Fill" one of its actions or transitions.
std::optional<BodyRef> bodyNamed(const model::ProjectModel &projectModel, const QString &name)
{
    const int dot = name.indexOf(QLatin1Char('.'));
    const model::Pou *pou = projectModel.project().findPou(dot < 0 ? name : name.left(dot));
    if (!pou)
        return std::nullopt;
    if (dot < 0)
        return BodyRef{pou->id, BodyRef::Part::Pou, {}};
    const QString part = name.mid(dot + 1);
    for (const BodyRef::Part kind : {BodyRef::Part::Action, BodyRef::Part::Transition}) {
        if (projectModel.findPouPart(pou->id, kind, part))
            return BodyRef{pou->id, kind, part};
    }
    return std::nullopt;
}

// The length of the token that starts at the 1-based column, so that the underline covers the
// whole misspelt name rather than its first letter (the compiler reports positions only).
int tokenLengthAt(const QString &lineText, int column)
{
    interp::LexState state;
    for (const interp::Token &token : interp::tokenize(lineText, state)) {
        if (token.offset == column - 1)
            return token.length;
    }
    return 0;
}

// The messages about elements of the body titled `title`, for its graphical editor.
QList<editors::ElementDiagnostic> elementDiagnostics(const QList<Message> &messages, const QString &title)
{
    QList<editors::ElementDiagnostic> diagnostics;
    for (const Message &message : messages) {
        if (!message.localId || message.pouName.compare(title, Qt::CaseInsensitive) != 0)
            continue;
        diagnostics.append({.localId = *message.localId,
            .severity = message.severity == Message::Severity::Error ? editors::ElementDiagnostic::Severity::Error
                                                                     : editors::ElementDiagnostic::Severity::Warning,
            .message = message.text});
    }
    return diagnostics;
}

// The messages with a line in the body titled `title`, underlined in its text editor.
QList<editors::TextDiagnostic> textDiagnostics(const QList<Message> &messages, const QString &title, const QTextDocument &document)
{
    const int lineCount = document.blockCount();
    QList<editors::TextDiagnostic> underlines;
    for (const Message &message : messages) {
        // Declaration diagnostics count lines in the printed declarations, not in the body.
        if (message.pouName.compare(title, Qt::CaseInsensitive) != 0 || message.line < 1 || message.line > lineCount)
            continue;
        const QString lineText = document.findBlockByNumber(message.line - 1).text();
        underlines.append({.line = message.line,
            .column = std::max(1, message.column),
            .length = tokenLengthAt(lineText, message.column),
            .severity = message.severity == Message::Severity::Error ? editors::TextDiagnostic::Severity::Error
                                                                     : editors::TextDiagnostic::Severity::Warning,
            .message = message.text});
    }
    return underlines;
}

} // namespace

QList<Message> messagesOf(const interp::Diagnostics &diagnostics)
{
    QList<Message> messages;
    for (const interp::Diagnostic &diagnostic : diagnostics.all()) {
        QString text = diagnostic.message;
        if (!diagnostic.hint.isEmpty())
            text = BuildController::tr("%1 Hint: %2").arg(text, diagnostic.hint);
        messages.append({.severity = diagnostic.severity == interp::Diagnostic::Severity::Error
                             ? Message::Severity::Error
                             : Message::Severity::Warning,
                         .text = text,
                         .pouName = diagnostic.pou,
                         .line = diagnostic.location.line,
                         .column = diagnostic.location.column,
                         .localId = diagnostic.location.localId >= 0
                             ? std::optional<quint64>(quint64(diagnostic.location.localId))
                             : std::nullopt});
    }
    return messages;
}

QList<Message> compileMessages(const model::Project &project)
{
    interp::Diagnostics diagnostics;
    interp::frontend::compileProject(project, diagnostics);
    return messagesOf(diagnostics);
}

BuildController::BuildController(model::ProjectModel &projectModel, DocumentArea &documents,
                                 MessagesPane &messages, QObject *parent)
    : QObject(parent)
    , m_projectModel(projectModel)
    , m_documents(documents)
    , m_messagesPane(messages)
{
    connect(&messages, &MessagesPane::messageActivated, this, &BuildController::openLocation);
    // A tab opened after the last compile shows its messages at once, not after the next one.
    connect(&documents, &QTabWidget::currentChanged, this, [this] {
        underlineInOpenEditors();
        sendGraphicalDiagnostics();
    });
}

bool BuildController::build(const interp::CompileOptions &options)
{
    // What the user typed in the last moments is part of what they asked to build.
    m_documents.flushEdits();
    interp::Diagnostics diagnostics;
    // The compile runs on the compiler's own thread with a stack of known size and waits for it
    // (interpreter/compiler/limits.h): the same nesting limits as iecstudio-cli, whatever this
    // thread's stack.
    m_module = interp::frontend::compileProject(m_projectModel.project(), diagnostics, options);
    publish(messagesOf(diagnostics));
    const int errors = m_messagesPane.model().count(Message::Severity::Error);
    Q_EMIT built(errors, m_messagesPane.model().count(Message::Severity::Warning));
    return errors == 0;
}

void BuildController::publish(const QList<Message> &messages)
{
    m_messages = messages;
    m_messagesPane.model().setMessages(kBuildSource, m_messages);
    underlineInOpenEditors();
    sendGraphicalDiagnostics();
}

void BuildController::sendGraphicalDiagnostics()
{
    const model::Project &project = m_projectModel.project();
    for (int index = 0; index < m_documents.count(); ++index) {
        const std::optional<BodyRef> ref = m_documents.bodyAt(index);
        const model::Body *body = ref ? m_projectModel.body(*ref) : nullptr;
        if (!body || !body->isGraphical())
            continue;
        const QString title = DocumentArea::title(project, *ref);
        QList<Message> own;
        for (const Message &message : std::as_const(m_messages)) {
            if (message.pouName.compare(title, Qt::CaseInsensitive) == 0)
                own.append(message);
        }
        Q_EMIT graphicalDiagnosticsChanged(*ref, own);
    }
}

void BuildController::underlineInOpenEditors()
{
    const model::Project &project = m_projectModel.project();
    for (int index = 0; index < m_documents.count(); ++index) {
        if (auto *member = qobject_cast<MemberEditor *>(m_documents.widget(index))) {
            if (const std::optional<QList<Message>> own = member->messagesAtLines(m_messages))
                member->editor()->setDiagnostics(textDiagnostics(*own, member->title(), *member->editor()->document()));
            continue;
        }
        const std::optional<BodyRef> ref = m_documents.bodyAt(index);
        if (!ref)
            continue;
        const QString title = DocumentArea::title(project, *ref);
        if (editors::DiagramEditor *diagram = m_documents.diagramEditorFor(*ref))
            diagram->setDiagnostics(elementDiagnostics(m_messages, title));
        if (editors::CodeEditor *editor = m_documents.textEditorFor(*ref)) {
            // Typing not yet pushed: these diagnostics are of older text (the next compile marks it).
            const model::Body *body = m_projectModel.body(*ref);
            if (body && editor->toPlainText() == body->text())
                editor->setDiagnostics(textDiagnostics(m_messages, title, *editor->document()));
        }
    }
}

void BuildController::openLocation(const Message &message)
{
    const std::optional<BodyRef> ref = bodyNamed(m_projectModel, message.pouName);
    if (!ref) {
        openMemberAt(message);
        return;
    }
    m_documents.openBody(*ref);
    if (editors::DiagramEditor *diagram = m_documents.diagramEditorFor(*ref); diagram && message.localId) {
        diagram->select({*message.localId});
        diagram->view()->setFocus();
        return;
    }
    editors::CodeEditor *editor = m_documents.textEditorFor(*ref);
    if (editor && message.line > 0 && message.line <= editor->document()->blockCount()) {
        editor->goToLine(message.line, std::max(1, message.column));
        editor->setFocus();
    }
}

void BuildController::openMemberAt(const Message &message)
{
    // "Counter.Add" (a method), "Counter.Count.GET" (a property's accessor): lines counted in
    // that body. A POU's name has no dot, so the first part is the POU and the second the member.
    const QStringList parts = message.pouName.split(QLatin1Char('.'));
    if (parts.size() == 1 && m_documents.openInterface(parts[0]))
        return; // an INTERFACE's message: its tab shows where
    const model::Pou *pou = parts.size() >= 2 ? m_projectModel.project().findPou(parts[0]) : nullptr;
    auto *member = pou ? qobject_cast<MemberEditor *>(m_documents.openMember(pou->id, parts[1])) : nullptr;
    if (!member)
        return;
    const Message placed = member->atTextLine(message);
    member->editor()->goToLine(placed.line, placed.column);
    member->editor()->setFocus();
}

} // namespace iec::app
