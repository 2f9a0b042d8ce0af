#pragma once

#include "interpreter/runtime/tracedata.h"

#include <QWidget>

#include <array>
#include <deque>
#include <memory>
#include <optional>
#include <vector>

class QScrollArea;
class QScrollBar;
class QVBoxLayout;

namespace iec::interp {
struct Module;
}

namespace iec::app {

class TraceLane;

// What the Trace pane recorded: the variables and their samples (the pane's own copy of the
// runtime's ring buffer), kept when going offline so it can still be read and exported.
struct TraceData {
    std::shared_ptr<const interp::Module> module; // keeps the variables' types alive
    std::vector<interp::TraceVariable> variables;
    std::deque<interp::TraceRow> rows;
    std::optional<int> triggerCycle;
    std::int64_t cycleNs = 10'000'000;

    [[nodiscard]] double timeMs(std::size_t row) const { return double(rows[row].timeNs) / 1e6; }
    // The last sample at or before `ms` (sample and hold); nullopt before the first.
    [[nodiscard]] std::optional<std::size_t> rowAt(double ms) const;
    [[nodiscard]] std::optional<std::size_t> nearestRow(double ms) const;
};

// The trend: one lane per shown variable, stacked and sharing the time axis (Qt Charts).
// BOOL lanes read like a logic analyser, numbers as sample-and-hold curves on their own scale.
// Two cursors (left click: cursor 1, Shift+click: cursor 2), a marker for the scan shown in
// history and one for the trigger. The wheel zooms the time axis around the pointer, the scroll
// bar pans it; while following (after Fit), the newest samples stay in view.
class TraceChart : public QWidget
{
    Q_OBJECT

public:
    explicit TraceChart(QWidget *parent = nullptr);
    ~TraceChart() override;

    // The data to draw (owned by the pane) and which variables show, in lane order.
    void setData(const TraceData *data);
    void setLanes(const std::vector<int> &variables);
    // Redraws after the data changed (new samples).
    void refresh();

    void setCursor(int which, std::optional<double> ms);
    [[nodiscard]] std::optional<double> cursor(int which) const { return m_cursors[size_t(which)]; }
    void setHistoryMarker(std::optional<double> ms);

    void zoom(double factor, std::optional<double> aroundMs = std::nullopt);
    void fit();
    [[nodiscard]] std::pair<double, double> visibleRange() const { return {m_from, m_to}; }
    [[nodiscard]] bool isFollowing() const { return m_follow; }
    [[nodiscard]] int laneCount() const { return int(m_lanes.size()); }

    // The lanes as a picture, for PNG and PDF export.
    [[nodiscard]] QImage image() const;

Q_SIGNALS:
    void cursorMoved(int which);
    // A sample was clicked: the cycle it was taken after.
    void sampleClicked(int cycle);

private:
    friend class TraceLane;
    void laneClicked(double ms, bool second);
    void laneWheel(double ms, int delta);
    void setRange(double from, double to, bool follow);
    void updateScrollBar();
    void scrolled(int value);
    void redrawLanes();
    [[nodiscard]] std::pair<double, double> dataRange() const;

    const TraceData *m_data = nullptr;
    std::vector<int> m_laneVariables;
    std::vector<TraceLane *> m_lanes;
    QScrollArea *m_laneScroll = nullptr;
    QWidget *m_laneBox = nullptr;
    QVBoxLayout *m_laneLayout = nullptr;
    QScrollBar *m_scroll = nullptr;
    std::array<std::optional<double>, 2> m_cursors;
    std::optional<double> m_historyMarker;
    double m_from = 0;
    double m_to = 100;
    bool m_follow = true;
    bool m_fitAll = true; // following shows every sample, not the last span
    bool m_updatingScroll = false;
};

} // namespace iec::app
