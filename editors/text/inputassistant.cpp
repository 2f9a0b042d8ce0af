#include "editors/text/inputassistant.h"

#include "editors/text/standardlibrary.h"

#include <QDialogButtonBox>
#include <QHash>
#include <QHeaderView>
#include <QKeyEvent>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSplitter>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace iec::editors {

InputAssistantDialog::InputAssistantDialog(TextLanguage language, const CompletionProvider *provider, QWidget *parent)
    : QDialog(parent)
{
    setWindowTitle(tr("Input Assistant"));
    setObjectName(QStringLiteral("inputAssistant"));

    m_categories = new QListWidget(this);
    m_categories->addItems({tr("Operators"), tr("Operands"), tr("Functions"), tr("Function blocks")});
    m_categories->setMaximumWidth(180);

    m_filter = new QLineEdit(this);
    m_filter->setPlaceholderText(tr("Filter"));
    m_filter->setClearButtonEnabled(true);

    m_items = new QTreeWidget(this);
    m_items->setColumnCount(2);
    m_items->setHeaderLabels({tr("Name"), tr("Description")});
    m_items->setRootIsDecorated(true);
    m_items->setUniformRowHeights(true);
    m_items->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);

    auto *splitter = new QSplitter(this);
    splitter->addWidget(m_categories);
    splitter->addWidget(m_items);
    splitter->setStretchFactor(1, 1);

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_filter);
    layout->addWidget(splitter, 1);
    layout->addWidget(buttons);
    resize(640, 420);

    buildEntries(language, provider);

    connect(m_categories, &QListWidget::currentRowChanged, this, [this] { populate(); });
    connect(m_filter, &QLineEdit::textChanged, this, [this] { populate(); });
    connect(m_items, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem *item) {
        if (item && item->childCount() == 0)
            chooseCurrent();
    });
    connect(buttons, &QDialogButtonBox::accepted, this, &InputAssistantDialog::chooseCurrent);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    m_categories->setCurrentRow(0);
    m_items->setFocus();
}

void InputAssistantDialog::buildEntries(TextLanguage language, const CompletionProvider *provider)
{
    auto &operators = m_entries[int(Category::Operators)];
    const QString operatorGroup = language == TextLanguage::IL ? tr("IL operators") : tr("ST operators");
    for (const IlOperator &op : language == TextLanguage::IL ? ilOperators() : stOperators())
        operators.append({operatorGroup, op.text, op.description});

    auto &operands = m_entries[int(Category::Operands)];
    if (provider) {
        for (const CompletionItem &item : provider->variables())
            operands.append({item.category.isEmpty() ? tr("Variables") : item.category, item.text, item.detail});
    }
    operands.append({tr("Boolean constants"), QStringLiteral("TRUE"), {}});
    operands.append({tr("Boolean constants"), QStringLiteral("FALSE"), {}});

    auto &functions = m_entries[int(Category::Functions)];
    auto &blocks = m_entries[int(Category::FunctionBlocks)];
    for (const StdPou &pou : standardPous()) {
        auto &target = pou.kind == StdPou::Kind::Function ? functions : blocks;
        target.append({stdCategoryName(pou.category), pou.name, pou.signature()});
    }
    if (provider) {
        for (const CompletionItem &pou : provider->pous()) {
            if (pou.kind == CompletionItem::Kind::Function)
                functions.append({tr("User-defined functions"), pou.text, pou.detail});
            else if (pou.kind == CompletionItem::Kind::FunctionBlock)
                blocks.append({tr("User-defined function blocks"), pou.text, pou.detail});
            else if (pou.kind == CompletionItem::Kind::Program)
                blocks.append({tr("Programs"), pou.text, pou.detail});
        }
    }
}

void InputAssistantDialog::populate()
{
    m_items->clear();
    const int row = std::max(0, m_categories->currentRow());
    const QString filter = m_filter->text().trimmed();
    QHash<QString, QTreeWidgetItem *> groups;
    for (const Entry &entry : m_entries[row]) {
        if (!filter.isEmpty() && !entry.text.contains(filter, Qt::CaseInsensitive))
            continue;
        QTreeWidgetItem *&group = groups[entry.group];
        if (!group) {
            group = new QTreeWidgetItem(m_items, {entry.group});
            QFont bold = group->font(0);
            bold.setBold(true);
            group->setFont(0, bold);
            group->setFlags(Qt::ItemIsEnabled);
            group->setFirstColumnSpanned(true);
        }
        new QTreeWidgetItem(group, {entry.text, entry.description});
    }
    m_items->expandAll();
    if (m_items->topLevelItemCount() > 0 && m_items->topLevelItem(0)->childCount() > 0)
        m_items->setCurrentItem(m_items->topLevelItem(0)->child(0));
}

void InputAssistantDialog::setCategory(Category category)
{
    m_categories->setCurrentRow(int(category));
}

InputAssistantDialog::Category InputAssistantDialog::category() const
{
    return Category(std::max(0, m_categories->currentRow()));
}

void InputAssistantDialog::setFilter(const QString &text)
{
    m_filter->setText(text);
}

QStringList InputAssistantDialog::itemTexts() const
{
    QStringList texts;
    for (int g = 0; g < m_items->topLevelItemCount(); ++g) {
        const QTreeWidgetItem *group = m_items->topLevelItem(g);
        for (int i = 0; i < group->childCount(); ++i)
            texts.append(group->child(i)->text(0));
    }
    return texts;
}

bool InputAssistantDialog::selectItem(const QString &text)
{
    for (int g = 0; g < m_items->topLevelItemCount(); ++g) {
        QTreeWidgetItem *group = m_items->topLevelItem(g);
        for (int i = 0; i < group->childCount(); ++i) {
            if (group->child(i)->text(0) == text) {
                m_items->setCurrentItem(group->child(i));
                return true;
            }
        }
    }
    return false;
}

QString InputAssistantDialog::selectedText() const
{
    const QTreeWidgetItem *item = m_items->currentItem();
    return item && item->childCount() == 0 && item->parent() ? item->text(0) : QString();
}

void InputAssistantDialog::chooseCurrent()
{
    const QString text = selectedText();
    if (text.isEmpty())
        return;
    Q_EMIT itemChosen(text);
    accept();
}

} // namespace iec::editors
