#include "app/documentarea.h"

#include "app/autodeclare.h"
#include "app/autodeclaredialog.h"
#include "app/projectsymbols.h"
#include "app/referencerename.h"
#include "app/treeicons.h"
#include "app/undostacks.h"
#include "editors/datatypes/datatypeeditor.h"
#include "editors/declarations/declarationeditor.h"
#include "editors/common/diagrameditor.h"
#include "editors/common/editorregistry.h"
#include "editors/standardeditors.h"
#include "editors/text/codeeditor.h"
#include "editors/text/texteditorwidget.h"
#include "model/projectmodel.h"

#include <QAbstractButton>
#include <QAbstractItemView>
#include <QAction>
#include <QComboBox>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QTabBar>
#include <QToolButton>
#include <QToolTip>
#include <QUndoStack>
#include <QSplitter>
#include <QTextDocument>

namespace iec::app {

using model::BodyRef;

namespace {

// Each tab's widget carries the body it shows, so no side table can drift from the tabs.
const char *const kBodyRefProperty = "iecBodyRef";

// The window that holds the tabs owns the undo stacks; a DocumentArea on its own (in a test)
// keeps stacks of its own.
UndoStacks *undoStacksOf(QWidget *window, QObject *owner)
{
    auto *stacks = window ? window->findChild<UndoStacks *>(QString(), Qt::FindDirectChildrenOnly) : nullptr;
    return stacks ? stacks : new UndoStacks(owner);
}

// A tab's text editor: the tab itself (actions, transitions) or the body below the declarations.
// Windows the document opened (a dialog) are not searched: focus changes while a dialog is being
// destroyed ask for the text editor, and the dialog's children are half gone by then.
editors::TextEditorWidget *textWidgetIn(QWidget *document)
{
    if (!document)
        return nullptr;
    if (auto *textWidget = qobject_cast<editors::TextEditorWidget *>(document))
        return textWidget;
    for (QObject *child : document->children()) {
        auto *widget = qobject_cast<QWidget *>(child);
        if (!widget || widget->isWindow())
            continue;
        if (auto *textWidget = textWidgetIn(widget))
            return textWidget;
    }
    return nullptr;
}

// The instance a body's variables belong to online: a program's own name; for a function block
// the first instance a program declares of it ("Main.Filler"); nothing for functions.
QString onlineInstanceOf(const model::Project &project, model::PouId id)
{
    const model::Pou *pou = project.findPou(id);
    if (!pou || pou->kind == model::PouKind::Function)
        return {};
    if (pou->kind == model::PouKind::Program)
        return pou->name;
    for (const model::Pou &holder : project.types.pous) {
        if (holder.kind != model::PouKind::Program || !holder.pouInterface)
            continue;
        for (const model::VarList &list : holder.pouInterface->varLists) {
            for (const model::Variable &variable : list.variables) {
                const auto *derived = std::get_if<model::DerivedType>(&variable.type.kind);
                if (derived && derived->name.compare(pou->name, Qt::CaseInsensitive) == 0)
                    return holder.name + QLatin1Char('.') + variable.name;
            }
        }
    }
    return {};
}

// Online, the declaration table's own Ctrl+Z/Ctrl+Y (which act on the POU's stack directly)
// would change the program: this filter, installed last so it runs first, swallows them.
class UndoKeyBlocker : public QObject
{
public:
    UndoKeyBlocker(QObject *parent, std::function<void()> refused)
        : QObject(parent)
        , m_refused(std::move(refused))
    {
        setObjectName(QStringLiteral("iecOnlineUndoBlocker"));
    }

