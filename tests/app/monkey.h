#pragma once

// A seeded monkey for the main window: random gestures on the current document, found generically
// (the QActions of the document widget and of the window's Edit, Insert and Online menus; typing,
// erasing, cut/copy/paste in text editors; selecting items in diagram views; zoom; renaming the
// POU from the project tree), never through a particular editor's functions, so new editors are
// driven as soon as they are registered. Dialogs the gestures open are answered at random.
// Every gesture's effect on the undo histories (each QUndoStack of the window and the typing of
// each text document) is logged, so that undoAll() can take everything back in reverse order.
#include <QList>
#include <QMap>
#include <QPointer>
#include <QRandomGenerator>
#include <QString>
#include <QStringList>

#include <functional>
#include <vector>

class QAction;
class QObject;
class QTimer;
class QWidget;

namespace iec::app {
class MainWindow;
}

namespace monkey {

class Monkey
{
public:
    Monkey(iec::app::MainWindow &window, quint32 seed);
    ~Monkey();
    Monkey(const Monkey &) = delete;
    Monkey &operator=(const Monkey &) = delete;

    // One random gesture on the current document; returns what it did ("action Insert Step",
    // "type ...", ...), for the log a failure prints.
    QString gesture();
    // Takes every logged gesture back, newest first; false (with `problem`) when an undo stack it
    // needs is gone. Typing in a text document whose tab has closed since cannot be taken back
    // that way: it is skipped (lostTyping() counts it), and the caller's comparison with the
    // starting model says whether what took the document away took the typing with it (undoing
    // an Add Method removes the method and what was typed in it).
    bool undoAll(QString *problem);
    [[nodiscard]] int lostTyping() const { return m_lostTyping; }
    // Ends online mode if a gesture started it (nothing may be edited online).
    void logout();
    // What the gestures did so far, one line each.
    [[nodiscard]] const QStringList &log() const { return m_log; }
    // Gestures by kind, e.g. {"action": 120, "type": 40, ...}.
    [[nodiscard]] QString statistics() const;

private:
    struct History {
        QPointer<QObject> owner; // a QUndoStack or a QTextDocument
        int position = 0;        // its index / available undo steps after the last gesture
    };
    struct Step {
        QPointer<QObject> owner;
        int delta = 0; // how far the gesture moved that history
        bool text = false; // a text document's typing, not an undo stack
    };

    QString trigger(const QList<QAction *> &candidates, const QString &kind);
    QString typeText();
    QString eraseText();
    QString clipboard();
    QString selectItems();
    QString zoom();
    QString rename();
    QList<QAction *> documentActions() const;
    QList<QAction *> menuActions(const char *menuName) const;
    QWidget *currentDocument() const;
    std::vector<History> histories() const;
    void recordSteps(const std::vector<History> &before);
    void answerDialogs();
    int pick(int count) { return count > 0 ? int(m_random.bounded(count)) : 0; }

    iec::app::MainWindow &m_window;
    QRandomGenerator m_random;
    QTimer *m_answerer = nullptr;
    std::vector<std::vector<Step>> m_steps; // per gesture
    QStringList m_log;
    QMap<QString, int> m_counts;
    int m_lostTyping = 0;
};

} // namespace monkey
