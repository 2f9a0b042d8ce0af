#include "interpreter/runtime/scanhistory.h"

#include <algorithm>
#include <cstring>

namespace iec::interp {

namespace {

std::vector<std::uint8_t> flatten(const RuntimeState &state)
{
    std::vector<std::uint8_t> flat(state.memory);
    for (const std::vector<std::uint8_t> &image : state.images)
        flat.insert(flat.end(), image.begin(), image.end());
    return flat;
}

void putWord(std::vector<std::uint8_t> &out, std::uint32_t word)
{
    const std::size_t at = out.size();
    out.resize(at + sizeof word);
    std::memcpy(out.data() + at, &word, sizeof word);
}

std::uint32_t getWord(const std::uint8_t *p)
{
    std::uint32_t word = 0;
    std::memcpy(&word, p, sizeof word);
    return word;
}

// Appends the runs of bytes where `after` differs from `before` (`size` bytes each; offsets
// counted from `base`). Equal stretches are skipped a word at a time; two runs closer than a run
// header are merged, which is smaller.
void appendChangedRuns(std::vector<std::uint8_t> &runs, const std::uint8_t *before, const std::uint8_t *after,
                       std::size_t size, std::size_t base)
{
    constexpr std::size_t kHeader = 2 * sizeof(std::uint32_t);
    std::size_t i = 0;
    while (i < size) {
        while (i + sizeof(std::uint64_t) <= size) {
            std::uint64_t a = 0;
            std::uint64_t b = 0;
            std::memcpy(&a, before + i, sizeof a);
            std::memcpy(&b, after + i, sizeof b);
            if (a != b)
                break;
            i += sizeof a;
        }
        while (i < size && before[i] == after[i])
            ++i;
        if (i >= size)
            break;
        const std::size_t start = i;
        std::size_t end = i + 1; // one past the last changed byte
        for (std::size_t j = end; j < size && j < end + kHeader; ++j) {
            if (before[j] != after[j])
                end = j + 1;
        }
        while (end < size && before[end] != after[end])
            ++end;
        putWord(runs, std::uint32_t(base + start));
        putWord(runs, std::uint32_t(end - start));
        runs.insert(runs.end(), after + start, after + end);
        i = end;
    }
}

void applyRuns(std::vector<std::uint8_t> &flat, const std::vector<std::uint8_t> &runs)
{
    const std::uint8_t *p = runs.data();
    const std::uint8_t *end = p + runs.size();
    while (p < end) {
        const std::uint32_t offset = getWord(p);
        const std::uint32_t length = getWord(p + 4);
        p += 8;
        std::memcpy(flat.data() + offset, p, length);
        p += length;
    }
}

} // namespace

std::size_t ScanHistory::Entry::bytes() const
{
    return sizeof(Entry) + data.capacity() + nextDue.capacity() * sizeof(std::int64_t) + singleBefore.size() / 8;
}

ScanHistory::ScanHistory(int scans, std::size_t maxBytes)
    : m_scanLimit(std::max(1, scans))
    , m_byteLimit(maxBytes)
{ }

void ScanHistory::setLimits(int scans, std::size_t maxBytes)
{
    m_scanLimit = std::max(1, scans);
    m_byteLimit = maxBytes;
    while (m_entries.size() > 1 && (int(m_entries.size()) > m_scanLimit || m_bytes > m_byteLimit))
        dropOldest();
}

void ScanHistory::record(const RuntimeState &state)
{
    if (!m_entries.empty() && state.cycle <= lastCycle())
        truncateAfter(state.cycle - 1);
    const std::size_t sizes[4] = {state.memory.size(), state.images[0].size(), state.images[1].size(),
                                  state.images[2].size()};
    const bool sameShape = !m_entries.empty() && std::equal(std::begin(sizes), std::end(sizes), std::begin(m_sizes));
    Entry entry;
    entry.cycle = state.cycle;
    entry.timeNs = state.timeNs;
    entry.nextDue = state.nextDue;
    entry.singleBefore = state.singleBefore;
    if (!sameShape || m_entries.back().cycle % kKeyInterval == kKeyInterval - 1) {
        if (!sameShape)
            clear(); // another program: its scans cannot be replayed on this one's
        std::copy(std::begin(sizes), std::end(sizes), std::begin(m_sizes));
        m_lastFlat = flatten(state);
        entry.key = true;
        entry.data = m_lastFlat;
    } else {
        const std::vector<std::uint8_t> *segments[4] = {&state.memory, &state.images[0], &state.images[1],
                                                        &state.images[2]};
        std::size_t base = 0;
        for (const std::vector<std::uint8_t> *segment : segments) {
            appendChangedRuns(entry.data, m_lastFlat.data() + base, segment->data(), segment->size(), base);
            base += segment->size();
        }
        applyRuns(m_lastFlat, entry.data);
        entry.data.shrink_to_fit();
    }
    m_bytes += entry.bytes();
    m_entries.push_back(std::move(entry));
    while (m_entries.size() > 1 && (int(m_entries.size()) > m_scanLimit || m_bytes > m_byteLimit))
        dropOldest();
}

std::optional<std::size_t> ScanHistory::index(int cycle) const
{
    const auto at = std::lower_bound(m_entries.begin(), m_entries.end(), cycle,
                                     [](const Entry &entry, int c) { return entry.cycle < c; });
    if (at == m_entries.end() || at->cycle != cycle)
        return std::nullopt;
    return std::size_t(at - m_entries.begin());
}

std::vector<std::uint8_t> ScanHistory::flatAt(std::size_t at) const
{
    std::size_t key = at;
    while (!m_entries[key].key)
        --key;
    std::vector<std::uint8_t> flat = m_entries[key].data;
    for (std::size_t i = key + 1; i <= at; ++i)
        applyRuns(flat, m_entries[i].data);
    return flat;
}

RuntimeState ScanHistory::unflatten(const std::vector<std::uint8_t> &flat, const Entry &entry) const
{
    RuntimeState state;
    auto from = flat.begin();
    state.memory.assign(from, from + std::ptrdiff_t(m_sizes[0]));
    from += std::ptrdiff_t(m_sizes[0]);
    for (int area = 0; area < 3; ++area) {
        state.images[area].assign(from, from + std::ptrdiff_t(m_sizes[area + 1]));
        from += std::ptrdiff_t(m_sizes[area + 1]);
    }
    state.cycle = entry.cycle;
    state.timeNs = entry.timeNs;
    state.nextDue = entry.nextDue;
    state.singleBefore = entry.singleBefore;
    return state;
}

std::optional<RuntimeState> ScanHistory::stateAt(int cycle) const
{
    const std::optional<std::size_t> at = index(cycle);
    if (!at)
        return std::nullopt;
    return unflatten(flatAt(*at), m_entries[*at]);
}

void ScanHistory::truncateAfter(int cycle)
{
    while (!m_entries.empty() && m_entries.back().cycle > cycle)
        m_entries.pop_back();
    if (!m_entries.empty())
        m_lastFlat = flatAt(m_entries.size() - 1);
    recount();
}

void ScanHistory::clear()
{
    m_entries.clear();
    m_lastFlat.clear();
    m_bytes = 0;
}

// The oldest scan goes; when the next is stored as changes, it becomes the full copy first.
void ScanHistory::dropOldest()
{
    if (m_entries.size() > 1 && !m_entries[1].key) {
        std::vector<std::uint8_t> flat = flatAt(1);
        m_bytes -= m_entries[1].bytes();
        m_entries[1].data = std::move(flat);
        m_entries[1].key = true;
        m_bytes += m_entries[1].bytes();
    }
    m_bytes -= m_entries.front().bytes();
    m_entries.pop_front();
}

void ScanHistory::recount()
{
    m_bytes = 0;
    for (const Entry &entry : m_entries)
        m_bytes += entry.bytes();
}

} // namespace iec::interp