    bool eventFilter(QObject *, QEvent *event) override
    {
        if (event->type() != QEvent::ShortcutOverride && event->type() != QEvent::KeyPress)
            return false;
        const auto *key = static_cast<QKeyEvent *>(event);
        const bool ctrlY = key->keyCombination() == QKeyCombination(Qt::CTRL, Qt::Key_Y); // redoes too
        if (!key->matches(QKeySequence::Undo) && !key->matches(QKeySequence::Redo) && !ctrlY)
            return false;
        event->accept();
        if (event->type() == QEvent::KeyPress)
            m_refused();
        return true;
    }

private:
    std::function<void()> m_refused;
};

// Turns the fields of a declaration or data type editor read-only and its buttons off (or back).
// A property marks what this changed, so unlocking gives back exactly that and leaves alone what
// the editor itself had made read-only or disabled.
const char *const kLockedProperty = "iecOnlineLocked";
const char *const kEditTriggersProperty = "iecEditTriggers";

void lockEditor(QWidget *editor, bool locked, const std::function<void()> &refused)
{
    for (QWidget *widget : editor->findChildren<QWidget *>()) {
        if (widget->property(kLockedProperty).toBool() == locked)
            continue;
        if (auto *line = qobject_cast<QLineEdit *>(widget)) {
            if (locked && line->isReadOnly())
                continue;
            line->setReadOnly(locked);
        } else if (auto *text = qobject_cast<QPlainTextEdit *>(widget)) {
            if (locked && text->isReadOnly())
                continue;
            text->setReadOnly(locked);
        } else if (auto *view = qobject_cast<QAbstractItemView *>(widget)) {
            if (locked) {
                view->setProperty(kEditTriggersProperty, int(view->editTriggers()));
                view->setEditTriggers(QAbstractItemView::NoEditTriggers);
                view->installEventFilter(new UndoKeyBlocker(view, refused));
            } else {
                view->setEditTriggers(QAbstractItemView::EditTriggers(view->property(kEditTriggersProperty).toInt()));
                delete view->findChild<QObject *>(QStringLiteral("iecOnlineUndoBlocker"), Qt::FindDirectChildrenOnly);
            }
        } else if ((qobject_cast<QAbstractButton *>(widget) && !qobject_cast<QTabBar *>(widget->parentWidget()))
                   || qobject_cast<QComboBox *>(widget)) {
            if (locked && !widget->isEnabled())
                continue;
            widget->setEnabled(!locked);
            // A tool bar's button follows its action, so the action is switched too.
            if (auto *tool = qobject_cast<QToolButton *>(widget); tool && tool->defaultAction())
                tool->defaultAction()->setEnabled(!locked);
        } else {
            continue;
        }
        widget->setProperty(kLockedProperty, locked);
    }
}

} // namespace

void DocumentArea::setEditingLocked(bool locked)
{
    m_editingLocked = locked;
    for (int index = 0; index < count(); ++index) {
        QWidget *document = widget(index);
        // Data type, global list and configuration tabs are editors as a whole.
        if (qobject_cast<editors::DataTypeEditor *>(document) || document->property(kWholeTabEditorProperty).toBool())
            lockEditor(document, locked, [this] { Q_EMIT editRefused(); });
        else if (auto *declarations = document->findChild<editors::DeclarationEditor *>())
            lockEditor(declarations, locked, [this] { Q_EMIT editRefused(); });
    }
}

DocumentArea::DocumentArea(model::ProjectModel &projectModel, QWidget *parent)
    : QTabWidget(parent)
    , m_projectModel(projectModel)
    , m_undoStacks(undoStacksOf(parent, this))
{
    setDocumentMode(true);
    setTabsClosable(true);
    setMovable(true);
    editors::registerStandardEditors();
    connect(this, &QTabWidget::tabCloseRequested, this, [this](int index) {
        flushEdits();
        closeDocument(index);
    });
    connect(&projectModel, &model::ProjectModel::projectReset, this, [this] {
        for (int index = count() - 1; index >= 0; --index)
            closeDocument(index);
    });
    connect(&projectModel, &model::ProjectModel::pouRemoved, this,
        [this](model::PouId id) { closeDocumentsIf([id](const BodyRef &ref) { return ref.pou == id; }); });
    connect(&projectModel, &model::ProjectModel::pouRenamed, this, &DocumentArea::retitleDocuments);
    connect(&projectModel, &model::ProjectModel::pouPartsChanged, this, [this] {
        // A renamed action keeps no tab: its BodyRef (by name) no longer finds a body.
        closeDocumentsIf([this](const BodyRef &ref) { return m_projectModel.body(ref) == nullptr; });
        retitleDocuments();
    });
    connect(&projectModel, &model::ProjectModel::bodyTextChanged, this, &DocumentArea::updateTextFromModel);
}

QString DocumentArea::title(const model::Project &project, const BodyRef &ref)
{
    const model::Pou *pou = project.findPou(ref.pou);
    if (!pou)
        return {};
    return ref.part == BodyRef::Part::Pou ? pou->name : pou->name + QLatin1Char('.') + ref.name;
}

BodyRef DocumentArea::refOf(int index) const
{
    return widget(index)->property(kBodyRefProperty).value<BodyRef>();
}

QWidget *DocumentArea::documentFor(const BodyRef &ref) const
{
    for (int index = 0; index < count(); ++index) {
        if (bodyAt(index) == ref)
            return widget(index);
    }
    return nullptr;
}

editors::CodeEditor *DocumentArea::textEditorFor(const BodyRef &ref) const
{
    const editors::TextEditorWidget *textWidget = textWidgetIn(documentFor(ref));
    return textWidget ? textWidget->editor() : nullptr;
}

editors::DeclarationEditor *DocumentArea::declarationEditorFor(const BodyRef &ref) const
{
    const QWidget *document = documentFor(ref);
    return document ? document->findChild<editors::DeclarationEditor *>() : nullptr;
}

std::optional<BodyRef> DocumentArea::bodyAt(int index) const
{
    // Data type tabs show no body.
    if (index < 0 || index >= count() || !widget(index)->property(kBodyRefProperty).isValid())
        return std::nullopt;
    return refOf(index);
}

QList<DocumentArea::OnlineDocument> DocumentArea::onlineViews() const
{
    QList<OnlineDocument> views;
    for (int index = 0; index < count(); ++index) {
        const std::optional<BodyRef> ref = bodyAt(index);
        if (!ref)
            continue;
        QList<QWidget *> widgets = widget(index)->findChildren<QWidget *>();
        widgets.prepend(widget(index));
        for (QWidget *candidate : std::as_const(widgets)) {
            if (auto *view = dynamic_cast<editors::OnlineView *>(candidate))
                views.append({*ref, view});
        }
    }
    return views;
}

std::optional<BodyRef> DocumentArea::currentBody() const
{
    return bodyAt(currentIndex());
}

editors::DataTypeEditor *DocumentArea::dataTypeEditorFor(const QString &typeName) const
{
    for (int index = 0; index < count(); ++index) {
        auto *editor = qobject_cast<editors::DataTypeEditor *>(widget(index));
        if (editor && editor->typeName().compare(typeName, Qt::CaseInsensitive) == 0)
            return editor;
    }
    return nullptr;
}

editors::DataTypeEditor *DocumentArea::currentDataTypeEditor() const
{
    return qobject_cast<editors::DataTypeEditor *>(currentWidget());
}

QWidget *DocumentArea::openDataType(const QString &typeName)
{
    if (editors::DataTypeEditor *open = dataTypeEditorFor(typeName)) {
        setCurrentWidget(open);
        return open;
    }
    if (m_projectModel.dataTypeIndex(typeName) < 0)
        return nullptr;
    auto *editor = new editors::DataTypeEditor(m_projectModel, typeName, &m_undoStacks->projectStack());
    editor->setRenameMembers([this](const QString &type, const Renames &renames, QUndoCommand *gesture) {
        flushEdits();
        addMemberReferenceRenames(m_projectModel, type, renames, gesture);
    });
    connect(editor, &editors::DataTypeEditor::typeRenamed, this, [this, editor](const QString &newName) {
        if (const int index = indexOf(editor); index >= 0)
            setTabText(index, newName);
    });
    // Queued: the editor is inside its own signal when it reports the removal.
    connect(editor, &editors::DataTypeEditor::typeRemoved, editor, [this, editor] {
        if (const int index = indexOf(editor); index >= 0)
            closeDocument(index);
    }, Qt::QueuedConnection);
    const int index = addTab(editor, typeName);
    if (m_editingLocked)
        lockEditor(editor, true, [this] { Q_EMIT editRefused(); });
    setCurrentIndex(index);
    return editor;
}

QWidget *DocumentArea::openBody(const BodyRef &ref)
{
    if (QWidget *open = documentFor(ref)) {
        setCurrentWidget(open);
        return open;
    }
    const model::Body *body = m_projectModel.body(ref);
    if (!body)
        return nullptr;
    QWidget *document = createEditor(ref);
    document->setProperty(kBodyRefProperty, QVariant::fromValue(ref));
    const int index = addTab(document, languageIcon(editors::editorLanguage(*body)), title(m_projectModel.project(), ref));
    if (auto *declarations = document->findChild<editors::DeclarationEditor *>(); declarations && m_editingLocked)
        lockEditor(declarations, true, [this] { Q_EMIT editRefused(); });
    setCurrentIndex(index);
    return document;
}

QWidget *DocumentArea::createEditor(const BodyRef &ref)
{
    QWidget *bodyEditor = createBodyEditor(ref);
    if (ref.part != BodyRef::Part::Pou)
        return bodyEditor;
    auto *splitter = new QSplitter(Qt::Vertical);
    splitter->setChildrenCollapsible(false);
    auto *declarations = new editors::DeclarationEditor(m_projectModel, ref.pou, m_undoStacks->pouStack(ref.pou));
    // A renamed variable renames its uses too; typing not yet in the model is pushed first.
    declarations->setRenameReferences([this](model::PouId pou, const Renames &renames, QUndoCommand *gesture) {
        flushEdits();
        addVariableReferenceRenames(m_projectModel, pou, renames, gesture);
    });
    splitter->addWidget(declarations);
    splitter->addWidget(bodyEditor);
    splitter->setStretchFactor(0, 1);
    splitter->setStretchFactor(1, 2);
    return splitter;
}

QWidget *DocumentArea::createBodyEditor(const BodyRef &ref)
{
    const model::Body *body = m_projectModel.body(ref);
    const editors::EditorLanguage language = editors::editorLanguage(*body);
    if (const editors::EditorFactory *factory = editors::EditorRegistry::instance().find(language))
        return createDiagramEditor(*factory, ref);
    if (language != editors::EditorLanguage::ST && language != editors::EditorLanguage::IL) {
        auto *placeholder = new QLabel(tr("This body is written in %1. Its editor is not available in this "
                                          "version; the body is kept unchanged when the project is saved.")
                                           .arg(editors::editorLanguageName(language)));
        placeholder->setAlignment(Qt::AlignCenter);
        placeholder->setWordWrap(true);
        return placeholder;
    }
    auto *textWidget = new editors::TextEditorWidget(
        language == editors::EditorLanguage::IL ? editors::TextLanguage::IL : editors::TextLanguage::ST);
    textWidget->setOnlineInstanceProvider([this, ref] { return onlineInstanceOf(m_projectModel.project(), ref.pou); });
    connect(textWidget, &editors::TextEditorWidget::addToWatchRequested, this, &DocumentArea::addToWatchRequested);
    editors::CodeEditor *editor = textWidget->editor();
    editor->setBodyText(body->text());
    editor->document()->setModified(false);
    connect(editor->document(), &QTextDocument::modificationChanged, this, &DocumentArea::typingModifiedChanged);
    connect(editor, &editors::CodeEditor::textEdited, this,
        [this, ref, editor] { m_projectModel.setBodyText(ref, editor->toPlainText()); });
    // Completion reads the model when asked, so it always sees the current declarations.
    auto *completion = new ModelCompletionProvider(m_projectModel, ref.pou);
    editor->setCompletionProvider(completion);
    connect(textWidget, &QObject::destroyed, this, [completion] { delete completion; });
    connect(editor, &editors::CodeEditor::definitionRequested, this,
        [this, ref](const QString &path) { goToDefinition(ref, path); });
    auto *declare = new QAction(tr("Declare Variable..."), editor);
    declare->setObjectName(QStringLiteral("declareVariableAction"));
    declare->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_F2));
    declare->setShortcutContext(Qt::WidgetShortcut);
    connect(declare, &QAction::triggered, this, [this, ref] { autoDeclareInteractive(ref); });
    editor->addAction(declare);
    return textWidget;
}

