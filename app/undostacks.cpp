#include "app/undostacks.h"

#include <QUndoGroup>
#include <QUndoStack>

#include <algorithm>

namespace iec::app {

UndoStacks::UndoStacks(QObject *parent)
    : QObject(parent)
    , m_group(new QUndoGroup(this))
    , m_projectStack(new QUndoStack(this))
{
    m_projectStack->setObjectName(QStringLiteral("projectUndoStack"));
    adopt(m_projectStack);
    m_group->setActiveStack(m_projectStack);
}

void UndoStacks::adopt(QUndoStack *stack)
{
    m_group->addStack(stack);
    connect(stack, &QUndoStack::cleanChanged, this, &UndoStacks::cleanChanged);
}

QUndoStack &UndoStacks::pouStack(model::PouId pou)
{
    auto [it, inserted] = m_pouStacks.try_emplace(pou, nullptr);
    if (inserted) {
        it->second = new QUndoStack(this);
        it->second->setObjectName(QStringLiteral("pouUndoStack%1").arg(pou.value));
        adopt(it->second);
    }
    return *it->second;
}

void UndoStacks::activateProjectStack()
{
    m_group->setActiveStack(m_projectStack);
}

void UndoStacks::activatePouStack(model::PouId pou)
{
    m_group->setActiveStack(&pouStack(pou));
}

bool UndoStacks::isClean() const
{
    if (!m_projectStack->isClean())
        return false;
    return std::ranges::all_of(m_pouStacks, [](const auto &entry) { return entry.second->isClean(); });
}

void UndoStacks::setClean()
{
    m_projectStack->setClean();
    for (const auto &[pou, stack] : m_pouStacks)
        stack->setClean();
}

void UndoStacks::clear()
{
    m_group->setActiveStack(m_projectStack);
    for (const auto &[pou, stack] : m_pouStacks)
        delete stack;
    m_pouStacks.clear();
    m_projectStack->clear();
    Q_EMIT cleanChanged();
}

} // namespace iec::app
