#pragma once

#include "app/messagespane.h"
#include "interpreter/compiler/compiler.h"
#include "model/ids.h"

#include <QObject>

namespace iec::model {
class ProjectModel;
struct Project;
}

namespace iec::app {

class DocumentArea;

// Project → Build: compiles the whole project with the interpreter, lists the diagnostics in
// the messages pane, underlines them in the open text editors, and opens the place a message
// points to when it is activated.
class BuildController : public QObject
{
    Q_OBJECT

public:
    BuildController(model::ProjectModel &projectModel, DocumentArea &documents, MessagesPane &messages,
                    QObject *parent = nullptr);

    // Returns true when the project compiled without errors.
    bool build(const interp::CompileOptions &options = {});
    [[nodiscard]] const QList<Message> &lastMessages() const { return m_messages; }
    // What the last build compiled; nullptr after errors.
    [[nodiscard]] std::shared_ptr<const interp::Module> lastModule() const { return m_module; }

    // Shows diagnostics of the project as the model holds it now (Build's, or a background
    // compile's of the current revision): the messages pane lists them; open text editors whose
    // text is the model's underline theirs (an editor with typing not yet in the model is left as
    // it is: the marks would land on newer text); graphicalDiagnosticsChanged goes out for every
    // open graphical body.
    void publish(const QList<Message> &messages);

public Q_SLOTS:
    // Opens the body a message names ("Main" or "Main.Fill") at its line and column.
    void openLocation(const iec::app::Message &message);

Q_SIGNALS:
    void built(int errors, int warnings);
    // The diagnostics of an open LD/FBD/CFC/SFC body (an empty list clears them). The hook for
    // the diagram editors' setDiagnostics(...): every message has the body's name and, when the
    // compiler located it there, the element's localId.
    void graphicalDiagnosticsChanged(const iec::model::BodyRef &body, const QList<iec::app::Message> &messages);

private:
    // A message about a method or property ("Counter.Add"): its tab opens at the line.
    void openMemberAt(const Message &message);
    void underlineInOpenEditors();
    void sendGraphicalDiagnostics();

    model::ProjectModel &m_projectModel;
    DocumentArea &m_documents;
    MessagesPane &m_messagesPane;
    QList<Message> m_messages;
    std::shared_ptr<const interp::Module> m_module;
};

// The compiler's diagnostics as messages for the pane.
QList<Message> messagesOf(const interp::Diagnostics &diagnostics);
// Compiles the project and returns the compiler's diagnostics as messages (for tests).
QList<Message> compileMessages(const model::Project &project);

} // namespace iec::app