QWidget *DocumentArea::createDiagramEditor(const editors::EditorFactory &factory, const BodyRef &ref)
{
    editors::DiagramEditor *editor = factory.createEditor(m_projectModel, ref, &m_undoStacks->pouStack(ref.pou));
    editor->setOnlineInstance(onlineInstanceOf(m_projectModel.project(), ref.pou));
    editor->setGridSize(m_gridSize);
    // Double-click on an action, a named transition or an "E"/"X" corner opens that body.
    connect(editor, &editors::DiagramEditor::openPartRequested, this,
        [this](model::PouId pou, BodyRef::Part part, const QString &name) { openBody(BodyRef {pou, part, name}); });
    connect(editor, &editors::DiagramEditor::prepareValueRequested, this, &DocumentArea::prepareValueRequested);
    connect(editor, &editors::DiagramEditor::declareVariableRequested, this,
        [this, editor](const BodyRef &body, const QString &name) { declareInteractive(body, name, editor); });
    // Completion reads the model when asked, so it always sees the current declarations.
    auto *completion = new ModelCompletionProvider(m_projectModel, ref.pou);
    editor->setCompletionProvider(completion);
    connect(editor, &QObject::destroyed, this, [completion] { delete completion; });
    return editor;
}

editors::DiagramEditor *DocumentArea::diagramEditorFor(const BodyRef &ref) const
{
    QWidget *document = documentFor(ref);
    if (auto *editor = qobject_cast<editors::DiagramEditor *>(document))
        return editor;
    return document ? document->findChild<editors::DiagramEditor *>() : nullptr;
}

