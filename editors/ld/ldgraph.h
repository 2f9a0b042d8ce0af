#pragma once

#include "editors/common/elementpool.h"
#include "model/body.h"
#include "model/element.h"

#include <unordered_map>
#include <vector>

namespace iec::editors::ld {

// The wires of a graphical body as adjacency lists over element indices, both ways: what each
// element's input pins are wired to, and who reads each element. Pins are numbered per element:
// a box's inputs in the order of its input variables (in-outs after them), its outputs in the
// order of its output variables; other elements have pin 0.
class LdGraph
{
public:
    struct Wire {
        int pin = 0;          // the input pin of the element
        std::size_t source = 0;
        int sourcePin = 0;    // the output pin of the source, -1 when the wire names none it has
    };
    struct Reader {
        std::size_t target = 0;
        int pin = 0;          // the input pin of the reader
        int sourcePin = 0;    // the output pin it reads
    };

    explicit LdGraph(const std::vector<model::Element> &elements);

    [[nodiscard]] std::size_t size() const { return m_elements.size(); }
    [[nodiscard]] const model::Element &element(std::size_t i) const { return m_elements[i]; }
    [[nodiscard]] quint64 localId(std::size_t i) const { return model::header(m_elements[i]).localId; }
    [[nodiscard]] const std::vector<Wire> &inputs(std::size_t i) const { return m_inputs[i]; }
    [[nodiscard]] const std::vector<Reader> &readers(std::size_t i) const { return m_readers[i]; }
    [[nodiscard]] bool isRail(std::size_t i) const;
    [[nodiscard]] const model::Position &position(std::size_t i) const { return model::header(m_elements[i]).position; }
    // The extent of elements from their positions and sizes.
    [[nodiscard]] double top(const std::vector<std::size_t> &indices) const;
    [[nodiscard]] double bottom(const std::vector<std::size_t> &indices) const;

private:
    const std::vector<model::Element> &m_elements;
    std::vector<std::vector<Wire>> m_inputs;
    std::vector<std::vector<Reader>> m_readers;
};

// outputPinIndex is shared (editors/common/elementpool.h).
using editors::outputPinIndex;

} // namespace iec::editors::ld
