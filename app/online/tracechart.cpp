#include "app/online/tracechart.h"

#include "interpreter/compiler/types.h"

#include <QChart>
#include <QChartView>
#include <QGraphicsLayout>
#include <QLineSeries>
#include <QMouseEvent>
#include <QScrollArea>
#include <QScrollBar>
#include <QVBoxLayout>
#include <QValueAxis>

#include <algorithm>
#include <cmath>

namespace iec::app {

namespace {

constexpr int kBoolLaneHeight = 58;
constexpr int kNumberLaneHeight = 140;
constexpr int kAxisLabelsHeight = 22; // below the last lane
constexpr int kPlotLeft = 78;         // room for the value axis' labels, the same in every lane
constexpr int kPlotRight = 34;         // room for the last time label
constexpr int kScrollSteps = 10'000;

const QColor kCursorColors[2] = {QColor(0x1f, 0x5f, 0xd0), QColor(0xc0, 0x30, 0x30)};
const QColor kHistoryColor(0xe0, 0x90, 0x00);
const QColor kTriggerColor(0x20, 0x90, 0x40);

} // namespace

std::optional<std::size_t> TraceData::rowAt(double ms) const
{
    const auto after = std::upper_bound(rows.begin(), rows.end(), ms,
                                        [](double t, const interp::TraceRow &row) { return t < double(row.timeNs) / 1e6; });
    if (after == rows.begin())
        return std::nullopt;
    return std::size_t(after - rows.begin()) - 1;
}

std::optional<std::size_t> TraceData::nearestRow(double ms) const
{
    if (rows.empty())
        return std::nullopt;
    const std::optional<std::size_t> before = rowAt(ms);
    if (!before)
        return 0;
    const std::size_t next = *before + 1;
    if (next < rows.size() && timeMs(next) - ms < ms - timeMs(*before))
        return next;
    return before;
}

// One variable's lane: a chart with its own value axis, drawn from the visible samples only.
class TraceLane : public QChartView
{
public:
    TraceLane(TraceChart &owner, int variable, bool showTimeLabels)
        : QChartView(new QChart())
        , m_owner(owner)
        , m_variable(variable)
        , m_series(new QLineSeries())
        , m_time(new QValueAxis())
        , m_value(new QValueAxis())
    {
        setRenderHint(QPainter::Antialiasing, false);
        setFrameShape(QFrame::NoFrame);
        QChart *c = chart();
        c->legend()->hide();
        c->setBackgroundRoundness(0);
        c->setMargins(QMargins(0, 0, 0, 0));
        c->layout()->setContentsMargins(0, 0, 0, 0);
        c->addSeries(m_series);
        c->addAxis(m_time, Qt::AlignBottom);
        c->addAxis(m_value, Qt::AlignLeft);
        m_series->attachAxis(m_time);
        m_series->attachAxis(m_value);
        QFont small = font();
        small.setPointSizeF(small.pointSizeF() * 0.85);
        m_time->setLabelsFont(small);
        m_value->setLabelsFont(small);
        m_time->setLabelsVisible(showTimeLabels);
        m_showTimeLabels = showTimeLabels;
        const interp::VariableRef &ref = owner.m_data->variables[size_t(variable)].ref;
        m_boolean = interp::isBoolean(ref);
        QPen pen(m_boolean ? QColor(0x10, 0x70, 0x30) : QColor(0x20, 0x40, 0x90));
        pen.setWidthF(1.5);
        m_series->setPen(pen);
        if (m_boolean) {
            m_value->setRange(-0.25, 1.25);
            m_value->setTickCount(2);
            m_value->setLabelsVisible(false);
            m_value->setGridLineVisible(false);
        }
        setFixedHeight((m_boolean ? kBoolLaneHeight : kNumberLaneHeight) + (showTimeLabels ? kAxisLabelsHeight : 0));
    }

    int variable() const { return m_variable; }