editors::DiagramEditor *DocumentArea::currentDiagramEditor() const
{
    const std::optional<BodyRef> ref = currentBody();
    return ref ? diagramEditorFor(*ref) : nullptr;
}

void DocumentArea::setGridSize(int size)
{
    m_gridSize = size;
    for (int index = 0; index < count(); ++index) {
        if (const std::optional<BodyRef> ref = bodyAt(index)) {
            if (editors::DiagramEditor *editor = diagramEditorFor(*ref))
                editor->setGridSize(size);
        }
    }
}

bool DocumentArea::goToDefinition(const BodyRef &from, const QString &path)
{
    const model::Project &project = m_projectModel.project();
    const int dot = path.lastIndexOf(QLatin1Char('.'));
    const QString head = path.section(QLatin1Char('.'), 0, 0).section(QLatin1Char('['), 0, 0).trimmed();
    const auto showDeclaration = [this](model::PouId pou, const QString &name) {
        openBody({pou, BodyRef::Part::Pou, {}});
        editors::DeclarationEditor *declarations = declarationEditorFor({pou, BodyRef::Part::Pou, {}});
        return declarations && declarations->showVariable(name);
    };
    if (dot > 0) {
        // A member: its declaration in the function block or program the prefix is an instance of.
        if (const model::Pou *owner = project.findPou(typeNameOfPath(project, from.pou, path.left(dot))))
            return showDeclaration(owner->id, path.mid(dot + 1));
        return showGlobalVariable(path.left(dot), path.mid(dot + 1)); // List.Variable
    }
    if (const auto visible = findVisibleVariable(project, from.pou, head))
        return visible->global ? showGlobalVariable({}, visible->variable->name)
                               : showDeclaration(from.pou, visible->variable->name);
    if (const model::Pou *pou = project.findPou(head))
        return openBody({pou->id, BodyRef::Part::Pou, {}}) != nullptr;
    if (project.findDataType(head))
        return openDataType(head) != nullptr;
    for (const auto part : {BodyRef::Part::Action, BodyRef::Part::Transition}) {
        if (const model::PouPart *found = m_projectModel.findPouPart(from.pou, part, head))
            return openBody({from.pou, part, found->name}) != nullptr;
    }
    return false;
}

