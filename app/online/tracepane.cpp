#include "app/online/tracepane.h"

#include "app/online/onlinecontroller.h"
#include "app/online/traceexport.h"
#include "app/online/tracesettingsdialog.h"
#include "interpreter/runtime/valueformat.h"
#include "model/projectmodel.h"

#include <QAction>
#include <QFileDialog>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QListWidget>
#include <QMenu>
#include <QMessageBox>
#include <QSplitter>
#include <QTableWidget>
#include <QToolBar>
#include <QToolButton>
#include <QVBoxLayout>

namespace iec::app {

namespace {

constexpr int kReadoutFixedRows = 2; // time, cycle

QString formatNumber(double value)
{
    return QString::number(value, 'g', 10);
}

} // namespace

interp::TraceSettings traceSettings(const model::SavedTrace &saved)
{
    interp::TraceSettings settings;
    settings.variables = saved.variables;
    settings.everyCycles = saved.everyCycles;
    settings.capacity = saved.capacity;
    settings.trigger = interp::TraceSettings::Trigger(std::clamp(saved.trigger, 0, 3));
    settings.triggerVariable = saved.triggerVariable;
    settings.triggerLevel = saved.triggerLevel;
    settings.samplesAfterTrigger = saved.samplesAfterTrigger;
    settings.recordCondition = saved.recordCondition;
    return settings;
}

TracePane::TracePane(model::ProjectModel &projectModel, OnlineController &online, QWidget *parent)
    : QWidget(parent)
    , m_projectModel(projectModel)
    , m_online(online)
    , m_toolBar(new QToolBar(this))
    , m_status(new QLabel(this))
    , m_lanes(new QListWidget(this))
    , m_chart(new TraceChart(this))
    , m_readout(new QTableWidget(this))
{
    createActions();
    m_chart->setData(&m_data);
    m_lanes->setObjectName(QStringLiteral("traceLanes"));
    m_lanes->setDragDropMode(QAbstractItemView::InternalMove);
    m_lanes->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_lanes->setContextMenuPolicy(Qt::ActionsContextMenu);
    m_lanes->addAction(m_remove);
    m_readout->setObjectName(QStringLiteral("traceReadout"));
    m_readout->setColumnCount(3);
    m_readout->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_readout->verticalHeader()->setDefaultSectionSize(m_readout->fontMetrics().height() + 4);
    m_readout->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto *side = new QSplitter(Qt::Vertical, this);
    side->addWidget(m_lanes);
    side->addWidget(m_readout);
    side->setStretchFactor(0, 1);
    side->setStretchFactor(1, 1);
    auto *split = new QSplitter(Qt::Horizontal, this);
    split->addWidget(side);
    split->addWidget(m_chart);
    split->setStretchFactor(1, 3);
    split->setSizes({330, 800});
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addWidget(m_toolBar);
    layout->addWidget(m_status);
    layout->addWidget(split, 1);

    connect(m_lanes, &QListWidget::itemChanged, this, &TracePane::lanesEdited);
    connect(m_lanes->model(), &QAbstractItemModel::rowsMoved, this, &TracePane::lanesEdited);
    connect(m_chart, &TraceChart::cursorMoved, this, &TracePane::updateReadout);
    connect(m_chart, &TraceChart::sampleClicked, this, [this](int cycle) {
        if (m_online.isOnline())
            m_online.showScan(cycle);
    });
    connect(&m_projectModel, &model::ProjectModel::projectReset, this, &TracePane::loadFromProject);
    connect(&m_online, &OnlineController::onlineChanged, this, [this](bool online) {
        if (online)
            sendSettings();
        updateStatus();
    });
    connect(&m_online, &OnlineController::snapshotShown, this,
            [this](std::shared_ptr<const interp::RuntimeSnapshot> snapshot) { showSnapshot(*snapshot); });
    loadFromProject();
    retranslate();
}

TracePane::~TracePane() = default;

void TracePane::createActions()
{
    m_configure = m_toolBar->addAction(QString(), this, &TracePane::configure);
    m_add = m_toolBar->addAction(QString(), this, &TracePane::askForVariable);
    m_toolBar->addSeparator();
    m_pause = m_toolBar->addAction(QString());
    m_pause->setCheckable(true);
    connect(m_pause, &QAction::toggled, this, [this](bool paused) { m_online.setTracePaused(paused); });
    m_restart = m_toolBar->addAction(QString(), this, [this] { m_online.restartTrace(); });
    m_toolBar->addSeparator();
    m_zoomIn = m_toolBar->addAction(QString(), this, [this] { m_chart->zoom(2.0); });
    m_zoomOut = m_toolBar->addAction(QString(), this, [this] { m_chart->zoom(0.5); });
    m_fit = m_toolBar->addAction(QString(), m_chart, &TraceChart::fit);
    m_toolBar->addSeparator();
    m_exportMenu = new QMenu(this);
    m_exportCsv = m_exportMenu->addAction(QString(), this, [this] { exportInteractive(QStringLiteral("csv")); });
    m_exportVcd = m_exportMenu->addAction(QString(), this, [this] { exportInteractive(QStringLiteral("vcd")); });
    m_exportPng = m_exportMenu->addAction(QString(), this, [this] { exportInteractive(QStringLiteral("png")); });
    m_exportPdf = m_exportMenu->addAction(QString(), this, [this] { exportInteractive(QStringLiteral("pdf")); });
    m_exportAction = m_toolBar->addAction(QString());
    m_exportAction->setMenu(m_exportMenu);
    if (auto *button = qobject_cast<QToolButton *>(m_toolBar->widgetForAction(m_exportAction)))
        button->setPopupMode(QToolButton::InstantPopup);
    m_remove = new QAction(this);
    m_remove->setShortcut(QKeySequence::Delete);
    m_remove->setShortcutContext(Qt::WidgetShortcut);
    connect(m_remove, &QAction::triggered, this, &TracePane::removeSelectedLanes);
}

void TracePane::retranslate()
{
    m_toolBar->setWindowTitle(tr("Trace"));
    m_configure->setText(tr("Configure..."));
    m_configure->setToolTip(tr("Choose the variables, the trigger and how often to sample"));
    m_add->setText(tr("Add Variable..."));
    m_pause->setText(tr("Pause"));
    m_restart->setText(tr("Restart"));
    m_restart->setToolTip(tr("Drop the samples and record again (the trigger is armed again)"));
    m_zoomIn->setText(tr("Zoom In"));
    m_zoomOut->setText(tr("Zoom Out"));
    m_fit->setText(tr("Fit"));
    m_fit->setToolTip(tr("Show every sample and follow the newest"));
    m_exportAction->setText(tr("Export"));
    m_exportCsv->setText(tr("CSV (spreadsheet)..."));
    m_exportVcd->setText(tr("VCD (GTKWave)..."));
    m_exportPng->setText(tr("PNG picture..."));
    m_exportPdf->setText(tr("PDF for a lab report..."));
    m_remove->setText(tr("Remove from Trace"));
    m_readout->setHorizontalHeaderLabels({tr("Cursor 1"), tr("Cursor 2"), tr("Difference")});
    m_lanes->setToolTip(tr("Tick to show a lane, drag to reorder. In the chart: click for cursor 1, "
                           "Shift+click for cursor 2, wheel to zoom."));
    updateReadout();
    updateStatus();
}

void TracePane::loadFromProject()
{
    m_settings = model::savedTrace(m_projectModel.project()).value_or(model::SavedTrace());
    m_data = TraceData();
    m_chart->setData(&m_data);
    fillLaneList();
    updateLanes();
    updateReadout();
    updateStatus();
}

void TracePane::storeIn(model::Project &project) const
{
    model::setSavedTrace(project, m_settings);
}

void TracePane::setSettings(const model::SavedTrace &settings)
{
    m_settings = settings;
    fillLaneList();
    sendSettings();
    updateLanes();
    updateStatus();
}

void TracePane::addVariable(const QString &name)
{
    const QString trimmed = name.trimmed();
    if (trimmed.isEmpty() || m_settings.variables.contains(trimmed, Qt::CaseInsensitive))
        return;
    model::SavedTrace settings = m_settings;
    settings.variables << trimmed;
    setSettings(settings);
}

void TracePane::sendSettings()
{
    if (!m_online.isOnline())
        return;
    m_online.setHistoryLimit(m_settings.historyScans);
    m_online.setTrace(traceSettings(m_settings));
    if (m_pause->isChecked())
        m_online.setTracePaused(true);
}

void TracePane::showSnapshot(const interp::RuntimeSnapshot &snapshot)
{
    m_data.cycleNs = snapshot.cycleNs;
    if (snapshot.trace)
        applyUpdate(*snapshot.trace);
    m_chart->setHistoryMarker(snapshot.historyCycle ? std::optional<double>(double(snapshot.timeNs) / 1e6)
                                                    : std::nullopt);
}

void TracePane::applyUpdate(const interp::TraceUpdate &update)
{
    const bool variablesChanged = update.variables.size() != m_data.variables.size()
        || !std::equal(update.variables.begin(), update.variables.end(), m_data.variables.begin(),
                       [](const interp::TraceVariable &a, const interp::TraceVariable &b) { return a.name == b.name; });
    if (update.reset)
        m_data.rows.clear();
    m_data.module = update.module;
    m_data.variables = update.variables;
    m_data.rows.insert(m_data.rows.end(), update.rows.begin(), update.rows.end());
    m_capacity = update.capacity;
    while (int(m_data.rows.size()) > m_capacity)
        m_data.rows.pop_front();
    m_data.triggerCycle = update.triggerCycle;
    m_recorderStatus = update.status;
    m_conditionProblem = update.conditionProblem;
    if (variablesChanged)
        updateLanes();
    m_chart->refresh();
    updateReadout();
    updateStatus();
}

void TracePane::fillLaneList()
{
    m_fillingList = true;
    m_lanes->clear();
    for (const QString &name : std::as_const(m_settings.variables)) {
        auto *item = new QListWidgetItem(name, m_lanes);
        item->setFlags(item->flags() | Qt::ItemIsUserCheckable | Qt::ItemIsDragEnabled);
        item->setFlags(item->flags() & ~Qt::ItemIsDropEnabled);
        item->setCheckState(m_settings.hidden.contains(name) ? Qt::Unchecked : Qt::Checked);
    }
    m_fillingList = false;
}

// Hiding and reordering lanes changes what is shown, not what is recorded.
void TracePane::lanesEdited()
{
    if (m_fillingList)
        return;
    QStringList order;
    QStringList hidden;
    for (int row = 0; row < m_lanes->count(); ++row) {
        const QListWidgetItem *item = m_lanes->item(row);
        order << item->text();
        if (item->checkState() != Qt::Checked)
            hidden << item->text();
    }
    m_settings.variables = order;
    m_settings.hidden = hidden;
    updateLanes();
}

// The recorded variables that are shown, in lane order (indices into m_data.variables).
std::vector<int> TracePane::shownVariables() const
{
    std::vector<int> shown;
    for (const QString &name : std::as_const(m_settings.variables)) {
        if (m_settings.hidden.contains(name))
            continue;
        for (std::size_t i = 0; i < m_data.variables.size(); ++i) {
            if (m_data.variables[i].name.compare(name, Qt::CaseInsensitive) == 0)
                shown.push_back(int(i));
        }
    }
    return shown;
}

void TracePane::updateLanes()
{
    m_chart->setLanes(shownVariables());
    updateReadout();
}

void TracePane::updateReadout()
{
    const std::vector<int> shown = shownVariables();
    m_readout->setRowCount(kReadoutFixedRows + int(shown.size()));
    QStringList labels{tr("Time (ms)"), tr("Cycle")};
    for (const int variable : shown)
        labels << m_data.variables[size_t(variable)].name;
    m_readout->setVerticalHeaderLabels(labels);
    std::optional<std::size_t> rows[2];
    for (int which = 0; which < 2; ++which) {
        if (const std::optional<double> at = m_chart->cursor(which))
            rows[which] = m_data.rowAt(*at + 1e-9);
    }
    const auto set = [&](int row, int column, const QString &text) {
        m_readout->setItem(row, column, new QTableWidgetItem(text));
    };
    for (int which = 0; which < 2; ++which) {
        const std::optional<std::size_t> at = rows[which];
        const bool valid = at && *at < m_data.rows.size();
        set(0, which, valid ? formatNumber(m_data.timeMs(*at)) : QString());
        set(1, which, valid ? QString::number(m_data.rows[*at].cycle) : QString());
        for (std::size_t i = 0; i < shown.size(); ++i) {
            const interp::VariableRef &ref = m_data.variables[size_t(shown[i])].ref;
            set(kReadoutFixedRows + int(i), which,
                valid ? interp::rowLiteral(m_data.rows[*at], size_t(shown[i]), ref) : QString());
        }
    }
    const bool both = rows[0] && rows[1] && *rows[0] < m_data.rows.size() && *rows[1] < m_data.rows.size();
    set(0, 2, both ? formatNumber(m_data.timeMs(*rows[1]) - m_data.timeMs(*rows[0])) : QString());
    set(1, 2, both ? QString::number(m_data.rows[*rows[1]].cycle - m_data.rows[*rows[0]].cycle) : QString());
    for (std::size_t i = 0; i < shown.size(); ++i) {
        const interp::VariableRef &ref = m_data.variables[size_t(shown[i])].ref;
        QString difference;
        if (both && !interp::isBoolean(ref)) {
            difference = formatNumber(interp::rowNumber(m_data.rows[*rows[1]], size_t(shown[i]), ref)
                                      - interp::rowNumber(m_data.rows[*rows[0]], size_t(shown[i]), ref));
        }
        set(kReadoutFixedRows + int(i), 2, difference);
    }
}

QString TracePane::statusText() const
{
    if (m_settings.variables.isEmpty())
        return tr("Nothing to record: choose variables with Configure... or Add Variable...");
    const QString samples = tr("%n sample(s)", nullptr, int(m_data.rows.size()));
    if (!m_online.isOnline())
        return m_data.rows.empty() ? tr("Offline: the trace records while you are logged in.")
                                   : tr("Offline: %1 from the last session.").arg(samples);
    if (!m_conditionProblem.isEmpty())
        return tr("The record condition cannot be evaluated: %1").arg(m_conditionProblem);
    using Status = interp::TraceRecorder::Status;
    switch (m_recorderStatus) {
    case Status::Recording:
        return tr("Recording: %1.").arg(samples);
    case Status::WaitingForTrigger:
        return tr("Waiting for the trigger on %1: %2 kept before it.").arg(m_settings.triggerVariable, samples);
    case Status::Triggered:
        return tr("Triggered in cycle %1: recording what follows (%2).").arg(m_data.triggerCycle.value_or(0)).arg(samples);
    case Status::Done:
        return tr("Triggered in cycle %1: done, %2. Restart arms the trigger again.")
            .arg(m_data.triggerCycle.value_or(0))
            .arg(samples);
    case Status::Paused:
        return tr("Paused: %1.").arg(samples);
    case Status::NoVariables:
        break;
    }
    return tr("None of the chosen variables can be recorded (see Messages).");
}

void TracePane::updateStatus()
{
    m_status->setText(statusText());
    const bool online = m_online.isOnline();
    m_pause->setEnabled(online);
    m_restart->setEnabled(online);
    m_exportAction->setEnabled(!m_data.rows.empty());
}

void TracePane::configure()
{
    TraceSettingsDialog dialog(m_settings, this);
    if (dialog.exec() == QDialog::Accepted)
        setSettings(dialog.settings());
}

void TracePane::askForVariable()
{
    bool ok = false;
    const QString name = QInputDialog::getText(this, tr("Add Variable"),
                                               tr("Variable to trace (e.g. Main.Level or a global):"),
                                               QLineEdit::Normal, QString(), &ok);
    if (ok)
        addVariable(name);
}

void TracePane::removeSelectedLanes()
{
    model::SavedTrace settings = m_settings;
    for (const QListWidgetItem *item : m_lanes->selectedItems()) {
        settings.variables.removeAll(item->text());
        settings.hidden.removeAll(item->text());
    }
    if (settings != m_settings)
        setSettings(settings);
}

bool TracePane::exportTo(const QString &path, QString &error) const
{
    const QString title = tr("Trace of %1, %2").arg(m_projectModel.project().contentHeader.name.isEmpty()
                                                        ? tr("the project")
                                                        : m_projectModel.project().contentHeader.name)
                              .arg(tr("%n sample(s)", nullptr, int(m_data.rows.size())));
    return exportTrace(m_data, m_chart->image(), title, path, error);
}

void TracePane::exportInteractive(const QString &suffix)
{
    const QString filter = suffix == QLatin1String("csv") ? tr("CSV files (*.csv)")
        : suffix == QLatin1String("vcd")                  ? tr("Value change dumps (*.vcd)")
        : suffix == QLatin1String("png")                  ? tr("PNG pictures (*.png)")
                                                          : tr("PDF documents (*.pdf)");
    QString path = QFileDialog::getSaveFileName(this, tr("Export Trace"), QStringLiteral("trace.") + suffix, filter);
    if (path.isEmpty())
        return;
    if (!path.endsWith(QLatin1Char('.') + suffix, Qt::CaseInsensitive))
        path += QLatin1Char('.') + suffix;
    QString error;
    if (!exportTo(path, error))
        QMessageBox::warning(this, tr("Export Trace"), error);
}

} // namespace iec::app
