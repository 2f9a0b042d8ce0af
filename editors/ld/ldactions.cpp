// The LD editor's commands as one table (DiagramEditor::ActionSpec): the right-click menu of
// RunPro (seed 002 §1: 前节 N, 后节 E, 串联 O, 并联触点 P, 功能块 F, 线圈 L, 使能运算符 E,
// 插入选项 K, 跳转 J, 返回 R, 注释 C — the Chinese translations carry these mnemonics), the
// window's Insert and Edit menus, the tool bar and the keys (CODESYS V3's shortcuts where it has
// one; docs/editors-ld.md lists them).
#include "editors/ld/ldeditor.h"

#include "editors/common/diagramclipboard.h"

namespace iec::editors::ld {

using namespace model;

namespace {

bool isContactOrCoil(const Element &e)
{
    return std::holds_alternative<Contact>(e) || std::holds_alternative<Coil>(e);
}

bool isCoil(const Element &e)
{
    return std::holds_alternative<Coil>(e);
}

bool isBoxOrSideVariable(const Element &e)
{
    return std::holds_alternative<Block>(e) || std::holds_alternative<InVariable>(e);
}

bool isSideVariable(const Element &e)
{
    return std::holds_alternative<InVariable>(e);
}

} // namespace

void LdEditor::createActions()
{
    using G = ActionGroup;
    const auto always = [] { return true; };
    const auto onElement = [this] { return cursorOnElement(); };
    const auto onNetworkOrElement = [this] { return m_cursor.kind != LdCursor::Kind::Wire && !document().networks.empty(); };
    const auto hasNetwork = [this] { return !document().networks.empty(); };
    const ActionSpec specs[] = {
        {"ldNetworkBefore", QT_TR_NOOP("&Network Before"), "Ctrl+I", G::Insert, true, false, [this] { insertNetwork(false); }, always},
        {"ldNetworkAfter", QT_TR_NOOP("Network Aft&er"), "Ctrl+T", G::Insert, true, true, [this] { insertNetwork(true); }, always,
            QT_TR_NOOP("Network")},
        {"ldContact", QT_TR_NOOP("C&ontact"), "Ctrl+K", G::Insert, true, true, [this] { insertContact(); }, hasNetwork},
        {"ldParallelContact", QT_TR_NOOP("&Parallel Contact (Below)"), "Ctrl+R", G::Insert, true, true,
            [this] { insertParallelContact(true); }, onElement, QT_TR_NOOP("Parallel")},
        {"ldParallelContactAbove", QT_TR_NOOP("Parallel Contact (Abo&ve)"), "Ctrl+Shift+R", G::Insert, true, false,
            [this] { insertParallelContact(false); }, onElement},
        {"ldFunctionBlock", QT_TR_NOOP("&Function Block…"), "Ctrl+Shift+B", G::Insert, true, true, [this] { askBoxType(false); }, hasNetwork,
            QT_TR_NOOP("Box…")},
        {"ldCoil", QT_TR_NOOP("Coi&l"), "Ctrl+A", G::Insert, true, true, [this] { insertCoil(); }, hasNetwork},
        {"ldBoxWithEn", QT_TR_NOOP("Box with E&N…"), "Ctrl+Shift+E", G::Insert, true, false, [this] { askBoxType(true); }, hasNetwork},
        {"ldBoxInput", QT_TR_NOOP("Insert at Box: In&put"), "Ctrl+Q", G::Insert, true, false, [this] { insertBoxInput(); },
            [this] { return cursorOn(&isBoxOrSideVariable); }},
        {"ldBoxAssignment", QT_TR_NOOP("Insert at Box: &Assignment"), "Ctrl+Shift+A", G::Insert, true, false,
            [this] { insertBoxAssignment(); }, [this] { return cursorOn(&isBoxOrSideVariable); }},
        {"ldBoxOperator", QT_TR_NOOP("Insert at Box: Operato&r"), "Ctrl+Shift+O", G::Insert, true, false,
            [this] { insertOperatorAtInput(); }, [this] { return cursorOn(&isSideVariable); }},
        {"ldJump", QT_TR_NOOP("&Jump…"), "Ctrl+L", G::Insert, true, true, [this] { askJump(); }, hasNetwork},
        {"ldReturn", QT_TR_NOOP("&Return"), "Ctrl+Shift+L", G::Insert, true, false, [this] { insertReturn(); }, hasNetwork},
        {"ldLabel", QT_TR_NOOP("La&bel…"), "Ctrl+Shift+J", G::Insert, true, false, [this] { askLabel(); }, hasNetwork},
        {"ldComment", QT_TR_NOOP("Co&mment…"), "Ctrl+Shift+K", G::Insert, true, true, [this] { askComment(); }, hasNetwork},
        {"ldNegate", QT_TR_NOOP("Ne&gate"), "Ctrl+Shift+N", G::Element, true, true, [this] { toggleNegation(); },
            [this] { return cursorOn(&isContactOrCoil); }},
        {"ldSetReset", QT_TR_NOOP("&Set/Reset"), "Ctrl+M", G::Element, true, true, [this] { cycleSetReset(); },
            [this] { return cursorOn(&isCoil); }, QT_TR_NOOP("S/R")},
        {"ldEdge", QT_TR_NOOP("E&dge (P/N)"), "Ctrl+E", G::Element, true, false, [this] { cycleEdge(); },
            [this] { return cursorOn(&isContactOrCoil); }},
        {"ldRename", QT_TR_NOOP("Edit &Name"), "F2", G::Element, true, false, [this] { startTyping(m_cursor.element()); }, onElement},
        {"ldCut", QT_TR_NOOP("Cu&t"), "Ctrl+X", G::Edit, true, false, [this] { cut(); }, onNetworkOrElement},
        {"ldCopy", QT_TR_NOOP("&Copy"), "Ctrl+C", G::Edit, false, false, [this] { copy(); }, onNetworkOrElement},
        {"ldPaste", QT_TR_NOOP("&Paste"), "Ctrl+V", G::Edit, true, false, [this] { paste(PasteMode::After); },
            [] { return clipboardHasElements(); }},
        {"ldPasteBelow", QT_TR_NOOP("Paste &Below"), "Ctrl+Shift+V", G::Edit, true, false, [this] { paste(PasteMode::Below); },
            [this] { return clipboardHasElements() && cursorOnElement(); }},
        {"ldPasteAbove", QT_TR_NOOP("Paste Abo&ve"), "Ctrl+Alt+V", G::Edit, true, false, [this] { paste(PasteMode::Above); },
            [this] { return clipboardHasElements() && cursorOnElement(); }},
        {"ldDelete", QT_TR_NOOP("&Delete"), "Del", G::Edit, true, true, [this] { deleteAtCursor(); }, onNetworkOrElement},
    };
    addActionTable(specs);
}

} // namespace iec::editors::ld