namespace {

// In a diagram, a name written as a box's instance has the box's type (Blinker on a BLINK box).
QString instanceTypeIn(const model::Body &body, const QString &name)
{
    if (const std::vector<model::Element> *elements = body.elements()) {
        for (const model::Element &element : *elements) {
            const auto *block = std::get_if<model::Block>(&element);
            if (block && block->instanceName && block->instanceName->compare(name, Qt::CaseInsensitive) == 0)
                return block->typeName;
        }
    }
    return {};
}

} // namespace

editors::DeclarationRow DocumentArea::proposeDeclaration(const BodyRef &ref, const QString &name) const
{
    const model::Body *body = m_projectModel.body(ref);
    editors::DeclarationRow row;
    row.name = name;
    row.type = body ? instanceTypeIn(*body, name) : QString();
    if (row.type.isEmpty())
        row.type = guessVariableType(m_projectModel.project(), ref.pou, body ? body->text() : QString(), name,
            body && body->language() == model::BodyLanguage::IL);
    return row;
}

bool DocumentArea::declareVariable(const BodyRef &ref, const editors::DeclarationRow &row, QString *error)
{
    flushEdits();
    const DeclareResult result = createDeclareCommand(m_projectModel, ref.pou, row);
    if (!result.command) {
        if (error)
            *error = result.error;
        return false;
    }
    m_undoStacks->pouStack(ref.pou).push(result.command);
    return true;
}

