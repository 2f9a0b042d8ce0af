#pragma once

#include "app/online/tracechart.h"
#include "interpreter/runtime/snapshot.h"
#include "model/savedtrace.h"

#include <QWidget>

#include <memory>

class QAction;
class QLabel;
class QListWidget;
class QMenu;
class QTableWidget;
class QToolBar;

namespace iec::model {
class ProjectModel;
}

namespace iec::app {

class OnlineController;

// The Trace pane: records chosen variables every cycle while online (the runtime's
// TraceRecorder, configured here and kept with the project) and shows them as a trend
// (TraceChart), with the lanes listed to hide and reorder them, two cursors and their
// readouts, and export to CSV, VCD, PNG and PDF. Clicking a sample shows that scan in the
// editors (going back in time). The recording stays after logout until the next login.
class TracePane : public QWidget
{
    Q_OBJECT

public:
    TracePane(model::ProjectModel &projectModel, OnlineController &online, QWidget *parent = nullptr);
    ~TracePane() override;

    [[nodiscard]] const model::SavedTrace &settings() const { return m_settings; }
    // New settings (the configuration dialog): sent to the runtime, which starts recording again.
    void setSettings(const model::SavedTrace &settings);
    void addVariable(const QString &name);
    // The project as it is saved: with this configuration in its addData.
    void storeIn(model::Project &project) const;

    [[nodiscard]] const TraceData &data() const { return m_data; }
    [[nodiscard]] TraceChart *chart() const { return m_chart; }
    [[nodiscard]] QListWidget *laneList() const { return m_lanes; }
    [[nodiscard]] QTableWidget *readout() const { return m_readout; }
    [[nodiscard]] QLabel *statusLabel() const { return m_status; }
    [[nodiscard]] QAction *pauseAction() const { return m_pause; }
    [[nodiscard]] QString statusText() const;
    // Writes the recording (format by suffix, traceexport.h); false with `error` on failure.
    bool exportTo(const QString &path, QString &error) const;

    void retranslate();

private:
    void createActions();
    void loadFromProject();
    void sendSettings();
    void showSnapshot(const interp::RuntimeSnapshot &snapshot);
    void applyUpdate(const interp::TraceUpdate &update);
    void fillLaneList();
    void lanesEdited();
    [[nodiscard]] std::vector<int> shownVariables() const;
    void updateLanes();
    void updateReadout();
    void updateStatus();
    void configure();
    void askForVariable();
    void removeSelectedLanes();
    void exportInteractive(const QString &suffix);

    model::ProjectModel &m_projectModel;
    OnlineController &m_online;
    model::SavedTrace m_settings;
    TraceData m_data;
    interp::TraceRecorder::Status m_recorderStatus = interp::TraceRecorder::Status::NoVariables;
    QString m_conditionProblem;
    int m_capacity = interp::TraceSettings::kDefaultCapacity;
    bool m_fillingList = false;

    QToolBar *m_toolBar;
    QAction *m_configure = nullptr;
    QAction *m_add = nullptr;
    QAction *m_pause = nullptr;
    QAction *m_restart = nullptr;
    QAction *m_zoomIn = nullptr;
    QAction *m_zoomOut = nullptr;
    QAction *m_fit = nullptr;
    QAction *m_exportAction = nullptr;
    QMenu *m_exportMenu = nullptr;
    QAction *m_exportCsv = nullptr;
    QAction *m_exportVcd = nullptr;
    QAction *m_exportPng = nullptr;
    QAction *m_exportPdf = nullptr;
    QAction *m_remove = nullptr;
    QLabel *m_status;
    QListWidget *m_lanes;
    TraceChart *m_chart;
    QTableWidget *m_readout;
};

// The runtime's settings for a saved configuration.
interp::TraceSettings traceSettings(const model::SavedTrace &saved);

} // namespace iec::app
