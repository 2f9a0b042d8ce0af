// The diagram editor's diagnostics (compiler messages on elements) and online side: snapshots
// applied through the language's overlay, values prepared for write/force.
#include "editors/common/diagrameditor.h"

#include "editors/common/diagramscene.h"
#include "editors/common/overlaymapper.h"

#include <QInputDialog>

namespace iec::editors {

// ---- diagnostics

void DiagramEditor::setDiagnostics(const QList<ElementDiagnostic> &diagnostics)
{
    for (const ElementDiagnostic &old : std::as_const(m_diagnostics)) {
        if (DiagramItem *item = m_scene->itemFor(old.localId))
            item->clearDiagnostic();
    }
    m_diagnostics = diagnostics;
    applyDiagnostics();
}

void DiagramEditor::applyDiagnostics()
{
    // Several messages on one element are shown together, the worst severity framing it.
    QHash<quint64, ElementDiagnostic> byElement;
    for (const ElementDiagnostic &diagnostic : std::as_const(m_diagnostics)) {
        auto it = byElement.find(diagnostic.localId);
        if (it == byElement.end()) {
            byElement.insert(diagnostic.localId, diagnostic);
            continue;
        }
        it->message += QLatin1Char('\n') + diagnostic.message;
        it->severity = std::max(it->severity, diagnostic.severity);
    }
    for (const ElementDiagnostic &diagnostic : std::as_const(byElement)) {
        if (DiagramItem *item = m_scene->itemFor(diagnostic.localId))
            item->setDiagnostic(diagnostic.severity, diagnostic.message);
    }
}

// ---- online

void DiagramEditor::setOverlayMapper(std::unique_ptr<OverlayMapper> mapper)
{
    m_overlay = std::move(mapper);
}

QStringList DiagramEditor::onlineNames() const
{
    return m_overlay ? m_overlay->names(*m_scene, m_onlineInstance) : QStringList();
}

bool DiagramEditor::wantsChartState() const
{
    return m_overlay && m_overlay->wantsChartState();
}

void DiagramEditor::setOnlineSnapshot(const interp::RuntimeSnapshot *snapshot)
{
    const bool online = snapshot != nullptr;
    if (online != m_online) {
        m_online = online;
        // Online the drawing is only looked at: no dragging or wiring; the commands that would
        // change it are off (and refuse anyway); copy, zoom, export and print stay.
        m_scene->setEditable(!online);
        updateActionStates();
        if (online && m_inPlace)
            m_inPlace->cancel();
        if (!online) {
            m_snapshot.reset();
            if (m_overlay)
                m_overlay->clear(*m_scene);
            showMessage(QString());
        }
    }
    if (snapshot) {
        m_snapshot = *snapshot;
        if (m_overlay)
            m_overlay->apply(*m_scene, *m_snapshot, m_onlineInstance);
        forgetPreparedOnceWritten();
    }
}

std::optional<QString> DiagramEditor::askValueToPrepare(const QString &name, const QString &now)
{
    const auto is = [&now](const char *literal) { return now.compare(QLatin1String(literal), Qt::CaseInsensitive) == 0; };
    if (is("TRUE") || is("FALSE"))
        return QString::fromLatin1(is("TRUE") ? "FALSE" : "TRUE"); // a BOOL: the other value, as in LD
    bool ok = false;
    const QString literal = QInputDialog::getText(this, tr("Prepare Value"), tr("New value of %1 (now %2):").arg(name, now),
        QLineEdit::Normal, now, &ok).trimmed();
    if (!ok || literal.isEmpty())
        return std::nullopt;
    return literal;
}

void DiagramEditor::announcePrepared(const QString &name, const QString &literal)
{
    Q_EMIT prepareValueRequested(name, literal);
    const QString message = tr("Prepared %1 := %2. Write it with Ctrl+F7 or force it with F7.").arg(name, literal);
    showMessage(message);
    m_prepared = Prepared {name, literal, message};
}

// "Prepared … write it with Ctrl+F7" is stale once the variable has the value: written, forced,
// or set by the program. (Another message shown since is left alone.)
void DiagramEditor::forgetPreparedOnceWritten()
{
    if (!m_prepared || !m_snapshot)
        return;
    if (lastMessage() != m_prepared->message) {
        m_prepared.reset();
        return;
    }
    const QString value = m_snapshot->value(m_prepared->name);
    if (!value.isEmpty() && value.compare(m_prepared->literal, Qt::CaseInsensitive) == 0) {
        m_prepared.reset();
        showMessage(QString());
    }
}

void DiagramEditor::onSceneRefreshed()
{
    // The drawing changed (an edit, undo or redo, another view of the body): a refusal shown
    // before is about a chart that is not there any more. (Online nothing changes the body.)
    if (!m_online)
        showMessage(QString());
    if (m_snapshot && m_overlay)
        m_overlay->apply(*m_scene, *m_snapshot, m_onlineInstance);
    applyDiagnostics();
    updateActionStates();
    sceneRefreshed();
    refreshBreakpointMarks();
}

} // namespace iec::editors