    void redraw(double from, double to)
    {
        m_time->setRange(from, to);
        placeTimeTicks(from, to);
        const TraceData &data = *m_owner.m_data;
        QList<QPointF> points;
        double low = 0;
        double high = 0;
        collect(data, from, to, points, low, high);
        m_series->replace(points);
        if (!m_boolean) {
            if (points.isEmpty())
                low = 0, high = 1;
            const double pad = high > low ? (high - low) * 0.08 : std::max(1.0, std::abs(high) * 0.1);
            // A value that never goes below zero keeps zero as the axis' floor.
            m_value->setRange(low >= 0 && low - pad < 0 ? 0.0 : low - pad, high + pad);
            m_value->applyNiceNumbers();
        }
        placePlotArea();
        viewport()->update();
    }

protected:
    void resizeEvent(QResizeEvent *event) override
    {
        QChartView::resizeEvent(event);
        placePlotArea();
        placeTimeTicks(m_time->min(), m_time->max());
    }

    void drawForeground(QPainter *painter, const QRectF &rect) override
    {
        QChartView::drawForeground(painter, rect);
        const QRectF plot = chart()->plotArea();
        painter->save();
        const auto line = [&](std::optional<double> ms, const QColor &color, Qt::PenStyle style) {
            if (!ms)
                return;
            const double x = chart()->mapToPosition(QPointF(*ms, 0), m_series).x();
            if (x < plot.left() - 0.5 || x > plot.right() + 0.5)
                return;
            QPen pen(color);
            pen.setWidthF(1.5);
            pen.setStyle(style);
            painter->setPen(pen);
            painter->drawLine(QPointF(x, plot.top()), QPointF(x, plot.bottom()));
        };
        const TraceData &data = *m_owner.m_data;
        if (data.triggerCycle) {
            const auto at = std::lower_bound(data.rows.begin(), data.rows.end(), *data.triggerCycle,
                                             [](const interp::TraceRow &row, int cycle) { return row.cycle < cycle; });
            if (at != data.rows.end() && at->cycle == *data.triggerCycle)
                line(double(at->timeNs) / 1e6, kTriggerColor, Qt::DotLine);
        }
        line(m_owner.m_historyMarker, kHistoryColor, Qt::DashLine);
        line(m_owner.m_cursors[0], kCursorColors[0], Qt::SolidLine);
        line(m_owner.m_cursors[1], kCursorColors[1], Qt::SolidLine);
        // The lane's name at the top left of its plot, readable over the curve.
        const QString name = data.variables[size_t(m_variable)].name;
        QFont bold = font();
        bold.setBold(true);
        painter->setFont(bold);
        const QFontMetrics metrics(bold);
        const QRectF label(plot.left() + 4, plot.top() + 2, metrics.horizontalAdvance(name) + 8, metrics.height() + 2);
        painter->setPen(Qt::NoPen);
        painter->setBrush(QColor(255, 255, 255, 200));
        painter->drawRect(label);
        painter->setPen(QColor(0x20, 0x20, 0x20));
        painter->drawText(label, Qt::AlignCenter, name);
        painter->restore();
    }

    void mousePressEvent(QMouseEvent *event) override { pick(event); }
    void mouseMoveEvent(QMouseEvent *event) override
    {
        if (event->buttons() & Qt::LeftButton)
            pick(event);
    }
    void mouseReleaseEvent(QMouseEvent *) override { }

    void wheelEvent(QWheelEvent *event) override
    {
        const QPointF value = chart()->mapToValue(event->position(), m_series);
        m_owner.laneWheel(value.x(), event->angleDelta().y());
        event->accept();
    }

private:
    void pick(QMouseEvent *event)
    {
        if (!(event->buttons() & Qt::LeftButton))
            return;
        const QPointF value = chart()->mapToValue(event->position(), m_series);
        m_owner.laneClicked(value.x(), event->modifiers() & Qt::ShiftModifier);
        event->accept();
    }

    // Ticks on round times (1, 2 or 5 times a power of ten) about every 110 pixels, so the labels
    // read 0 ms, 500 ms, 1000 ms ... and never crowd.
    void placeTimeTicks(double from, double to)
    {
        const double columns = std::max(2.0, double(width() - kPlotLeft - kPlotRight) / 110.0);
        const double raw = std::max((to - from) / columns, 1e-6);
        const double power = std::pow(10.0, std::floor(std::log10(raw)));
        double step = power;
        for (const double factor : {1.0, 2.0, 5.0, 10.0}) {
            step = factor * power;
            if (step >= raw)
                break;
        }
        m_time->setTickType(QValueAxis::TicksDynamic);
        m_time->setTickAnchor(0);
        m_time->setTickInterval(step);
        m_time->setLabelFormat(step >= 1 ? QStringLiteral("%.0f ms") : QStringLiteral("%.3g ms"));
    }

