#pragma once

#include "app/messagespane.h"
#include "interpreter/compiler/compiler.h"

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

public Q_SLOTS:
    // Opens the body a message names ("Main" or "Main.Fill") at its line and column.
    void openLocation(const iec::app::Message &message);

Q_SIGNALS:
    void built(int errors, int warnings);

private:
    void underlineInOpenEditors();

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
