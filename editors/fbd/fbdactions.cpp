// The FBD editor's commands as one table (DiagramEditor::ActionSpec): the Insert menu of RunPro /
// CoDeSys 2.3 (seed 002 §2: 输入, 输出, 运算符, 赋值, 跳转, 返回, 反向, 置位/复位), the window's
// Insert and Edit menus, the tool bar and the keys (CoDeSys 2.3's where the window does not use
// them; docs/editors-fbd.md lists them).
#include "editors/fbd/fbdeditor.h"

#include "editors/common/diagramclipboard.h"

namespace iec::editors::fbd {

using namespace model;
using Kind = FbdCursor::Kind;

void FbdEditor::createActions()
{
    using G = ActionGroup;
    const auto always = [] { return true; };
    const auto hasNetwork = [this] { return !document().networks.empty(); };
    const auto atInputOrBox = [this] { return cursorIs({Kind::Input, Kind::Box}); };
    const auto atPlace = [this] { return cursorIs({Kind::Input, Kind::Output, Kind::Crossing, Kind::End, Kind::Text, Kind::Network, Kind::Box}); };
    const auto atNegatable = [this] { return cursorIs({Kind::Input, Kind::Output, Kind::Crossing, Kind::Text}); };
    const auto atAssignment = [this] { return cursorIs({Kind::Crossing, Kind::Text, Kind::Output}); };
    const auto atInput = [this] { return cursorIs({Kind::Input, Kind::Text}); };
    const auto atElement = [this] { return cursorIs({Kind::Text, Kind::Box}); };
    const auto atSomething = [this] { return cursorIs({Kind::Network, Kind::Text, Kind::Box, Kind::Input, Kind::Output, Kind::Crossing}); };
    const ActionSpec specs[] = {
        {"fbdNetworkBefore", QT_TR_NOOP("&Network Before"), "Ctrl+I", G::Insert, true, false, [this] { insertNetwork(false); }, always},
        {"fbdNetworkAfter", QT_TR_NOOP("Network Aft&er"), "Ctrl+T", G::Insert, true, true, [this] { insertNetwork(true); }, always,
            QT_TR_NOOP("Network")},
        {"fbdOperator", QT_TR_NOOP("&Operator"), "Ctrl+Shift+B", G::Insert, true, true, [this] { insertOperator(); }, atPlace,
            QT_TR_NOOP("Operator")},
        {"fbdBoxWithEn", QT_TR_NOOP("Box with E&N…"), "Ctrl+Shift+E", G::Insert, true, false, [this] { askBoxWithEn(); }, atPlace},
        {"fbdInput", QT_TR_NOOP("&Input"), "Ctrl+U", G::Insert, true, true, [this] { insertInput(); }, atInputOrBox},
        {"fbdOutput", QT_TR_NOOP("O&utput"), "Ctrl+Shift+U", G::Insert, true, true, [this] { insertOutput(); }, atPlace},
        {"fbdAssignment", QT_TR_NOOP("&Assignment"), "Ctrl+A", G::Insert, true, true, [this] { insertAssignment(); }, atPlace},
        {"fbdJump", QT_TR_NOOP("&Jump…"), "Ctrl+L", G::Insert, true, true, [this] { askJump(); }, atPlace},
        {"fbdReturn", QT_TR_NOOP("&Return"), "Ctrl+R", G::Insert, true, false, [this] { insertReturn(); }, atPlace},
        {"fbdLabel", QT_TR_NOOP("La&bel…"), "Ctrl+Shift+J", G::Insert, true, false, [this] { askLabel(); }, hasNetwork},
        {"fbdComment", QT_TR_NOOP("Co&mment…"), "Ctrl+Shift+K", G::Insert, true, false, [this] { askComment(); }, hasNetwork},
        {"fbdNegate", QT_TR_NOOP("Ne&gate"), "Ctrl+Shift+N", G::Element, true, true, [this] { toggleNegation(); }, atNegatable},
        {"fbdSetReset", QT_TR_NOOP("&Set/Reset"), "Ctrl+M", G::Element, true, true, [this] { cycleSetReset(); }, atAssignment,
            QT_TR_NOOP("S/R")},
        {"fbdEdge", QT_TR_NOOP("E&dge (Rising/Falling)"), "Ctrl+E", G::Element, true, false, [this] { cycleEdge(); }, atInput},
        {"fbdRename", QT_TR_NOOP("Edit &Name"), "F2", G::Element, true, false, [this] { startTyping(); }, atElement},
        {"fbdCut", QT_TR_NOOP("Cu&t"), "Ctrl+X", G::Edit, true, false, [this] { cut(); }, atSomething},
        {"fbdCopy", QT_TR_NOOP("&Copy"), "Ctrl+C", G::Edit, false, false, [this] { copy(); }, atSomething},
        {"fbdPaste", QT_TR_NOOP("&Paste"), "Ctrl+V", G::Edit, true, false, [this] { paste(); }, [] { return clipboardHasElements(); }},
        {"fbdDelete", QT_TR_NOOP("&Delete"), "Del", G::Edit, true, true, [this] { deleteAtCursor(); }, atSomething},
    };
    addActionTable(specs);
}

} // namespace iec::editors::fbd