    // The same plot area in every lane, so that the time axes line up across the lanes.
    void placePlotArea()
    {
        const int bottom = m_showTimeLabels ? kAxisLabelsHeight : 2;
        const QRectF area(kPlotLeft, 4, std::max(10, width() - kPlotLeft - kPlotRight), std::max(10, height() - 4 - bottom));
        if (chart()->plotArea() == area)
            return;
        chart()->setPlotArea(area);
        chart()->layout()->activate(); // the axes follow at once, not at the next layout pass
    }

    // Sample and hold: a point where each shown value starts; more samples than pixels are
    // drawn as one vertical stroke per pixel column from the column's lowest to highest value.
    void collect(const TraceData &data, double from, double to, QList<QPointF> &points, double &low, double &high) const
    {
        if (data.rows.empty())
            return;
        const interp::VariableRef &ref = data.variables[size_t(m_variable)].ref;
        std::size_t first = data.rowAt(from).value_or(0);
        std::size_t last = data.rowAt(to).value_or(0);
        if (last + 1 < data.rows.size())
            ++last;
        const std::size_t count = last - first + 1;
        const std::size_t columns = std::size_t(std::max(50, width() - kPlotLeft - kPlotRight));
        const std::size_t perColumn = std::max<std::size_t>(1, count / columns);
        low = high = interp::rowNumber(data.rows[first], size_t(m_variable), ref);
        double previous = std::nan("");
        for (std::size_t i = first; i <= last; i += perColumn) {
            const std::size_t end = std::min(last + 1, i + perColumn);
            const double t = data.timeMs(i);
            double columnLow = interp::rowNumber(data.rows[i], size_t(m_variable), ref);
            double columnHigh = columnLow;
            const double start = columnLow;
            double finish = columnLow;
            for (std::size_t j = i + 1; j < end; ++j) {
                finish = interp::rowNumber(data.rows[j], size_t(m_variable), ref);
                columnLow = std::min(columnLow, finish);
                columnHigh = std::max(columnHigh, finish);
            }
            low = std::min(low, columnLow);
            high = std::max(high, columnHigh);
            if (!std::isnan(previous) && start != previous)
                points.append(QPointF(t, previous));
            if (std::isnan(previous) || start != previous)
                points.append(QPointF(t, start));
            if (columnLow != columnHigh) {
                points.append(QPointF(t, columnLow));
                points.append(QPointF(t, columnHigh));
                points.append(QPointF(t, finish));
            }
            previous = finish;
        }
        points.append(QPointF(std::max(data.timeMs(last), to), previous));
    }

