// The CFC editor's commands as one table (DiagramEditor::ActionSpec): the Insert menu of CoDeSys
// 2.3's CFC (seed 002 §6; box, input, output, jump, label, return, comment, connection marks), the
// execution-order commands of its Extras menu, the window's Edit menu, the tool bar and the keys
// (docs/editors-cfc.md lists them). The Insert buttons of the tool bar also drag their element
// onto the sheet.
#include "editors/cfc/cfceditor.h"

#include "editors/common/diagramclipboard.h"

namespace iec::editors::cfc {

void CfcEditor::createActions()
{
    using G = ActionGroup;
    const auto always = [] { return true; };
    const auto selected = [this] { return !selectedIds().empty(); };
    const auto one = [this] { return selectedIds().size() == 1; };
    const auto oneBox = [this] {
        const std::vector<quint64> ids = selectedIds();
        const model::Element *e = ids.size() == 1 ? element(ids.front()) : nullptr;
        return e && std::holds_alternative<model::Block>(*e);
    };
    const auto runs = [this] { return selectionRuns(); };
    const auto many = [this] { return !executionOrder(elements()).empty(); };
    const ActionSpec specs[] = {
        {"cfcBox", QT_TR_NOOP("&Box"), "Ctrl+Shift+B", G::Insert, true, true, [this] { insertBox(); }, always, QT_TR_NOOP("Box")},
        {"cfcInput", QT_TR_NOOP("&Input"), "Ctrl+E", G::Insert, true, true, [this] { insertInput(); }, always, QT_TR_NOOP("Input")},
        {"cfcOutput", QT_TR_NOOP("O&utput"), "Ctrl+A", G::Insert, true, true, [this] { insertOutput(); }, always, QT_TR_NOOP("Output")},
        {"cfcJump", QT_TR_NOOP("&Jump"), "Ctrl+G", G::Insert, true, true, [this] { insertJump(); }, always, QT_TR_NOOP("Jump")},
        {"cfcLabel", QT_TR_NOOP("&Label"), "Ctrl+L", G::Insert, true, true, [this] { insertLabel(); }, always, QT_TR_NOOP("Label")},
        {"cfcReturn", QT_TR_NOOP("&Return"), "Ctrl+R", G::Insert, true, true, [this] { insertReturn(); }, always, QT_TR_NOOP("Return")},
        {"cfcComment", QT_TR_NOOP("Co&mment…"), "Ctrl+K", G::Insert, true, true, [this] { askComment(); }, always, QT_TR_NOOP("Comment")},
        {"cfcConnector", QT_TR_NOOP("Connection Mark (&Source)"), "", G::Insert, true, false, [this] { insertConnector(); }, always},
        {"cfcContinuation", QT_TR_NOOP("Connection Mark (&Sink)"), "", G::Insert, true, false, [this] { insertContinuation(); }, always},
        {"cfcNegate", QT_TR_NOOP("Ne&gate"), "Ctrl+Shift+N", G::Element, true, false, [this] { toggleNegation(); }, selected},
        {"cfcEnEno", QT_TR_NOOP("EN/ENO"), "", G::Element, true, false, [this] { toggleEnEno(); }, oneBox},
        {"cfcRename", QT_TR_NOOP("Edit &Name"), "F2", G::Element, true, false, [this] { startTyping(); }, one},
        {"cfcOrderDataFlow", QT_TR_NOOP("Order by &Data Flow"), "", G::Element, true, true, [this] { orderByDataFlow(); }, many,
            QT_TR_NOOP("Data Flow")},
        {"cfcOrderTopology", QT_TR_NOOP("Order by &Topology"), "", G::Element, true, false, [this] { orderByTopology(); }, many},
        {"cfcOrderEarlier", QT_TR_NOOP("Order: One &Earlier"), "Ctrl+Shift+Up", G::Element, true, false,
            [this] { moveInOrder(OrderMove::Earlier); }, runs},
        {"cfcOrderLater", QT_TR_NOOP("Order: One &Later"), "Ctrl+Shift+Down", G::Element, true, false,
            [this] { moveInOrder(OrderMove::Later); }, runs},
        {"cfcOrderFront", QT_TR_NOOP("Order: To the &Front"), "Ctrl+Shift+Home", G::Element, true, false,
            [this] { moveInOrder(OrderMove::ToFront); }, runs},
        {"cfcOrderBack", QT_TR_NOOP("Order: To the &Back"), "Ctrl+Shift+End", G::Element, true, false,
            [this] { moveInOrder(OrderMove::ToBack); }, runs},
        {"cfcOrderSet", QT_TR_NOOP("Set Order &Number…"), "", G::Element, true, false, [this] { askOrderNumber(); }, runs},
        {"cfcCut", QT_TR_NOOP("Cu&t"), "Ctrl+X", G::Edit, true, false, [this] { cut(); }, selected},
        {"cfcCopy", QT_TR_NOOP("&Copy"), "Ctrl+C", G::Edit, false, false, [this] { copy(); }, selected},
        {"cfcPaste", QT_TR_NOOP("&Paste"), "Ctrl+V", G::Edit, true, false, [this] { paste(); }, [] { return clipboardHasElements(); }},
        {"cfcDelete", QT_TR_NOOP("&Delete"), "Del", G::Edit, true, true, [this] { deleteSelection(); }, selected},
    };
    addActionTable(specs);
}

} // namespace iec::editors::cfc
