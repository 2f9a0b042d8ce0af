#pragma once

#include "model/ids.h"

#include <QObject>

#include <unordered_map>

class QUndoGroup;
class QUndoStack;

namespace iec::app {

// The undo stacks of one open project (DESIGN.md): one for project-wide changes (the tree's
// add/rename/delete/duplicate) and one per POU for edits inside its bodies, all in one QUndoGroup
// whose active stack the window switches as the focus moves. A POU's stack outlives the POU:
// deleting it is itself undoable, and its edits must still count as unsaved when it comes back.
class UndoStacks : public QObject
{
    Q_OBJECT

public:
    explicit UndoStacks(QObject *parent = nullptr);

    [[nodiscard]] QUndoGroup &group() const { return *m_group; }
    [[nodiscard]] QUndoStack &projectStack() const { return *m_projectStack; }
    // The POU's stack, created on first use.
    QUndoStack &pouStack(model::PouId pou);

    void activateProjectStack();
    void activatePouStack(model::PouId pou);

    // True when every stack is at its clean index.
    [[nodiscard]] bool isClean() const;
    void setClean();
    // A different project was loaded: no history survives it.
    void clear();

Q_SIGNALS:
    // Some stack became clean or unclean.
    void cleanChanged();

private:
    void adopt(QUndoStack *stack);

    QUndoGroup *m_group;
    QUndoStack *m_projectStack;
    std::unordered_map<model::PouId, QUndoStack *> m_pouStacks;
};

} // namespace iec::app