    TraceChart &m_owner;
    int m_variable;
    QLineSeries *m_series;
    QValueAxis *m_time;
    QValueAxis *m_value;
    bool m_boolean = false;
    bool m_showTimeLabels = false;
};

TraceChart::TraceChart(QWidget *parent)
    : QWidget(parent)
    , m_laneScroll(new QScrollArea(this))
    , m_laneBox(new QWidget(m_laneScroll))
    , m_laneLayout(new QVBoxLayout(m_laneBox))
    , m_scroll(new QScrollBar(Qt::Horizontal, this))
{
    m_laneLayout->setContentsMargins(0, 0, 0, 0);
    m_laneLayout->setSpacing(1);
    m_laneLayout->addStretch(1);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    // Lanes keep their height; more than fit scroll.
    m_laneScroll->setWidget(m_laneBox);
    m_laneScroll->setWidgetResizable(true);
    m_laneScroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_laneScroll->setFrameShape(QFrame::NoFrame);
    layout->addWidget(m_laneScroll, 1);
    layout->addWidget(m_scroll);
    m_scroll->setRange(0, 0);
    connect(m_scroll, &QScrollBar::valueChanged, this, &TraceChart::scrolled);
}

TraceChart::~TraceChart() = default;

void TraceChart::setData(const TraceData *data)
{
    m_data = data;
    setLanes({});
}

void TraceChart::setLanes(const std::vector<int> &variables)
{
    if (variables == m_laneVariables && int(m_lanes.size()) == int(variables.size()))
        return;
    m_laneVariables = variables;
    for (TraceLane *lane : m_lanes)
        delete lane;
    m_lanes.clear();
    if (!m_data)
        return;
    for (std::size_t i = 0; i < variables.size(); ++i) {
        if (variables[i] < 0 || size_t(variables[i]) >= m_data->variables.size())
            continue;
        auto *lane = new TraceLane(*this, variables[i], i + 1 == variables.size());
        m_laneLayout->insertWidget(m_laneLayout->count() - 1, lane);
        m_lanes.push_back(lane);
    }
    refresh();
}

std::pair<double, double> TraceChart::dataRange() const
{
    if (!m_data || m_data->rows.empty())
        return {0.0, 100.0};
    const double first = m_data->timeMs(0);
    double last = m_data->timeMs(m_data->rows.size() - 1);
    if (last <= first)
        last = first + double(m_data->cycleNs) / 1e6;
    return {first, last};
}

void TraceChart::refresh()
{
    if (m_follow) {
        const auto [first, last] = dataRange();
        const double span = m_to - m_from;
        // Following keeps the newest samples in view; all of them after Fit.
        if (m_fitAll || last - first <= span)
            setRange(first, last, true);
        else
            setRange(last - span, last, true);
        return;
    }
    redrawLanes();
    updateScrollBar();
}

void TraceChart::redrawLanes()
{
    for (TraceLane *lane : m_lanes)
        lane->redraw(m_from, m_to);
}

void TraceChart::setRange(double from, double to, bool follow)
{
    m_from = from;
    m_to = std::max(to, from + 1e-3);
    m_follow = follow;
    redrawLanes();
    updateScrollBar();
}

void TraceChart::updateScrollBar()
{
    const auto [first, last] = dataRange();
    const double total = std::max(last - first, m_to - m_from);
    m_updatingScroll = true;
    const int page = int(std::clamp((m_to - m_from) / total, 0.0, 1.0) * kScrollSteps);
    m_scroll->setPageStep(std::max(1, page));
    m_scroll->setSingleStep(std::max(1, page / 10));
    m_scroll->setRange(0, kScrollSteps - page);
    m_scroll->setValue(int((m_from - first) / total * kScrollSteps));
    m_updatingScroll = false;
}

void TraceChart::scrolled(int value)
{
    if (m_updatingScroll)
        return;
    const auto [first, last] = dataRange();
    const double span = m_to - m_from;
    const double total = std::max(last - first, span);
    const double from = first + double(value) / kScrollSteps * total;
    m_fitAll = false;
    setRange(from, from + span, from + span >= last);
}

void TraceChart::zoom(double factor, std::optional<double> aroundMs)
{
    const double span = m_to - m_from;
    const double center = aroundMs.value_or((m_from + m_to) / 2);
    const double share = span > 0 ? (center - m_from) / span : 0.5;
    const auto [first, last] = dataRange();
    const double newSpan = std::clamp(span / factor, double(m_data ? m_data->cycleNs : 10'000'000) / 1e6 * 2,
                                      std::max(last - first, 1.0) * 4);
    double from = center - share * newSpan;
    from = std::max(from, first - newSpan * 0.5);
    m_fitAll = false;
    setRange(from, from + newSpan, false);
}

void TraceChart::fit()
{
    m_fitAll = true;
    const auto [first, last] = dataRange();
    setRange(first, last, true);
}

void TraceChart::laneClicked(double ms, bool second)
{
    if (!m_data || m_data->rows.empty())
        return;
    const std::optional<std::size_t> row = m_data->nearestRow(ms);
    const double snapped = m_data->timeMs(*row);
    setCursor(second ? 1 : 0, snapped);
    if (!second)
        Q_EMIT sampleClicked(m_data->rows[*row].cycle);
}

void TraceChart::laneWheel(double ms, int delta)
{
    if (delta != 0)
        zoom(delta > 0 ? 1.25 : 0.8, ms);
}

void TraceChart::setCursor(int which, std::optional<double> ms)
{
    m_cursors[size_t(which)] = ms;
    for (TraceLane *lane : m_lanes)
        lane->viewport()->update();
    Q_EMIT cursorMoved(which);
}

void TraceChart::setHistoryMarker(std::optional<double> ms)
{
    if (m_historyMarker == ms)
        return;
    m_historyMarker = ms;
    for (TraceLane *lane : m_lanes)
        lane->viewport()->update();
}

QImage TraceChart::image() const
{
    return m_laneBox->grab().toImage();
}

} // namespace iec::app
