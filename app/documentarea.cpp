#include "app/documentarea.h"

#include "app/treeicons.h"
#include "app/undostacks.h"
#include "editors/declarations/declarationeditor.h"
#include "editors/text/codeeditor.h"
#include "editors/text/texteditorwidget.h"
#include "model/projectmodel.h"

#include <QLabel>
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
editors::TextEditorWidget *textWidgetIn(QWidget *document)
{
    if (auto *textWidget = qobject_cast<editors::TextEditorWidget *>(document))
        return textWidget;
    return document ? document->findChild<editors::TextEditorWidget *>() : nullptr;
}

} // namespace

DocumentArea::DocumentArea(model::ProjectModel &projectModel, QWidget *parent)
    : QTabWidget(parent)
    , m_projectModel(projectModel)
    , m_undoStacks(undoStacksOf(parent, this))
{
    setDocumentMode(true);
    setTabsClosable(true);
    setMovable(true);
    connect(this, &QTabWidget::tabCloseRequested, this, [this](int index) {
        flushEdits();
        closeDocument(index);
    });
    connect(&projectModel, &model::ProjectModel::projectReset, this,
        [this] { closeDocumentsIf([](const BodyRef &) { return true; }); });
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
        if (refOf(index) == ref)
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
    if (index < 0 || index >= count())
        return std::nullopt;
    return refOf(index);
}

std::optional<BodyRef> DocumentArea::currentBody() const
{
    if (currentIndex() < 0)
        return std::nullopt;
    return refOf(currentIndex());
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
    const int index = addTab(document, languageIcon(body->language()), title(m_projectModel.project(), ref));
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
    splitter->addWidget(new editors::DeclarationEditor(m_projectModel, ref.pou, m_undoStacks->pouStack(ref.pou)));
    splitter->addWidget(bodyEditor);
    splitter->setStretchFactor(0, 1);
    splitter->setStretchFactor(1, 2);
    return splitter;
}

QWidget *DocumentArea::createBodyEditor(const BodyRef &ref)
{
    const model::Body *body = m_projectModel.body(ref);
    if (body->language() != model::BodyLanguage::ST && body->language() != model::BodyLanguage::IL) {
        auto *placeholder = new QLabel(tr("This body is written in %1. Its editor is not available in this "
                                          "version; the body is kept unchanged when the project is saved.")
                                           .arg(languageName(body->language())));
        placeholder->setAlignment(Qt::AlignCenter);
        placeholder->setWordWrap(true);
        return placeholder;
    }
    const auto language
        = body->language() == model::BodyLanguage::IL ? editors::TextLanguage::IL : editors::TextLanguage::ST;
    auto *textWidget = new editors::TextEditorWidget(language);
    editors::CodeEditor *editor = textWidget->editor();
    editor->setBodyText(body->text());
    editor->document()->setModified(false);
    connect(editor->document(), &QTextDocument::modificationChanged, this, &DocumentArea::typingModifiedChanged);
    connect(editor, &editors::CodeEditor::textEdited, this,
        [this, ref, editor] { m_projectModel.setBodyText(ref, editor->toPlainText()); });
    return textWidget;
}

void DocumentArea::flushEdits()
{
    for (int index = 0; index < count(); ++index) {
        if (auto *declarations = widget(index)->findChild<editors::DeclarationEditor *>())
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
        editor->setBodyText(body->text());
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
        if (shouldClose(refOf(index)))
            closeDocument(index);
    }
}

void DocumentArea::retitleDocuments()
{
    for (int index = 0; index < count(); ++index)
        setTabText(index, title(m_projectModel.project(), refOf(index)));
}

} // namespace iec::app
