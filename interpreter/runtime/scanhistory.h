#pragma once

#include "interpreter/runtime/runtime.h"

#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

namespace iec::interp {

// The last scans of a run, to go back to: the state after each cycle (RuntimeState), bounded
// by a number of scans and a number of bytes, whichever is reached first (the oldest go).
//
// A scan is kept as the byte runs that changed since the scan before it, with a full copy every
// kKeyInterval scans, so a program whose memory mostly stays the same costs a few bytes per scan
// and going back replays at most kKeyInterval - 1 runs lists.
class ScanHistory
{
public:
    static constexpr int kDefaultScans = 1000;
    static constexpr std::size_t kDefaultBytes = std::size_t(256) << 20;
    static constexpr int kKeyInterval = 64;

    explicit ScanHistory(int scans = kDefaultScans, std::size_t maxBytes = kDefaultBytes);

    void setLimits(int scans, std::size_t maxBytes);
    [[nodiscard]] int scanLimit() const { return m_scanLimit; }

    // Keeps the state after a scan. A cycle at or before the last one kept starts a new branch:
    // the scans from that cycle on are dropped first.
    void record(const RuntimeState &state);
    [[nodiscard]] std::optional<RuntimeState> stateAt(int cycle) const;
    // Drops the scans after `cycle` (resuming from an earlier scan makes a new branch).
    void truncateAfter(int cycle);
    void clear();

    [[nodiscard]] bool isEmpty() const { return m_entries.empty(); }
    [[nodiscard]] int size() const { return int(m_entries.size()); }
    [[nodiscard]] int firstCycle() const { return m_entries.empty() ? 0 : m_entries.front().cycle; }
    [[nodiscard]] int lastCycle() const { return m_entries.empty() ? 0 : m_entries.back().cycle; }
    [[nodiscard]] bool contains(int cycle) const { return index(cycle).has_value(); }
    [[nodiscard]] std::size_t bytesUsed() const { return m_bytes + m_lastFlat.capacity(); }

private:
    struct Entry {
        int cycle = 0;
        bool key = false;
        std::vector<std::uint8_t> data; // key: the flat image; else runs of (offset, length, bytes)
        std::int64_t timeNs = 0;
        std::vector<std::int64_t> nextDue;
        std::vector<bool> singleBefore;
        std::size_t bytes() const;
    };

    [[nodiscard]] std::optional<std::size_t> index(int cycle) const;
    [[nodiscard]] std::vector<std::uint8_t> flatAt(std::size_t index) const;
    [[nodiscard]] RuntimeState unflatten(const std::vector<std::uint8_t> &flat, const Entry &entry) const;
    void dropOldest();
    void recount();

    int m_scanLimit;
    std::size_t m_byteLimit;
    std::deque<Entry> m_entries;
    std::vector<std::uint8_t> m_lastFlat; // the flat image of the last entry, to diff against
    std::size_t m_sizes[4] = {};          // memory, I, Q, M image sizes (the same for every scan)
    std::size_t m_bytes = 0;
};

} // namespace iec::interp