namespace {

// What the type box offers: the elementary types, the common standard function blocks, the
// project's data types and function blocks.
QStringList declarableTypeNames(const model::Project &project)
{
    QStringList names {QStringLiteral("BOOL"), QStringLiteral("INT"), QStringLiteral("DINT"), QStringLiteral("UINT"),
        QStringLiteral("REAL"), QStringLiteral("LREAL"), QStringLiteral("TIME"), QStringLiteral("STRING"),
        QStringLiteral("BYTE"), QStringLiteral("WORD"), QStringLiteral("DWORD")};
    names += commonFunctionBlocks();
    for (const model::DataTypeDecl &type : project.types.dataTypes)
        names.append(type.name);
    for (const model::Pou &pou : project.types.pous) {
        if (pou.kind == model::PouKind::FunctionBlock)
            names.append(pou.name);
    }
    return names;
}

} // namespace

void DocumentArea::autoDeclareInteractive(const BodyRef &ref)
{
    editors::CodeEditor *editor = textEditorFor(ref);
    if (!editor)
        return;
    const QString path = editor->identifierPathAt(editor->textCursor().position());
    const QString name = path.section(QLatin1Char('.'), 0, 0).section(QLatin1Char('['), 0, 0).trimmed();
    if (name.isEmpty())
        return;
    declareInteractive(ref, name, editor, editor->cursorRect().bottomLeft());
}

