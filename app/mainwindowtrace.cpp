// The main window's tools for watching the scan over time: the Trace pane (a dock beside the
// watch pane) and the history bar (a tool bar shown while online).
#include "app/mainwindow.h"

#include "app/online/debugcontroller.h"
#include "app/online/historybar.h"
#include "app/online/onlinecontroller.h"
#include "app/online/tracepane.h"
#include "app/messagespane.h"
#include "model/projectmodel.h"

#include <QDockWidget>

namespace iec::app {

namespace {

const QString kTraceSource = QStringLiteral("trace");

} // namespace

void MainWindow::createTraceTools()
{
    m_trace = new TracePane(*m_projectModel, *m_online, this);
    m_trace->setObjectName(QStringLiteral("tracePane"));
    m_traceDock = new QDockWidget(this);
    m_traceDock->setObjectName(QStringLiteral("traceDock"));
    m_traceDock->setWidget(m_trace);
    addDockWidget(Qt::BottomDockWidgetArea, m_traceDock);
    tabifyDockWidget(m_watchDock, m_traceDock);
    m_watchDock->raise();
    // What the runtime cannot record goes to the messages pane, where a student looks for it.
    connect(m_online, &OnlineController::traceProblems, this, [this](const QStringList &problems) {
        QList<Message> messages;
        for (const QString &problem : problems) {
            Message message;
            message.severity = Message::Severity::Warning;
            message.text = tr("Trace: %1").arg(problem);
            messages.append(message);
        }
        m_messages->model().setMessages(kTraceSource, messages);
        m_messagesDock->show();
    });
    connect(m_online, &OnlineController::onlineChanged, this,
            [this] { m_messages->model().setMessages(kTraceSource, {}); });

    // Added to the window below the main tool bar (createToolBar).
    m_historyBar = new HistoryBar(*m_online, *m_documents, this);
}

void MainWindow::retranslateTraceTools()
{
    m_traceDock->setWindowTitle(tr("Trace"));
    m_trace->retranslate();
    m_historyBar->retranslate();
}

model::Project MainWindow::projectToSave() const
{
    model::Project project = m_debug->projectToSave();
    m_trace->storeIn(project);
    return project;
}

} // namespace iec::app