void DocumentArea::declareInteractive(const BodyRef &ref, const QString &name, QWidget *anchor, QPoint at)
{
    flushEdits();
    const model::Project &project = m_projectModel.project();
    if (findVisibleVariable(project, ref.pou, name) || project.findPou(name)) {
        QToolTip::showText(anchor->mapToGlobal(at), tr("%1 is declared already.").arg(name), anchor);
        return;
    }
    const BodyRef pouBody {ref.pou, BodyRef::Part::Pou, {}};
    AutoDeclareDialog dialog(proposeDeclaration(ref, name), declarableTypeNames(project),
        [this, pouBody](const editors::DeclarationRow &row) {
            const DeclareResult check = createDeclareCommand(m_projectModel, pouBody.pou, row);
            delete check.command;
            return check.error;
        },
        this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    QString error;
    if (!declareVariable(ref, dialog.row(), &error))
        QToolTip::showText(anchor->mapToGlobal(at), error, anchor);
}

void DocumentArea::flushEdits()
{
    for (int index = 0; index < count(); ++index) {
        auto *declarations = qobject_cast<editors::DeclarationEditorBase *>(widget(index));
        if (!declarations)
            declarations = widget(index)->findChild<editors::DeclarationEditorBase *>();
        if (declarations)
            declarations->flushPendingEdit();
        if (auto *textWidget = textWidgetIn(widget(index)))
            textWidget->editor()->flushPendingEdit();
    }
}

void DocumentArea::updateTextFromModel(const BodyRef &ref)
{
    // The editor's own edits come back here too; only a change made elsewhere (a rename that
    // rewrote references, an undo of such a change) replaces the editor's text.
    editors::CodeEditor *editor = textEditorFor(ref);
    const model::Body *body = m_projectModel.body(ref);
    if (editor && body && editor->toPlainText() != body->text()) {
        // The replaced text came from an undoable command; typing before it is still unsaved.
        const bool typedBefore = editor->document()->isModified();
        editor->setBodyTextKeepingCursor(body->text());
        editor->document()->setModified(typedBefore);
    }
}

bool DocumentArea::hasUnsavedTyping() const
{
    if (m_typingInClosedDocuments)
        return true;
    for (int index = 0; index < count(); ++index) {
        if (const auto *textWidget = textWidgetIn(widget(index))) {
            if (textWidget->editor()->document()->isModified())
                return true;
        }
    }
    return false;
}

void DocumentArea::markTypingSaved()
{
    m_typingInClosedDocuments = false;
    for (int index = 0; index < count(); ++index) {
        if (auto *textWidget = textWidgetIn(widget(index)))
            textWidget->editor()->document()->setModified(false);
    }
    Q_EMIT typingModifiedChanged();
}

void DocumentArea::closeDocument(int index)
{
    // The typing is in the model by now (flushed), but no undo stack remembers it.
    if (const auto *textWidget = textWidgetIn(widget(index))) {
        if (textWidget->editor()->document()->isModified())
            m_typingInClosedDocuments = true;
    }
    // Out of the tabs first: focus leaving the dying widgets asks for the current document, which
    // must not find one half destroyed.
    QWidget *document = widget(index);
    removeTab(index);
    delete document;
    Q_EMIT typingModifiedChanged();
}

void DocumentArea::activateNext()
{
    if (count() > 0)
        setCurrentIndex((currentIndex() + 1) % count());
}

void DocumentArea::activatePrevious()
{
    if (count() > 0)
        setCurrentIndex((currentIndex() + count() - 1) % count());
}

void DocumentArea::closeAll()
{
    flushEdits();
    for (int index = count() - 1; index >= 0; --index)
        closeDocument(index);
}

void DocumentArea::closeDocumentsIf(const std::function<bool(const BodyRef &)> &shouldClose)
{
    for (int index = count() - 1; index >= 0; --index) {
        const std::optional<BodyRef> ref = bodyAt(index);
        if (ref && shouldClose(*ref))
            closeDocument(index);
    }
}

void DocumentArea::retitleDocuments()
{
    for (int index = 0; index < count(); ++index) {
        if (const std::optional<BodyRef> ref = bodyAt(index))
            setTabText(index, title(m_projectModel.project(), *ref));
    }
}

} // namespace iec::app
